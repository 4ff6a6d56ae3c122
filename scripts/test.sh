#!/usr/bin/env bash
# Fresh machine to a full test run: installs dependencies, builds, runs every test under ctest
# (GoogleTest, pytest for the Python module, the installed package), runs the tests of our code's
# logic and a representative set of GL tests again built with ASan + UBSan and leak checking
# (scripts/sanitize.sh; --all for every GL test), and fuzzes the file readers briefly (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# The three builds below (plain, ASan, fuzz) take a few GB of disk together.
free_kb=$(df -Pk . | awk 'NR == 2 {print $4}')
if [ "$free_kb" -lt $((2 * 1024 * 1024)) ]; then
  echo "warning: $((free_kb / 1024)) MB free in $PWD; a full test run's builds take a few GB" >&2
fi
scripts/install_deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
# Under ASan + UBSan, leaks checked (Mesa's own in scripts/lsan.supp), into build-asan/.
scripts/sanitize.sh
# Every file reader under libFuzzer for 30 s each.
scripts/fuzz.sh 30
