#!/usr/bin/env bash
# Fails when library code includes a part above its own (docs/architecture.md):
# the parts, lowest first, are util model phantom solvers fit report io batch
# cli. Tests (*_test.cc) and src/pfdm/testing may include anything.
set -euo pipefail
cd "$(dirname "$0")/.."
parts=(util model phantom solvers fit report io batch cli)
declare -A rank
for i in "${!parts[@]}"; do rank[${parts[$i]}]=$i; done
status=0
for file in src/pfdm/*/*.h src/pfdm/*/*.cc; do
  part=$(basename "$(dirname "$file")")
  case "$file" in *_test.cc) continue ;; esac
  [ "$part" = testing ] && continue
  if [ -z "${rank[$part]+x}" ]; then
    echo "$file: folder '$part' is not a known part"; status=1; continue
  fi
  while IFS= read -r included; do
    if [ -z "${rank[$included]+x}" ] || [ "${rank[$included]}" -gt "${rank[$part]}" ]; then
      echo "$file: $part includes pfdm/$included/ (a higher part)"; status=1
    fi
  done < <(grep -o '^#include "pfdm/[a-z_]*/' "$file" | sed 's|#include "pfdm/||; s|/$||' | sort -u)
done
[ $status -eq 0 ] && echo "layers: every include points down"
exit $status
