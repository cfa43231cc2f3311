#!/usr/bin/env bash
# Fits the same inputs with two pfdm binaries and fails unless every output
# file is byte-identical, fit.json's timings (solve_seconds, start_seconds,
# checks_seconds) aside.  For a change that must not change behaviour (a
# refactoring):
#
#   scripts/compare_fit_outputs.sh OLD_PFDM NEW_PFDM [WORK_DIR]
#
# The cases: the README example (2,000 tracked tags), the independent LV
# phantom with mid-wall tags and with tags through the wall (the solid),
# 10,000 tags (frame 0's coarse round), and, when ../shared/data is there,
# biv-me patient 1's contours as the cavity and as both walls.  The inputs
# are made once, by OLD_PFDM.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 OLD_PFDM NEW_PFDM [WORK_DIR]" >&2
  exit 2
fi
old=$(realpath "$1")
new=$(realpath "$2")
cd "$(dirname "$0")/.."
work=${3:-$(mktemp -d /tmp/pfdm_compare.XXXXXX)}
data=../shared/data
mkdir -p "$work/inputs"

"$old" simulate --out "$work/inputs/phantom.csv" >/dev/null
"$old" simulate --tags 10000 --out "$work/inputs/tags10k.csv" >/dev/null
"$old" simulate --phantom lv --out "$work/inputs/lv.csv" >/dev/null
"$old" simulate --phantom lv --wall_tags wall --out "$work/inputs/lv_wall.csv" >/dev/null

cases=(
  "readme|--points $work/inputs/phantom.csv"
  "tags10k|--points $work/inputs/tags10k.csv"
  "lv_phantom|--points $work/inputs/lv.csv"
  "lv_phantom_wall|--points $work/inputs/lv_wall.csv"
)
if [ -d "$data/biv-me-patient1" ]; then
  cases+=("biv_me_cavity|--points $data/biv-me-patient1/guidepoints --contours lv-cavity"
          "biv_me_walls|--points $data/biv-me-patient1/guidepoints --contours lv-cavity,lv-epi")
else
  echo "note: $data absent, biv-me cases skipped"
fi

status=0
for entry in "${cases[@]}"; do
  name=${entry%%|*}
  read -r -a flags <<<"${entry#*|}"
  for which in old new; do
    binary=$old
    [ "$which" = new ] && binary=$new
    rm -rf "$work/$which/$name"
    "$binary" fit "${flags[@]}" --out "$work/$which/$name" >"$work/$which.$name.log" 2>&1
  done
  differing=()
  while IFS= read -r file; do
    a="$work/old/$name/$file"
    b="$work/new/$name/$file"
    if [ "$file" = fit.json ]; then
      timing='s/"(solve|start|checks)_seconds": *[-0-9.eE+]+/"\1_seconds": 0/'
      cmp -s <(sed -E "$timing" "$a") <(sed -E "$timing" "$b") || differing+=("$file")
    else
      cmp -s "$a" "$b" || differing+=("$file")
    fi
  done < <(cd "$work/old/$name" && find . -type f | sed 's|^\./||' | sort)
  count=$(cd "$work/old/$name" && find . -type f | wc -l)
  if [ "$count" != "$(cd "$work/new/$name" && find . -type f | wc -l)" ]; then
    differing+=("(the file sets differ)")
  fi
  if [ ${#differing[@]} -eq 0 ]; then
    echo "$name: $count files identical"
  else
    echo "$name: DIFFERENT: ${differing[*]}"
    status=1
  fi
done
echo "outputs in $work"
exit $status
