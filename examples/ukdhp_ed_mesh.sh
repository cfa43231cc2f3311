#!/usr/bin/env bash
# The UK Digital Heart mean end-diastolic LV: a static fit of its
# endocardium.  In LV_ED_mean.vtk label 1 is the endocardium (it encloses
# 151 ml; label 0, 252 ml, is the epicardium).
source "$(dirname "$0")/common.sh"
"$PFDM" mesh-points --mesh "$DATA/ukdhp-lv-ed/LV_ED_mean.vtk" --label 1 \
  --out "$OUT/ukdhp-ed/points.csv"
"$PFDM" fit --points "$OUT/ukdhp-ed/points.csv" --out "$OUT/ukdhp-ed/fit"
