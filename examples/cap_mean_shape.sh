#!/usr/bin/env bash
# The Cardiac Atlas Project's mean LV of 2,291 subjects: ED and ES
# endocardium (841 corresponding points each) as two tracked frames.
# Longitudinal shortening and radial contraction from the fit against those
# measured on the meshes (printed by mesh-points).
source "$(dirname "$0")/common.sh"
"$PFDM" mesh-points --mesh "$DATA/cap-lv-mean/mean_shape.csv" \
  --cap_surfaces ED-endo,ES-endo --out "$OUT/cap-mean/points.csv"
"$PFDM" fit --points "$OUT/cap-mean/points.csv" --out "$OUT/cap-mean/fit"
