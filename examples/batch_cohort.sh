#!/usr/bin/env bash
# A small cohort in one command: three synthetic phantoms and the biv-me
# patient, two cases at a time, then the same command again, which skips
# what is done.  summary.csv has one row per case.
source "$(dirname "$0")/common.sh"
mkdir -p "$OUT/cohort"
for seed in 1 2 3; do
  "$PFDM" simulate --seed "$seed" --out "$OUT/cohort/phantom$seed.csv"
done
cat > "$OUT/cohort/cases.csv" <<CSV
case,points,contours
phantom1,phantom1.csv,
phantom2,phantom2.csv,
phantom3,phantom3.csv,
biv-me-patient1,$(realpath "$DATA/biv-me-patient1/guidepoints"),lv-cavity
CSV
"$PFDM" batch --manifest "$OUT/cohort/cases.csv" --out "$OUT/cohort/fits" --jobs 2
"$PFDM" batch --manifest "$OUT/cohort/cases.csv" --out "$OUT/cohort/fits" --jobs 2
cat "$OUT/cohort/fits/summary.csv"
