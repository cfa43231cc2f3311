#!/usr/bin/env bash
# The UK Digital Heart mean end-diastolic LV: a static fit of its
# endocardium.  In LV_ED_mean.vtk label 1 is the endocardium (it encloses
# 151 ml; label 0, 252 ml, is the epicardium); a label says no wall by its
# name, so --surface endo says it: the volume is the cavity's.
source "$(dirname "$0")/common.sh"
"$PFDM" mesh-points --mesh "$DATA/ukdhp-lv-ed/LV_ED_mean.vtk" --label 1 \
  --out "$OUT/ukdhp-ed/points.csv"
"$PFDM" fit --points "$OUT/ukdhp-ed/points.csv" --surface endo \
  --out "$OUT/ukdhp-ed/fit"
