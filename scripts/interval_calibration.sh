#!/usr/bin/env bash
# Issue 30's full calibration of the derived numbers' 95 % intervals on the
# LV phantom: runs LvIntervalCalibrationTest (mid-wall tags, tags through
# the wall, both walls' contours, the endocardium's, the epicardium's or
# the mid-wall's contours alone, and the phantom with a hypokinetic
# segment: mid-wall tags, tags through the wall, with and without
# --local_transmural, and both walls' contours) over SEEDS noise draws
# (default 100), and LvIntervalShrinkTest (four kinds' sds at 400 and
# 1,600 points, 2 seeds), and writes their tables into
# docs/uncertainty_calibration.md.
#   scripts/interval_calibration.sh [build dir] [seeds] [log]
# Per seed about 3.5 s of one core for the mid-wall tags, 5-8 s for the
# wall's, 6-7 s for both walls' contours (with the lesion alike), 1.3-1.5 s
# for each of the others (two fits each, noisy and noise-free), and one
# dense noise-free fit per kind.
# Given a log of that test already run with PFDM_CALIBRATION_SEEDS=seeds,
# the table is taken from it instead.  What follows the line $KEEP in the
# old file (the run's circumstances and the reading, written by hand) is
# kept after the new tables.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
seeds=${2:-100}
out=docs/uncertainty_calibration.md
KEEP='<!-- written by hand, kept by scripts/interval_calibration.sh -->'
kept=$(mktemp)
trap 'rm -f "$kept"' EXIT
if [[ -f $out ]]; then
  sed -n "\|^$KEEP\$|,\$p" "$out" >"$kept"
fi
if [[ $# -ge 3 ]]; then
  log=$3
else
  log=$(mktemp)
  trap 'rm -f "$log" "$kept"' EXIT
  PFDM_CALIBRATION_SEEDS=$seeds "$build/pfdm_tests" \
    --gtest_filter='LvIntervalCalibrationTest.*:LvIntervalShrinkTest.*' >"$log" 2>&1 || true
fi
{
  echo "# Calibration of the 95 % intervals on the LV phantom"
  echo
  echo "Written by \`scripts/interval_calibration.sh\` ($(date -u +%Y-%m-%d)):"
  echo "$seeds noise seeds of the LV phantom (\`phantom/lv_phantom.h\`, the"
  echo "model did not make it), noise 0.5 mm per coordinate, ED and ES, the"
  echo "paper's model with 9 knots, --uncertainty on; six kinds of data:"
  echo "400 mid-wall tags, 400 tags through the wall (a solid), both walls'"
  echo "contours on 9 short-axis slices and 3 long-axis planes (a solid),"
  echo "and on the same planes the endocardium's contours alone (one"
  echo "surface, as biv-me's lv-cavity), the epicardium's alone and the"
  echo "mid-wall's alone; and the tags (mid-wall, through the wall, and"
  echo "through it with --local_transmural on) and both walls' contours of"
  echo "the phantom whose segment 8 contracts at 40 % of normal, its"
  echo "segments hung on the phantom's RV insertion.  Per number at ES (the"
  echo "mass at ED):"
  echo "whether pfdm claims its"
  echo "interval calibrated on that kind of data (fit.json's"
  echo "uncertainty_calibrated, report/interval_calibration.h), how often the"
  echo "interval (value - noise bias -+ 1.96 sd) holds the same data's"
  echo "noise-free fit (what it promises: 0.95; the 'segments' rows pool the"
  echo "17 segments), the mean sd, the rms and mean of the error against the"
  echo "noise-free fit, the mean error of the number itself (not less its"
  echo "bias), how often the interval holds the noise-free fit of ten times"
  echo "the points (4,000, seed 0: the model's answer with little of the"
  echo "sampling's own error) and the mean error against it, and, where the"
  echo "phantom's truth is defined as the fit's number is, how often the"
  echo "interval holds it and the mean bias (fit minus truth).  What the"
  echo "tables show is read in docs/uncertainty.md, Calibration.  The last"
  echo "four tables (LvIntervalShrinkTest, 2 seeds whatever the seeds above)"
  echo "give each number's mean sd at 400 and at 1,600 points and their"
  echo "ratio, 0.5 where the sd shrinks like 1/sqrt(N)."
  echo
  grep -E '^(\||## |$|pooled|Lesion)' "$log" | sed 's/^pooled/Pooled/' | cat -s
  cat "$kept"
} >"$out.new"
mv "$out.new" "$out"
rm -f "$kept"
echo "wrote $out"
