#!/usr/bin/env bash
# Fresh machine to a full test run: installs dependencies, builds, runs every test under ctest, fuzzes
# the file readers briefly (scripts/fuzz.sh) and runs the suite under ASan + UBSan (scripts/sanitize.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
# Every file reader under libFuzzer for 30 s each, then the whole suite again under ASan + UBSan.
scripts/fuzz.sh 30
scripts/sanitize.sh
