#!/usr/bin/python3
"""Smoke test of scripts/paper_tables: the quick triple-point cases give a Markdown table
whose rows carry numbers, and a timeout is recorded in the table instead of stopping it.

  paper_tables_test.py SCRIPT BUILD_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys


def rows(path):
    with open(path) as f:
        lines = [l.strip() for l in f if l.startswith("| triple-point")]
    return [[c.strip() for c in l.strip("|").split("|")] for l in lines]


def number(text):
    try:
        return float(text)
    except ValueError:
        sys.exit("not a number: %r" % text)


def run(script, build, work, out, *extra):
    r = subprocess.run([sys.executable, script, "--build", build, "--quick", "--cases",
                        "triple-point", "--work", work, "--output", out] + list(extra),
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("paper_tables failed (%d): %s" % (r.returncode, r.stderr))


def main():
    script, build, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "results.md")
    run(script, build, os.path.join(work, "runs"), out)
    table = rows(out)
    if len(table) != 4:
        sys.exit("expected 4 triple-point rows, got %d" % len(table))
    with open(out) as f:
        text = f.read()
    for needle in ("Machine:", "Command: `scripts/paper_tables", "Load average"):
        if needle not in text:
            sys.exit("results.md: %r missing" % needle)
    if "Not run" in text:
        sys.exit("results.md lists cases not run")
    for r in table:
        # case, grid, cells in, cells out, min SJ, dist_init, dist_final, ratio, discrepancy
        if int(r[2]) <= 0:
            sys.exit("no input cells: %s" % r)
        for pair in (r[3], r[4], r[8], r[9]):
            base, ours = (number(x) for x in pair.split(" / "))
            if base < 0 or ours < 0:
                sys.exit("negative figure in %s" % r)
        sj_ours = number(r[4].split(" / ")[1])
        if not 0.3 <= sj_ours <= 1.0:
            sys.exit("guaranteed min SJ %g outside [0.3, 1]: %s" % (sj_ours, r))
        if number(r[8].split(" / ")[1]) >= 0.5:
            sys.exit("discrepancy implausibly large: %s" % r)
    # A timeout is a row with a note, not a failure of the script.
    out2 = os.path.join(work, "timeout.md")
    run(script, build, os.path.join(work, "runs2"), out2, "--timeout", "0.000001")
    if not all("timeout" in r[-1] for r in rows(out2)) or len(rows(out2)) != 4:
        sys.exit("timeouts not recorded: %s" % rows(out2))
    print("ok: %d rows" % len(table))


if __name__ == "__main__":
    main()
