#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, ASan + UBSan) into
# build-fuzz/ and runs each reader's for SECONDS (default 30) from its seed
# corpus and dictionary.  New inputs go to build-fuzz/corpus/, crashes to
# build-fuzz/crashes/.  Exits non-zero on the first crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DPFDM_FUZZ=ON -DPFDM_BUILD_TESTS=OFF \
  -DPFDM_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build build-fuzz --target pfdm_fuzzers -j 2
mkdir -p build-fuzz/crashes
for reader in points_csv gpfile obj vtk cap manifest; do
  corpus=build-fuzz/corpus/$reader
  mkdir -p "$corpus"
  echo "fuzzing $reader for ${seconds}s"
  build-fuzz/fuzz/fuzz_$reader "$corpus" fuzz/corpus/$reader \
    -dict=fuzz/$reader.dict -max_total_time="$seconds" -max_len=4096 \
    -artifact_prefix=build-fuzz/crashes/$reader- -print_final_stats=1 \
    2>&1 | grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" || true
  test "${PIPESTATUS[0]}" -eq 0
done
