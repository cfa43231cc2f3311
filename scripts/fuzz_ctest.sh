#!/usr/bin/env bash
# CTest FuzzHarnessesShortRun: builds the libFuzzer harnesses (fuzz/, clang,
# ASan + UBSan) into BUILD_DIR and runs each for SECONDS over a copy of its
# committed seed corpus with its dictionary.  Exits 77 (CTest's skip) where
# clang or libFuzzer is not installed (set-up installs neither: README,
# Fuzzing), 1 on a crash or a failed build, its input kept under
# BUILD_DIR/crashes/.
#   scripts/fuzz_ctest.sh BUILD_DIR [SECONDS]
set -uo pipefail
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
build_dir=${1:?usage: fuzz_ctest.sh BUILD_DIR [SECONDS]}
seconds=${2:-12}
readers=(points_csv gpfile obj vtk cap manifest)

# libFuzzer comes with clang's runtime (Debian: libclang-rt-14-dev), not
# with clang itself: link a trivial harness to know.
if ! command -v clang++ > /dev/null; then
  echo "skipped: clang++ is not installed"
  exit 77
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf '%s\n' '#include <cstddef>' '#include <cstdint>' \
  'extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }' \
  > "$probe/probe.cc"
if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cc" \
    -o "$probe/probe" > "$probe/log" 2>&1; then
  echo "skipped: clang++ cannot link a libFuzzer harness:"
  head -3 "$probe/log"
  exit 77
fi

start=$SECONDS
mkdir -p "$build_dir"
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if ! cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" -DPFDM_FUZZ=ON \
    -DPFDM_BUILD_TESTS=OFF -DPFDM_BUILD_BENCHMARKS=OFF \
    -DPFDM_BUILD_PYTHON=OFF > "$build_dir/configure.log" 2>&1; then
  cat "$build_dir/configure.log"
  exit 1
fi
if ! cmake --build "$build_dir" --target pfdm_fuzzers -j 2 \
    > "$build_dir/build.log" 2>&1; then
  tail -40 "$build_dir/build.log"
  exit 1
fi
echo "built the harnesses in $((SECONDS - start)) s"

mkdir -p "$build_dir/crashes"
status=0
for reader in "${readers[@]}"; do
  # A fresh copy: the fuzzer adds what it finds to its first folder, and
  # the committed corpus stays as it is.
  corpus="$build_dir/corpus/$reader"
  rm -rf "$corpus"
  mkdir -p "$corpus"
  cp "$source_dir/fuzz/corpus/$reader/"* "$corpus/"
  log="$build_dir/$reader.log"
  "$build_dir/fuzz/fuzz_$reader" "$corpus" \
    -dict="$source_dir/fuzz/$reader.dict" -max_total_time="$seconds" \
    -max_len=4096 -artifact_prefix="$build_dir/crashes/$reader-" \
    -print_final_stats=1 > "$log" 2>&1
  code=$?
  runs=$(grep -m1 -oE "stat::number_of_executed_units: *[0-9]+" "$log" |
    grep -oE "[0-9]+$")
  if [ "$code" -ne 0 ]; then
    echo "fuzz_$reader: CRASH (exit $code), input in $build_dir/crashes/:"
    grep -E "==[0-9]+==ERROR|SUMMARY|runtime error|Test unit written" "$log" |
      head -10
    status=1
  else
    echo "fuzz_$reader: ${runs:-?} inputs in ${seconds} s, no crash"
  fi
done
echo "total $((SECONDS - start)) s"
exit $status
