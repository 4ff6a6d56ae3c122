#!/usr/bin/env bash
# The fit table on public scans and CAD parts: CGAL's example meshes (Debian's libcgal-demo, its
# data.tar.gz), each simplified to N vertices, then fitted by gpsurf fit (GPS) and gpsurf fit --plain,
# both with their defaults; per mesh, GPS ÷ plain rms distance of the mesh's vertices to the fitted
# limit surface, the normals' rms angle of each, and each fit's iterations and seconds.
# Usage: scripts/fit_table.sh GPSURF_BINARY OUT_FOLDER [VERTICES [MESHES...]]
set -euo pipefail
gpsurf=$1 out=$2 vertices=${3:-1500}
shift $(($# < 3 ? $# : 3))
[ $# -gt 0 ] && meshes=("$@") || meshes=(bunny00 armadillo camel cow turbine fandisk fandisk_large anchor_dense blade cheese)
data=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$data" ] || { echo "fit_table.sh: $data is missing (apt-get install libcgal-demo)" >&2; exit 1; }
mkdir -p "$out"
tar -xzf "$data" -C "$out" --wildcards '*/meshes/*.off'
# The rms distance and the normals' rms angle that gpsurf compare reports, as "RMS ANGLE".
measure() { "$gpsurf" compare "$1" "$2" | awk '/^rms/ {r = $2} /^normals/ {a = $4; sub("°", "", a)} END {print r, a}'; }
echo "| mesh | GPS ÷ plain rms | normals GPS / plain | iterations GPS / plain | seconds GPS / plain |"
echo "|---|---|---|---|---|"
for name in "${meshes[@]}"; do
  dense=$(find "$out" -path "*/meshes/$name.off" | head -1)
  [ -n "$dense" ] || { echo "fit_table.sh: no mesh $name in $data" >&2; exit 1; }
  "$gpsurf" simplify "$dense" -o "$out/$name.ply" --vertices "$vertices" --repair -q
  declare -A rms angle iterations seconds
  for mode in gps plain; do
    flag=$([ $mode = plain ] && echo --plain || true)
    start=$(date +%s.%N)
    "$gpsurf" fit "$out/$name.ply" --target "$dense" -o "$out/$name-$mode.ply" --level 0 $flag >"$out/$name-$mode.log"
    seconds[$mode]=$(echo "$(date +%s.%N) - $start" | bc)
    iterations[$mode]=$(sed -n 's/^stopped after \([0-9]*\) iterations.*/\1/p' "$out/$name-$mode.log")
    read -r rms[$mode] angle[$mode] <<<"$(measure "$dense" "$out/$name-$mode.ply")"
  done
  awk -v n="$name" -v g="${rms[gps]}" -v p="${rms[plain]}" -v ga="${angle[gps]}" -v pa="${angle[plain]}" \
    -v gi="${iterations[gps]}" -v pi="${iterations[plain]}" -v gs="${seconds[gps]}" -v ps="${seconds[plain]}" \
    'BEGIN {printf "| %s | %.2f | %s° / %s° | %s / %s | %.1f / %.1f |\n", n, g / p, ga, pa, gi, pi, gs, ps}'
done
