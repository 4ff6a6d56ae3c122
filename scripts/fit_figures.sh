#!/bin/bash
# Figures of gpsurf fit: per test mesh (scripts/fit_test_meshes.py) and control vertex count, the
# distances of the dense mesh's vertices to the simplified mesh's faces (piecewise linear), to its
# limit surface (GPS inference, no fit), to the plain fit's and to the GPS fit's, with times. Each
# fit's output is kept in OUT_FOLDER/MESH-COUNT-MODE.log (its per-iteration lines for
# scripts/plot_fit_iterations.py).
# Usage: scripts/fit_figures.sh GPSURF_BINARY OUT_FOLDER [CELLS_PER_CUBE_EDGE [VERTEX COUNTS...]]
set -euo pipefail
gpsurf=$1 out=$2 cells=${3:-91}
shift $(( $# < 3 ? $# : 3 ))
[ $# -gt 0 ] && counts=("$@") || counts=(500 1500 5000)
mkdir -p "$out"
/usr/bin/python3 "$(dirname "$0")/fit_test_meshes.py" "$out" "$cells"
for mesh in block bumpy scan; do
  for n in "${counts[@]}"; do
    echo "== $mesh, $n control vertices"
    start=$(date +%s.%N)
    "$gpsurf" simplify "$out/$mesh.obj" --vertices "$n" -o "$out/$mesh-$n.ply" | grep -E "^(rms|max)" | sed 's/^/GPS inference: /'
    echo "simplify: $(echo "$(date +%s.%N) - $start" | bc) s"
    "$gpsurf" compare "$out/$mesh.obj" "$out/$mesh-$n.ply" --linear | grep -E "^(rms|max)" | sed 's/^/simplified faces: /'
    for mode in plain gps; do
      flag=$([ $mode = plain ] && echo --plain || true)
      start=$(date +%s.%N)
      "$gpsurf" fit "$out/$mesh-$n.ply" --target "$out/$mesh.obj" -o "$out/$mesh-$n-$mode.ply" $flag \
        | tee "$out/$mesh-$n-$mode.log" | grep -E "^(iteration|rms|max)" | sed "s/^/$mode fit: /"
      echo "$mode fit: $(echo "$(date +%s.%N) - $start" | bc) s"
    done
  done
done
