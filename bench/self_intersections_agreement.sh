#!/usr/bin/env bash
# The exact self-intersection test against CGAL's Polygon_mesh_processing::self_intersections on
# the comparison's meshes: each input reconstructed with both methods at the defaults, then
# bench/cgal_self_intersections (built when CGAL is found) counts the pairs three ways and times
# each full search: ours as `hrsr check` counts them (vertex copies at one position welded), ours
# by vertex index (CGAL's view) and CGAL's. "equal" compares the last two pair by pair.
# Usage: bench/self_intersections_agreement.sh [BUILD_DIR]   (a benchmark, not a test; ~15 min
# on 2 cores, most of it RsR on the dragon and the bunny)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${1:-$ROOT/build}
DATA=$ROOT/../shared/data
TOOL=$BUILD/bench/cgal_self_intersections
[ -x "$TOOL" ] || { echo "no $TOOL (CGAL not found at configure time?)" >&2; exit 1; }
INPUTS=("$ROOT/data/owl_little.ply"
        "$DATA/topology/kitten_points_genus1_normals.ply"
        "$DATA/scans/bunny_rangescans_merged_normals.ply"
        "$DATA/meshes/dragon_vrip.ply"
        "$DATA/scans/lion_takanawa_mvs_normals.ply")
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
echo "machine: $(nproc) cores; commit $(git -C "$ROOT" rev-parse --short HEAD)"
printf '%-38s %-6s %9s %7s %9s %7s %6s %8s %8s %8s\n' input method triangles ours by_index cgal equal ours_s index_s cgal_s
for input in "${INPUTS[@]}"; do
  [ -f "$input" ] || { echo "skipping $input (needs ../shared/data)"; continue; }
  for method in hrsr rsr; do
    "$BUILD/apps/hrsr" reconstruct "$input" -o "$OUT/mesh.ply" --method "$method" -q ||
      { echo "failed: $input $method"; continue; }
    line=$("$TOOL" "$OUT/mesh.ply") || true
    set -- $line
    printf '%-38s %-6s %9s %7s %9s %7s %6s %8s %8s %8s\n' "$(basename "$input")" "$method" \
      "$2" "$4" "$6" "$8" "${12}" "${14}" "${16}" "${18}"
  done
done
