#!/usr/bin/env bash
# Fresh machine to a full test run: installs dependencies, builds, runs every test under ctest, runs
# the whole suite again built with ASan + UBSan and leak checking (scripts/sanitize.sh), and fuzzes
# the file readers briefly (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
# The suite under ASan + UBSan, leaks checked (Mesa's own in scripts/lsan.supp), into build-asan/.
scripts/sanitize.sh
# Every file reader under libFuzzer for 30 s each.
scripts/fuzz.sh 30
