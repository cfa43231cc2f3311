#!/bin/bash
# CTest's browser check of report.html (ReportOpensInHeadlessChromium): fits
# an LV phantom (a solid, both walls drawn) with the built pfdm, opens the
# report in headless Chromium with WebGL on SwiftShader (no GPU), and fails
# unless the page logs no error and the 3D view's canvas drew
# (report_js/viewer.js sets data-drawn="1" once three.js rendered
# triangles); saves OUT_DIR/report.png, the page's top with the 3D view.  Exits 77 (CTest:
# skipped) when Chromium is not installed (apt-get install chromium).
#   scripts/report_browser_check.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$1
out=$2
browser=$(command -v chromium || command -v chromium-browser ||
  command -v google-chrome || true)
[ -n "$browser" ] || { echo "chromium not installed: skipped"; exit 77; }
rm -rf "$out" && mkdir -p "$out"
"$build/pfdm" simulate --phantom lv --wall_tags wall --frames 9 \
  --kinematics cycle --out "$out/lv.csv" > /dev/null
"$build/pfdm" fit --points "$out/lv.csv" --out "$out/fit" > /dev/null
page="file://$(cd "$out/fit" && pwd)/report.html"
chrome() {
  # Its own profile, so that a user's running Chromium is not joined.
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu \
    --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader \
    --user-data-dir="$out/profile" --no-first-run --hide-scrollbars \
    --enable-logging=stderr --v=0 --virtual-time-budget=10000 "$@"
}
chrome --dump-dom "$page" > "$out/dom.html" 2> "$out/console.log" || {
  echo "chromium failed on $page:" >&2
  tail -n 20 "$out/console.log" >&2
  exit 1
}
if grep -E 'CONSOLE.*(Uncaught|Error|error)|Uncaught' "$out/console.log" \
  > "$out/errors.log"; then
  echo "report.html logged errors in Chromium:" >&2
  cat "$out/errors.log" >&2
  exit 1
fi
grep -q 'data-drawn="1"' "$out/dom.html" || {
  echo "report.html's 3D view did not draw (no data-drawn=\"1\" on its" \
    "canvas; console: $out/console.log)" >&2
  exit 1
}
bytes=$(stat -c %s "$out/fit/report.html")
# The page's top, the 3D view in it (a #pfdm-view3d fragment left the
# headless screenshot blank).
chrome --screenshot="$out/report.png" --window-size=900,1400 "$page" \
  2> "$out/screenshot.log" > /dev/null || true
echo "report.html ($bytes bytes) loads without errors and its 3D view drew;" \
  "screenshot: $out/report.png"
