#!/usr/bin/env bash
# biv-me patient 1: SAX and LAX LV endocardial contours of 25 frames with
# the aortic valve points (lv-cavity, the default --contours).  The cavity
# is closed at each frame's mitral valve plane (the guide points'
# MITRAL_VALVE rows); compare its volumes with biv-me's own meshes, which
# biv_me_meshes.sh prints.
source "$(dirname "$0")/common.sh"
"$PFDM" fit --points "$DATA/biv-me-patient1/guidepoints" \
  --contours lv-cavity --out "$OUT/biv-me-guidepoints"
echo "open $OUT/biv-me-guidepoints/report.html; ParaView: fit.pvd"
