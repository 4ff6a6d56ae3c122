#!/usr/bin/env bash
# Fresh machine to the main job: installs dependencies, builds, and runs gpsurf on its embedded
# default sample, writing the results to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
mkdir -p out
gpsurf=build/app/gpsurf
$gpsurf sample cube -o out/cube.ply
$gpsurf subdivide out/cube.ply -o out/cube_subdivided.ply --levels 3 --limit
$gpsurf info out/cube_subdivided.ply
echo "results: $(pwd)/out/cube.ply (the built-in cube), $(pwd)/out/cube_subdivided.ply (3 levels of GPS subdivision, limit positions)"
