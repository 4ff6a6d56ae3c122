#!/usr/bin/env bash
# Fresh machine to a full test run: installs dependencies, builds, runs every test under ctest and fuzzes
# the file readers briefly (scripts/fuzz.sh). The ASan + UBSan run of the suite (scripts/sanitize.sh) is
# not part of it yet: it has not been run end to end on the merged tree.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 600)
# Every file reader under libFuzzer for 30 s each.
scripts/fuzz.sh 30
