#!/usr/bin/env bash
# Builds pfdm and its tests with AddressSanitizer and UndefinedBehaviorSanitizer
# into build-asan/ and runs the whole suite there (README: Sanitizers).
# Extra arguments go to ctest, e.g. scripts/sanitize.sh -R PointReader.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPFDM_SANITIZE=ON \
  -DPFDM_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build build-asan -j "${JOBS:-2}"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir build-asan --output-on-failure -j "${JOBS:-2}" "$@"
