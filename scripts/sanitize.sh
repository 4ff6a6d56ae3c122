#!/usr/bin/env bash
# The test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (clang) into build-asan/ and
# run under ctest, leak checking on; Mesa's own allocations are suppressed by scripts/lsan.supp (each
# entry says why). By default every test of our code's logic without a window (core, app, ui) and
# fixed representative sets of the GL tests (the pipeline, edits, picking, the render command, the
# compute scan, the overlays, the cache) and of the window tests; `sanitize.sh --all` runs them all,
# and the numeric tests too (tests/numeric: the plain suite's alone by default).
#   scripts/sanitize.sh [--all]
set -euo pipefail
cd "$(dirname "$0")/.."
# GL tests that measure pictures or evaluated points rather than take paths of their own, each minutes
# or tens of seconds under ASan for paths the other tests take too (all run in the plain suite, and
# here with --all): the thin-Gaussian torus rendered many ways; the GPU against the CPU evaluator
# (tessellated vertices, creased and Loop patches, AOVs pixel for pixel, the CPU evaluators' images);
# the render command's framing, silhouette, up-axis and adaptive-level pictures; every patch of a
# large mesh; the cache's tests once per weld mode (welding when settled differs from welding at
# capture only in when), and its re-evaluation of edits of every kind (a drag's stays).
skipped=(-E 'RenderCli\.ThinGaussiansOfOneOrientation|GpuTest\.TessellatedVerticesMatchTheCpuEvaluator|RenderCli\.ExactEvaluatorDrawsThePatchesOwnTriangles|RenderCli\.TheCpusImagesOfAMeshFarFromTheOriginAreTheGpus|StoredVertices/.*/WeldedWhenSettled|GpuTest\.(Creased|Loop)PatchesMatchTheCpuEvaluator|GpuTest\.AovsMatchTheCpuEvaluatorPixelForPixel|GpuTest\.EveryPatchOfALargeMeshIsDrawnAtLevelOne|RenderCli\.(DefaultsToAdaptiveLevelsForTheOutputSize|TheSilhouetteFillsTheImage|AViewAlongTheUpAxisOfAMeshAwayFromTheOriginIsDrawn|UpAxisShowsAZUpMeshAsItsYUpTwin|FramingIsTheSameWhereverTheMeshLiesAndAtAnyScale)|StoredVertices/.*EditsEvaluatedAgainEqualACapture/WeldedAtCapture')
if [ "${1:-}" = "--all" ]; then
  test_folders="core;numeric;app;render;ui;window"
  gl_tests=""
  window_tests=""
  skipped=()
fi
source scripts/configure_asan.sh
cmake --build build-asan -j"$(nproc)"
# Libraries stay loaded until exit (scripts/no_dlclose.c), so leaks in them name their module.
cc -shared -fPIC -O1 -o build-asan/no_dlclose.so scripts/no_dlclose.c
# C heap blocks over 128 KiB are reused, not mapped afresh on every draw (scripts/asan_block_reuse.c:
# the GL tests are many times slower without it); first checked to keep ASan's findings.
cc -shared -fPIC -O2 -fno-omit-frame-pointer -o build-asan/asan_block_reuse.so scripts/asan_block_reuse.c
clang -fsanitize=address,undefined -shared-libsan -Wl,-rpath,"$(clang -print-runtime-dir)" -O0 -g \
  -o build-asan/asan_block_reuse_check scripts/asan_block_reuse_check.c
reuse_check() {
  LD_PRELOAD=build-asan/asan_block_reuse.so ASAN_OPTIONS=verify_asan_link_order=0 build-asan/asan_block_reuse_check "$1" 2>&1
}
if ! reuse_check reused >/dev/null; then
  echo "scripts/asan_block_reuse.c is not in effect: a freed large block did not come back" >&2
  exit 1
fi
for check in overflow:use-after-poison use-after-free:use-after-poison overflow-after-realloc:use-after-poison \
  double-free:double-free leak:LeakSanitizer; do
  if report=$(reuse_check "${check%%:*}") || [[ "$report" != *"${check#*:}"* ]]; then
    echo "scripts/asan_block_reuse.c hides ASan's finding in case ${check%%:*} (expected ${check#*:}):" >&2
    echo "$report" | head -20 >&2
    exit 1
  fi
done
# Mesa's llvmpipe links LLVM, which the GL loaders open late (dlopen; no binary links OSMesa, which
# render/gl/gl_context.cpp loads when it makes a context). LeakSanitizer's tracer then crashed at the
# editor's exit (signal 11 while it stopped the threads, 3 runs in 4); with LLVM loaded at start,
# as when OSMesa was linked, it does not (4 in 4).
llvm=$(ldd "$(ldconfig -p | awk '/libOSMesa\.so\.8 / {print $NF; exit}')" 2>/dev/null | awk '/libLLVM/ {print $3; exit}' || true)
export LD_PRELOAD="$PWD/build-asan/no_dlclose.so $PWD/build-asan/asan_block_reuse.so${llvm:+ $llvm}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:detect_odr_violation=0:verify_asan_link_order=0"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
# The installed-package check installs the plain build's package, not this one.
ctest --output-on-failure -j"$(nproc)" --timeout 900 -LE install "${skipped[@]}"
