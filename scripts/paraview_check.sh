#!/bin/bash
# CTest's ParaView check: fits a small phantom with the built pfdm and opens
# the fit.pvd in ParaView (scripts/paraview_check.py).  Exits 77 (CTest:
# skipped) when pvpython is not installed: ParaView is an optional viewer,
# not a dependency (apt-get install paraview python3-paraview xvfb).  With
# xvfb-run it also saves screenshots of the first and last frame.
#   scripts/paraview_check.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$1
out=$2
command -v pvpython > /dev/null || { echo "pvpython not installed: skipped"; exit 77; }
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
"$build/pfdm" simulate --frames 5 --tags 1000 --out "$out/phantom.csv" > /dev/null
"$build/pfdm" fit --points "$out/phantom.csv" --out "$out/fit" > /dev/null
if command -v xvfb-run > /dev/null; then
  xvfb-run -a -s "-screen 0 1024x1024x24" pvpython "$here/paraview_check.py" \
    "$out/fit/fit.pvd" 5 --screenshots "$out/paraview"
  echo "screenshots: $out/paraview_first.png $out/paraview_last.png"
else
  pvpython "$here/paraview_check.py" "$out/fit/fit.pvd" 5
fi
