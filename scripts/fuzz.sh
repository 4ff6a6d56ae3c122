#!/usr/bin/env bash
# Builds the libFuzzer targets of the file readers (clang, ASan + UBSan) into build-fuzz/ and runs
# each for SECONDS seconds (default 30) from the seeds in fuzz/corpus/READER. New inputs the fuzzer
# finds go to build-fuzz/corpus/READER (not into the repository); a crash leaves its input in
# build-fuzz/ and ends the script with a non-zero status.
#   scripts/fuzz.sh [SECONDS] [READER...]     READER: ply obj off stl gltf (default: all)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
shift || true
readers=("${@:-ply obj off stl gltf}")
read -r -a readers <<< "${readers[*]}"
source scripts/compiler_cache.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGPSURF_BUILD_FUZZ=ON \
  -DGPSURF_BUILD_TESTS=OFF -DGPSURF_BUILD_BENCH=OFF -DGPSURF_BUILD_GL=OFF -DGPSURF_BUILD_PYTHON=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${readers[@]/#/fuzz_}"
for r in "${readers[@]}"; do
  mkdir -p "build-fuzz/corpus/$r"
  echo "fuzzing the $r reader for ${seconds} s"
  # -rss_limit_mb: a reader must stay far below this on inputs of at most -max_len bytes.
  log="build-fuzz/fuzz-$r.log"
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "build-fuzz/fuzz/fuzz_$r" "build-fuzz/corpus/$r" "fuzz/corpus/$r" -max_total_time="$seconds" \
    -max_len=65536 -rss_limit_mb=2048 -timeout=10 -artifact_prefix="build-fuzz/crash-$r-" -print_final_stats=1 >"$log" 2>&1; then
    tail -n 40 "$log"
    echo "the $r fuzzer found a failure (input in build-fuzz/crash-$r-*)"
    exit 1
  fi
  grep -E "^stat::(number_of_executed_units|peak_rss_mb)" "$log" | tr '\n' ' '
  echo
done
