#!/bin/sh
# Runs examples/Makefile on a small triple-point case in a fresh folder, checks that every
# stage's file and picture is there, then that a second run rebuilds nothing, that touching
# the assigned grid or changing a stage's options re-runs only the stages after it, that the
# adapt and measure commands are shown, and that an adapt that wrote nothing stops make.
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
# A stage's options changed: that stage and the ones after it run again, shown with their
# commands (adapt's and measure's too), and the stages before it do not.
run() { make -C "$examples" CASE=triple-point DIMS=42,18 BUILD="$build" OUT="$out" "$@" all pictures \
          > "$out/run.txt" 2>&1 || { cat "$out/run.txt"; exit 1; }; }
ran() { grep -q "hexadapt-$1 " "$out/run.txt"; }
A=ASSIGN_OPTS=--zero-below=1e-4 R=RECONSTRUCT_OPTS=--method=greedy
run  # back to the first run's parameters (the dry run above rewrote DIMS)
run "$A"
ran assign || { echo "new ASSIGN_OPTS did not re-run assign"; exit 1; }
grep -q "hexadapt-adapt .*triple-point.assign.vtu" "$out/run.txt" || { echo "adapt command hidden"; cat "$out/run.txt"; exit 1; }
grep -q "hexadapt-measure .*triple-point.mesh.vtu" "$out/run.txt" || { echo "measure command hidden"; cat "$out/run.txt"; exit 1; }
run "$A" "$R"
ran reconstruct || { echo "new RECONSTRUCT_OPTS did not re-run reconstruct"; exit 1; }
if ran assign; then echo "assign re-run needlessly"; exit 1; fi
run "$A" "$R" RENDER_OPTS=--size=400x200
ran render || { echo "new RENDER_OPTS did not re-run render"; exit 1; }
if ran adapt; then echo "adapt re-run for a picture option"; exit 1; fi
# A grid whose own cells fail the threshold: adapt writes nothing (exit 3), and make stops
# there instead of measuring a missing file.
bad="$out/bad"
if make -s -C "$examples" CASE=triple-point DIMS=42,18 BUILD="$build" OUT="$bad" \
     GENERATE_OPTS="--jitter 0.45 --jitter-floor 0.05" all > "$out/log3.txt" 2>&1; then
  echo "make succeeded without an adapted mesh"; cat "$out/log3.txt"; exit 1
fi
grep -q "nothing written" "$out/log3.txt" || { echo "adapt did not refuse the grid"; cat "$out/log3.txt"; exit 1; }
if grep -q hexadapt-measure "$out/log3.txt"; then echo "measure ran on a missing mesh"; cat "$out/log3.txt"; exit 1; fi
echo ok
