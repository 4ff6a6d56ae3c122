# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: configures build-asan/, the one clang build with
# AddressSanitizer + UndefinedBehaviorSanitizer that holds both the sanitizer suite and the file
# readers' fuzzers (their coverage instrumentation on core/io alone), so that the library is compiled
# instrumented once. test_folders, when set: the test folders it builds; by default every one but
# numeric/ (arithmetic measured against the reference, on paths the logic tests take too: tens of
# times slower instrumented; the plain suite runs it). gl_tests and window_tests, when set: the GL and window tests it builds (empty: all).
# By default, representative sets: the GL pipeline, edits, picking, the render command, the compute
# scan, the overlays and the cache; the editor's command line, creases, and the random-input soak
# (first views and the modelling replays take minutes under ASan and run in the plain suite).
test_folders="${test_folders-core;app;render;ui;window}"
gl_tests="${gl_tests-surface_renderer;surface_edits;surface_cache;picking;render_cli;exclusive_scan;ellipsoid_overlay;shared_basis}"
window_tests="${window_tests-editor;editor_creases;editor_soak;window_context}"
source scripts/compiler_cache.sh
# Line tables only (-g1): a report still names functions, files and lines at a fraction of the disk.
# -O1, ASan's usual level: a much shorter build for a slightly slower suite. Clang, as libFuzzer needs:
# it compiles the instrumented tests in about a third of gcc's time. The logic tests run as shards of a
# few dozen tests per process (GPSURF_TEST_SHARDS): an instrumented process takes longer to start and
# finish than most of them take to run.
if [ -f build-asan/CMakeCache.txt ] && ! grep -q "^CMAKE_CXX_COMPILER:FILEPATH=.*clang++" build-asan/CMakeCache.txt; then
  rm -rf build-asan  # configured with another compiler, which a cache keeps
fi
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DGPSURF_SANITIZE=ON -DGPSURF_BUILD_FUZZ=ON -DGPSURF_BUILD_BENCH=OFF \
  -DGPSURF_BUILD_PYTHON=OFF -DGPSURF_TEST_FOLDERS="$test_folders" -DGPSURF_GL_TESTS="$gl_tests" \
  -DGPSURF_WINDOW_TESTS="$window_tests" -DGPSURF_TEST_SHARDS=8 "${launcher[@]}" >/dev/null
