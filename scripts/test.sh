#!/usr/bin/env bash
# Fresh machine to a full test run: installs dependencies, builds, runs every test under ctest
# (the GL and window tests, pytest for the Python module, the installed package), runs the tests of
# our code's logic and representative sets of GL and window tests built with ASan + UBSan and leak
# checking (scripts/sanitize.sh; --all for all of them), and fuzzes the file readers briefly
# (scripts/fuzz.sh). Every test runs at least once. Each stage prints how long it took.
set -euo pipefail
cd "$(dirname "$0")/.."
# The two builds below (plain; ASan with the fuzzers) take a few GB of disk together.
free_kb=$(df -Pk . | awk 'NR == 2 {print $4}')
if [ "$free_kb" -lt $((2 * 1024 * 1024)) ]; then
  echo "warning: $((free_kb / 1024)) MB free in $PWD; a full test run's builds take a few GB" >&2
fi
started=$SECONDS
stage() {
  local name=$1
  shift
  local from=$SECONDS
  "$@"
  echo "== $name: $((SECONDS - from)) s (total $((SECONDS - started)) s)"
}
stage "dependencies" scripts/install_deps.sh
# Everything the user gets, with the tests that need GL, a display, Python or the installed package.
# The tests of the logic (core, app, ui) are built and run in the sanitizer build alone; the numeric
# ones (plans, normals and fits measured against the reference: arithmetic, which runs tens of times
# slower instrumented, on paths the logic tests take too) in this one alone.
stage "build" scripts/build.sh -DGPSURF_TEST_FOLDERS="numeric;render;window"
stage "tests" bash -c 'cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600'
# Every test of core, app and ui and representative GL and window sets under ASan + UBSan, leaks
# checked (Mesa's own in scripts/lsan.supp), into build-asan/.
stage "sanitizers" scripts/sanitize.sh
# Every file reader under libFuzzer for 20 s each, in the sanitizer build.
stage "fuzzing" scripts/fuzz.sh 20
