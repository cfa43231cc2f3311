#!/usr/bin/env bash
# biv-me patient 1's own fitted LV endocardial meshes: the 1,572 vertices
# keep their numbering over the 25 frames, so they serve as tracked material
# points, which lets the fit see twist.  mesh-points prints the volumes,
# length and radial contraction measured on the meshes themselves.
source "$(dirname "$0")/common.sh"
"$PFDM" mesh-points --mesh "$DATA/biv-me-patient1/obj" \
  --mesh_filter LV_ENDOCARDIAL --out "$OUT/biv-me-meshes/points.csv"
"$PFDM" fit --points "$OUT/biv-me-meshes/points.csv" \
  --out "$OUT/biv-me-meshes/fit"
