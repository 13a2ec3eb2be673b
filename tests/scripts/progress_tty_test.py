"""The progress bars of the tools: drawn on a terminal, absent on a pipe and with -q.

Runs generate -> assign -> adapt on a small case, then hexadapt-measure --reference and
hexadapt-render, each under a pseudo-terminal (stderr is a tty) and on a pipe, and checks
the phases their bars name and that every bar ends at 100%.

  progress_tty_test.py TOOLS_DIR WORK_DIR
"""
import os
import pty
import re
import shutil
import subprocess
import sys


def run_on_tty(cmd):
    """Runs cmd with stderr on a pseudo-terminal; returns (exit code, what it drew)."""
    master, slave = pty.openpty()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:  # EIO once the child has closed the terminal
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    return proc.wait(), b"".join(chunks).decode(errors="replace")


def bars(text):
    """Phase name -> last percentage drawn for it."""
    last = {}
    for m in re.finditer(r"([A-Za-z_\-]+)\s*\[[# ]*\]\s*(\d+)%", text):
        last[m.group(1)] = int(m.group(2))
    return last


def check(name, cmd, phases):
    code, text = run_on_tty(cmd)
    assert code == 0, f"{name}: exit {code}: {text[-500:]}"
    drawn = bars(text)
    for p in phases:
        assert p in drawn, f"{name}: no bar for phase {p!r} in {text!r}"
        assert drawn[p] == 100, f"{name}: the bar of {p!r} ends at {drawn[p]}%"
    code, text = run_on_tty(cmd + ["-q"])
    assert code == 0 and "%" not in text, f"{name} -q drew: {text!r}"
    piped = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    assert piped.returncode == 0 and "%" not in piped.stderr, f"{name} on a pipe: {piped.stderr!r}"


def main():
    tools, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    t = lambda s: os.path.join(tools, "hexadapt-" + s)
    w = lambda f: os.path.join(work, f)
    subprocess.run([t("generate"), "triple-point", "--dims", "42,18", "-o", w("vf.vtu"), "-q"],
                   check=True)
    subprocess.run([t("assign"), w("vf.vtu"), "-o", w("assign.vtu"), "-q"], check=True)
    subprocess.run([t("adapt"), w("assign.vtu"), "-o", w("mesh.vtu"), "-q"], check=True)
    # The bars, not the verdict: --min-edge 0 keeps a sliver of adapt from failing the run.
    check("hexadapt-measure",
          [t("measure"), w("mesh.vtu"), "--reference", w("vf.vtu"), "--min-edge", "0"],
          ["read", "quality", "read_reference", "imprint", "size"])
    check("hexadapt-render", [t("render"), w("mesh.vtu"), "-o", w("mesh.png")],
          ["read", "slice", "draw"])
    print("ok")


if __name__ == "__main__":
    main()
