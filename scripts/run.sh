#!/usr/bin/env bash
# Fresh machine to the main job: installs dependencies, builds, and installs gpsurf under /usr/local
# (the programs, the C++ package and the Python module: `python3 -c "import gpsurf"`); then, where
# there is a display, opens the editor on its embedded default sample (Preiner's cone with a sharp
# apex), and where there is none renders that sample headless (OSMesa) to out/default.png. Headless,
# the image comes first: only the two programs it runs are built before it, the editor and the
# module after.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  scripts/build.sh --programs
  cmake --install build >/dev/null
  exec build/app/gpsurf-editor "$@"
fi
scripts/build.sh --target gpsurf --target gpsurf-render
mkdir -p out
gpsurf=build/app/gpsurf
$gpsurf sample cone-pointy -o out/default.ply
$gpsurf render out/default.ply -o out/default.png --size 960x720 --mesh --pixels 4
echo "no display: rendered the built-in sample 'cone-pointy' (Preiner's cone with a sharp apex) headless: $(pwd)/out/default.png"
echo "building and installing the editor, the C++ package and the Python module under /usr/local"
scripts/build.sh --programs
cmake --install build >/dev/null
