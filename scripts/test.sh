#!/usr/bin/env bash
# Fresh machine to a full test run: installs dependencies, builds, runs every test under ctest, runs
# the whole suite again built with ASan + UBSan and leak checking (scripts/sanitize.sh), and fuzzes
# the file readers briefly (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# The three builds below (plain, ASan, fuzz) take about 1.6 GB of disk together (0.2, 1.3, 0.1).
free_kb=$(df -Pk . | awk 'NR == 2 {print $4}')
if [ "$free_kb" -lt $((2 * 1024 * 1024)) ]; then
  echo "warning: $((free_kb / 1024)) MB free in $PWD; a full test run's builds take about 1.6 GB" >&2
fi
scripts/install_deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
# The suite under ASan + UBSan, leaks checked (Mesa's own in scripts/lsan.supp), into build-asan/.
scripts/sanitize.sh
# Every file reader under libFuzzer for 30 s each.
scripts/fuzz.sh 30
