#!/bin/sh
# scripts/setup with stand-ins for dpkg-query, apt-get, sudo, cmake and Debian's python3:
# python3-vtk9 is asked of apt only when no VTK Python module is there (python3-paraview
# brings one and conflicts with python3-vtk9, so installing it would remove ParaView).
#
#   setup_test.sh SETUP_SCRIPT WORK_DIR
set -eu
setup=$1
work=$2
rm -rf "$work"
mkdir -p "$work/bin"

# dpkg-query -W -f=... PACKAGE: installed unless PACKAGE is listed in $ABSENT.
cat >"$work/bin/dpkg-query" <<'STUB'
#!/bin/sh
for p; do :; done
case " $ABSENT " in *" $p "*) exit 1 ;; esac
printf 'install ok installed'
STUB
# apt-get: records its arguments.
cat >"$work/bin/apt-get" <<'STUB'
#!/bin/sh
echo "apt-get $*" >>"$APT_LOG"
STUB
printf '#!/bin/sh\nexec "$@"\n' >"$work/bin/sudo"
printf '#!/bin/sh\nexit 0\n' >"$work/bin/cmake"
# The interpreter: `import vtk` succeeds when $VTK_IMPORTS is 1.
printf '#!/bin/sh\n[ "$VTK_IMPORTS" = 1 ]\n' >"$work/python3"
chmod +x "$work/bin/"* "$work/python3"

fail=0
# run NAME VTK_IMPORTS ABSENT EXPECT: EXPECT is "vtk9" (python3-vtk9 installed) or "none"
# (apt-get not run at all).
run() {
  log="$work/$1.apt"
  : >"$log"
  if ! PATH="$work/bin:$PATH" HEXADAPT_SYSTEM_PYTHON="$work/python3" VTK_IMPORTS=$2 \
      ABSENT="$3" APT_LOG="$log" "$setup" >"$work/$1.out" 2>&1; then
    echo "FAIL $1: setup exited non-zero:"; cat "$work/$1.out"; fail=1; return
  fi
  case $4 in
    vtk9) grep -q "install .*python3-vtk9" "$log" || { echo "FAIL $1: python3-vtk9 not installed"; fail=1; } ;;
    none) [ ! -s "$log" ] || { echo "FAIL $1: apt-get ran:"; cat "$log"; fail=1; } ;;
  esac
  echo "$1: apt-get log: $(cat "$log")"
}

# ParaView's VTK imports: nothing to install (python3-vtk9 would remove python3-paraview).
run paraview_vtk 1 "python3-vtk9" none
# ParaView installed but its VTK does not import: still not python3-vtk9, and a warning.
run paraview_no_vtk 0 "python3-vtk9" none
grep -q "python3-paraview is installed" "$work/paraview_no_vtk.out" ||
  { echo "FAIL paraview_no_vtk: no warning"; cat "$work/paraview_no_vtk.out"; fail=1; }
# Neither: python3-vtk9 is installed.
run no_vtk 0 "python3-vtk9 python3-paraview" vtk9
# Every package there already: apt-get is not run.
run all_there 1 "" none

[ $fail -eq 0 ] && echo "setup_test: every case passed"
exit $fail
