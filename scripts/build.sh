#!/usr/bin/env bash
# Configures and builds gpsurf into build/ (optimised, with line tables).
set -euo pipefail
cd "$(dirname "$0")/.."
# Line tables only (-g1), as in scripts/sanitize.sh: a backtrace still names functions, files and
# lines, at a fraction of the disk and compile time of full debug information. Arguments are passed
# to cmake's configure (-DGPSURF_BUILD_GL=OFF, -DGPSURF_TEST_FOLDERS=..., ...; every test folder unless
# they say otherwise); a first argument --programs builds only what the
# install installs (the programs, the core library and the Python module), not the tests; leading
# `--target NAME` arguments build only those targets.
target=()
while [ "${1:-}" = --programs ] || [ "${1:-}" = --target ]; do
  if [ "$1" = --programs ]; then
    target+=(--target programs)
    shift
  else
    target+=(--target "${2:?--target needs a name}")
    shift 2
  fi
done
source scripts/compiler_cache.sh
cmake -S . -B build -G Ninja "${launcher[@]}" -DGPSURF_TEST_FOLDERS="core;numeric;app;render;ui;window" "$@" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" >/dev/null
cmake --build build -j"$(nproc)" "${target[@]}"
