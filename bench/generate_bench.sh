#!/usr/bin/env bash
# Times hexadapt-generate on the reference sizes of the generate issue, with 1 and 2 threads:
# the 420x180 triple point (the paper's grid) at 8x8 samples per cell and a 128^3 sphere at
# 4^3 and 8^3 samples per cell. Prints wall-clock and CPU (user) seconds, and the tool's own
# phase times (grid, jitter, sample, package, write) from its JSON report. On a shared
# machine the CPU time is the steadier figure.
#   bench/generate_bench.sh [build/tools]
set -euo pipefail
tools=${1:-build/tools}
gen=$tools/hexadapt-generate
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

run() {  # label, threads, generate args...
  local label=$1 threads=$2
  shift 2
  local TIMEFORMAT='%R %U'
  { time "$gen" "$@" --threads "$threads" -q -o "$out/case.vtu" --json "$out/report.json" ; } \
    2> "$out/time"
  /usr/bin/python3 - "$label" "$threads" "$out/time" "$out/report.json" <<'PY'
import json, sys
label, threads, timing, report = sys.argv[1:]
wall, user = open(timing).read().split()[-2:]
r = json.load(open(report))
phases = " ".join(f"{k}={v:.2f}" for k, v in r["times"].items())
print(f"{label:26s} threads={threads} wall={float(wall):6.2f}s cpu={float(user):6.2f}s "
      f"cells={r['cells']} mixed={r['mixed_cells']} rk4_steps={r['rk4_steps']}  {phases}")
PY
}

for threads in 1 2; do
  run "triple-point 420x180 s=8" "$threads" triple-point --dims 420,180 --samples 8
  run "sphere 128^3 s=4" "$threads" sphere --dims 128,128,128 --samples 4
  run "sphere 128^3 s=8" "$threads" sphere --dims 128,128,128 --samples 8
done
