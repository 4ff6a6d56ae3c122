#!/usr/bin/env bash
# The editor soak run long: random event scripts (tests/support/random_events.h) replayed in
# gpsurf-editor on five samples (tests/window/test_editor_soak.cpp), EVENTS events per sample per round,
# one round per seed from FIRST_SEED, under xvfb-run. Stops at the first crash, hang or unloadable
# save; the failing events file is left as build/tests/soak-failed-SAMPLE.json (replay it with
# gpsurf-editor MESH --play FILE). Builds into BUILD (default build/; build-asan/ after
# scripts/sanitize.sh soaks with the sanitizers).
#   scripts/soak.sh [EVENTS] [ROUNDS] [FIRST_SEED]     defaults: 2000 events, 5 rounds, seed 1
set -euo pipefail
cd "$(dirname "$0")/.."
events="${1:-2000}"
rounds="${2:-5}"
first_seed="${3:-1}"
build="${BUILD:-build}"
if [ ! -f "$build/build.ninja" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target test_editor_soak gpsurf-editor gpsurf
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
total=0
start=$(date +%s)
for ((round = 0; round < rounds; ++round)); do
  seed=$((first_seed + round))
  echo "soak round $((round + 1))/$rounds: seed $seed, $events events per sample"
  (cd "$build/tests" && GPS_SOAK_EVENTS="$events" GPS_SOAK_SEED="$seed" GPS_SOAK_TIMEOUT=$((600 + 2 * events)) \
    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ./test_editor_soak --gtest_brief=1)
  total=$((total + 5 * events))
done
echo "soak: $total random events on 5 samples in $(( $(date +%s) - start )) s, no crash, no hang, every save loads"
