#!/usr/bin/env bash
# Issue 30's full calibration of the derived numbers' 95 % intervals on the
# LV phantom: runs LvIntervalCalibrationTest over SEEDS noise draws (default
# 120) and writes its table into docs/uncertainty_calibration.md.
#   scripts/interval_calibration.sh [build dir] [seeds] [log]
# About 3.5 s of one core per seed (two fits of 400 tags, ED and ES).
# Given a log of that test already run with PFDM_CALIBRATION_SEEDS=seeds,
# the table is taken from it instead.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
seeds=${2:-120}
out=docs/uncertainty_calibration.md
if [[ $# -ge 3 ]]; then
  log=$3
else
  log=$(mktemp)
  trap 'rm -f "$log"' EXIT
  PFDM_CALIBRATION_SEEDS=$seeds "$build/pfdm_tests" \
    --gtest_filter='LvIntervalCalibrationTest.*' >"$log" 2>&1 || true
fi
{
  echo "# Calibration of the 95 % intervals on the LV phantom"
  echo
  echo "Written by \`scripts/interval_calibration.sh\` ($(date -u +%Y-%m-%d)):"
  echo "$seeds noise seeds of the LV phantom (\`phantom/lv_phantom.h\`, the"
  echo "model did not make it), 400 mid-wall tags, noise 0.5 mm per"
  echo "coordinate, ED and ES, the paper's model with 9 knots, --uncertainty"
  echo "on.  Per number at ES: how often the interval (value - noise bias"
  echo "-+ 1.96 sd) holds the same tags' noise-free fit (what it promises:"
  echo "0.95; the 'segments' rows pool the 17 segments), the mean sd,"
  echo "the rms and mean of the error against the noise-free fit, and, where"
  echo "the phantom's truth is defined as the fit's number is, how often the"
  echo "interval holds it and the mean bias (fit minus truth).  What the"
  echo "table shows is read in docs/uncertainty.md, Calibration."
  echo
  grep -E '^\|' "$log"
  echo
  grep -E '^pooled' "$log" | sed 's/^/Pooled: /'
} >"$out"
echo "wrote $out"
