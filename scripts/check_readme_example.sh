#!/usr/bin/env bash
# Runs the README's example command (the second line of its first sh block)
# as written, with ./build the given build folder, in a scratch folder; fails
# unless it exits 0 and writes fit.json.  CTest: ReadmeExampleRuns.
set -euo pipefail
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="$1"
scratch="$2"
example="$(awk '/^```sh$/ {blocks++; next}
  blocks == 1 && ++lines == 2 {print; exit}' "$source_dir/README.md")"
example="${example%%#*}"
case "$example" in
  ./build/pfdm\ simulate*) ;;
  *) echo "README's example line is not a pfdm command: $example" >&2; exit 1 ;;
esac
rm -rf "$scratch" && mkdir -p "$scratch" && ln -s "$build_dir" "$scratch/build"
cd "$scratch"
echo "+ $example"
eval "$example"
test -s out/fit/fit.json
echo "README example: out/fit/fit.json written"
