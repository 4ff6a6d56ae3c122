#!/usr/bin/env bash
# The library as a user gets it. A core-only configure (no GL, tests, benchmarks or Python) must look
# for no GL or image package; the package this build installs (the same core library: core knows
# nothing of GL) goes into a temporary prefix, and examples/cpp, a standalone CMake project, finds it
# with find_package(gpsurf 0.2), builds and runs. The core is not compiled a second time.
#   check_installed_package.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
source_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
work=$3
rm -rf "$work" && mkdir -p "$work"
cmake -S "$source_dir" -B "$work/core-configure" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGPSURF_BUILD_GL=OFF \
  -DGPSURF_BUILD_TESTS=OFF -DGPSURF_BUILD_BENCH=OFF -DGPSURF_BUILD_PYTHON=OFF >"$work/configure.log"
# Nothing GL- or image-related was looked for.
if looked=$(grep -i -E "osmesa|glfw|openimageio|oiio|egl|glm_|imgui|glad" "$work/core-configure/CMakeCache.txt"); then
  echo "the core-only configure looked for GL or image packages:" >&2
  echo "$looked" >&2
  exit 1
fi
cmake --install "$build_dir" --prefix "$work/prefix" >"$work/install.log"
test -f "$work/prefix/lib/cmake/gpsurf/gpsurfConfig.cmake"
test -f "$work/prefix/include/gpsurf/core/plans/planned_surface.h"
# Only the public headers and what they include: not the decimation's OpenMesh mesh, nor the plan builders.
test ! -e "$work/prefix/include/gpsurf/core/fitting/halfedge_collapse.h"
test ! -e "$work/prefix/include/gpsurf/core/plans/loop_plan_builder.h"
if grep -rl "#include <OpenMesh" "$work/prefix/include/gpsurf"; then
  echo "an installed header includes OpenMesh" >&2
  exit 1
fi
# Every installed header compiles from the prefix alone (nothing it includes was left out).
find "$work/prefix/include/gpsurf" -name '*.h' | sed 's|.*/include/gpsurf/\(.*\)|#include "\1"|' >"$work/all_headers.cpp"
c++ -std=c++20 -fsyntax-only -I"$work/prefix/include/gpsurf" -I/usr/include/eigen3 "$work/all_headers.cpp"
# The installed headers need C++20, which the exported target asks of whoever links it.
grep -q "cxx_std_20" "$work/prefix/lib/cmake/gpsurf/gpsurfTargets.cmake"
test -x "$work/prefix/bin/gpsurf"
"$work/prefix/bin/gpsurf" --version | grep -q "^gpsurf [0-9]"

cmake -S "$source_dir/examples/cpp" -B "$work/example-build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/example-configure.log"
cmake --build "$work/example-build" >"$work/example-build.log"
(cd "$work" && example-build/evaluate_surface > example.txt)
cat "$work/example.txt"
grep -q "Loop, 8 patches" "$work/example.txt"
grep -q "^wrote tessellation.obj" "$work/example.txt"
# The tessellation is the one `gpsurf tessellate` writes for the same mesh and level.
"$work/prefix/bin/gpsurf" sample cone-pointy -o "$work/cone.ply" >/dev/null
"$work/prefix/bin/gpsurf" tessellate "$work/cone.ply" -o "$work/cli.obj" --level 8 >/dev/null
cmp "$work/tessellation.obj" "$work/cli.obj"
echo "installed package: a core-only configure without GL; installed, found by examples/cpp"
