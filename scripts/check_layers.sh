#!/usr/bin/env bash
# Fails when library code includes a part above its own (docs/architecture.md):
# the parts, lowest first, are util segmentation model phantom solvers fit
# report io batch cli.  Inside fit/ the sub-parts are ordered the same way: residuals,
# correspondence, fit/ itself (fit_options.h), problem, stages.  Tests
# (*_test.cc) and src/pfdm/testing may include anything.
set -euo pipefail
cd "$(dirname "$0")/.."
parts=(util segmentation model phantom solvers fit report io batch cli)
fit_parts=(residuals correspondence . problem stages)
declare -A rank fit_rank
for i in "${!parts[@]}"; do rank[${parts[$i]}]=$i; done
for i in "${!fit_parts[@]}"; do fit_rank[${fit_parts[$i]}]=$i; done

# The sub-part of fit/ a path below src/pfdm/fit/ (or pfdm/fit/) lies in: its
# folder, or "." for a file of fit/ itself.
fit_part() {
  local rest=${1#*fit/}
  case "$rest" in */*) echo "${rest%%/*}" ;; *) echo . ;; esac
}

status=0
while IFS= read -r file; do
  relative=${file#src/pfdm/}
  part=${relative%%/*}
  case "$file" in *_test.cc) continue ;; esac
  [ "$part" = testing ] && continue
  if [ -z "${rank[$part]+x}" ]; then
    echo "$file: folder '$part' is not a known part"; status=1; continue
  fi
  own_fit_part=""
  if [ "$part" = fit ]; then
    own_fit_part=$(fit_part "$file")
    if [ -z "${fit_rank[$own_fit_part]+x}" ]; then
      echo "$file: folder 'fit/$own_fit_part' is not a known sub-part"; status=1
      continue
    fi
  fi
  while IFS= read -r included; do
    included_part=${included%%/*}
    if [ -z "${rank[$included_part]+x}" ] ||
       [ "${rank[$included_part]}" -gt "${rank[$part]}" ]; then
      echo "$file: $part includes pfdm/$included (a higher part)"; status=1
    elif [ -n "$own_fit_part" ] && [ "$included_part" = fit ]; then
      sub=$(fit_part "$included")
      if [ -z "${fit_rank[$sub]+x}" ] ||
         [ "${fit_rank[$sub]}" -gt "${fit_rank[$own_fit_part]}" ]; then
        echo "$file: fit/$own_fit_part includes pfdm/$included (a higher sub-part)"
        status=1
      fi
    fi
  done < <(grep -o '^#include "pfdm/[a-z_/]*\.h' "$file" | sed 's|#include "pfdm/||' | sort -u)
done < <(find src/pfdm -name '*.h' -o -name '*.cc' | sort)
[ $status -eq 0 ] && echo "layers: every include points down"
exit $status
