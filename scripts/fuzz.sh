#!/usr/bin/env bash
# Builds the libFuzzer targets of the file readers (clang, ASan + UBSan) in the sanitizer build,
# build-asan/ (scripts/configure_asan.sh; configured here unless scripts/sanitize.sh did), and runs
# each for SECONDS seconds (default 30) from the seeds in fuzz/corpus/READER, two at a time. New inputs
# the fuzzer finds go to build-asan/corpus/READER (not into the repository); a crash leaves its input
# in build-asan/ and ends the script with a non-zero status.
#   scripts/fuzz.sh [SECONDS] [READER...]     READER: ply obj off stl gltf (default: all)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
shift || true
readers=("${@:-ply obj off stl gltf}")
read -r -a readers <<< "${readers[*]}"
if ! grep -qs "^GPSURF_BUILD_FUZZ:BOOL=ON" build-asan/CMakeCache.txt; then
  source scripts/configure_asan.sh
fi
cmake --build build-asan -j"$(nproc)" --target "${readers[@]/#/fuzz_}"
# One reader: runs it, then prints its figures or, on a failure, the end of its log.
fuzz_one() {
  local r=$1 log="build-asan/fuzz-$1.log"
  mkdir -p "build-asan/corpus/$r"
  # -rss_limit_mb: a reader must stay far below this on inputs of at most -max_len bytes. The ASan
  # runtime is a shared library in this build, which libFuzzer's own objects come before.
  if ! ASAN_OPTIONS=detect_leaks=1:verify_asan_link_order=0 UBSAN_OPTIONS=print_stacktrace=1 \
    "build-asan/fuzz/fuzz_$r" "build-asan/corpus/$r" "fuzz/corpus/$r" -max_total_time="$seconds" \
    -max_len=65536 -rss_limit_mb=2048 -timeout=10 -artifact_prefix="build-asan/crash-$r-" -print_final_stats=1 >"$log" 2>&1; then
    tail -n 40 "$log"
    echo "the $r fuzzer found a failure (input in build-asan/crash-$r-*)"
    return 1
  fi
  echo "fuzzed the $r reader for ${seconds} s: $(grep -E "^stat::(number_of_executed_units|peak_rss_mb)" "$log" | tr '\n' ' ')"
}
# As many readers at once as there are cores, each fuzzer being one process.
status=0
pids=()
for r in "${readers[@]}"; do
  fuzz_one "$r" &
  pids+=($!)
  if [ "${#pids[@]}" -ge "$(nproc)" ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit "$status"
