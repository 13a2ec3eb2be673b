#!/bin/sh
# Runs examples/Makefile on a small triple-point case in a fresh folder, checks that every
# stage's file and picture is there, then that a second run rebuilds nothing and that
# touching the assigned grid re-runs only the stages after it.
set -eu
examples=$1 build=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
make -s -C "$examples" CASE=triple-point DIMS=42,18 BUILD="$build" OUT="$out" all pictures > "$out/log1.txt" 2>&1 \
  || { cat "$out/log1.txt"; exit 1; }
for f in vf.vtu assign.vtu pixels.vtu model.vtk mesh.vtu adapt.json measure.json \
         vf.png assign.png pixels.png mesh.png quality.png zoom.png; do
  [ -s "$out/triple-point.$f" ] || { echo "missing triple-point.$f"; ls "$out"; exit 1; }
done
grep -q '"passed": true' "$out/triple-point.measure.json" || { echo "measure did not pass"; exit 1; }
# Nothing changed: make has nothing to do.
if ! make -q -C "$examples" CASE=triple-point DIMS=42,18 BUILD="$build" OUT="$out" all pictures; then
  echo "second run would rebuild"; exit 1
fi
# The assigned grid changed: generate does not run again, reconstruct does.
sleep 1; touch "$out/triple-point.assign.vtu"
make -n -C "$examples" CASE=triple-point DIMS=42,18 BUILD="$build" OUT="$out" all pictures > "$out/plan.txt"
grep -q hexadapt-reconstruct "$out/plan.txt" || { echo "reconstruct not re-run"; exit 1; }
if grep -q hexadapt-generate "$out/plan.txt"; then echo "generate re-run needlessly"; exit 1; fi
# Other parameters: generate runs again.
make -n -C "$examples" CASE=triple-point DIMS=40,18 BUILD="$build" OUT="$out" all > "$out/plan2.txt"
grep -q hexadapt-generate "$out/plan2.txt" || { echo "new DIMS did not re-run generate"; exit 1; }
echo ok
