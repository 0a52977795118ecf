#!/usr/bin/env bash
# D-32 (issue 16): two hrsr binaries side by side in one run, both methods, at the defaults, on
# the comparison's inputs: intersecting pairs of the written mesh by the exact test (`hrsr check`
# of the NEW binary on both outputs), r_v, points dropped in folds, boundary edges and loops,
# components, the largest component's genus, and the time of the run and of the fold phases.
# Usage: bench/fold_removal.sh OLD_HRSR NEW_HRSR [BUILD_DIR]   (a benchmark, not a test; about
# 8 min on 2 cores; needs ../shared/data for all but the owl)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OLD=$1 NEW=$2 BUILD=${3:-$ROOT/build}
DATA=$ROOT/../shared/data
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
inputs=("owl:$ROOT/data/owl_little.ply"
        "kitten:$DATA/topology/kitten_points_genus1_normals.ply"
        "bunny:$DATA/scans/bunny_rangescans_merged_normals.ply"
        "lion:$DATA/scans/lion_takanawa_mvs_normals.ply")
if [ -f "$DATA/meshes/dragon_vrip.ply" ]; then
  "$BUILD/bench/bench_points" vertices "$DATA/meshes/dragon_vrip.ply" "$OUT/dragon_vertices.ply"
  "$BUILD/bench/bench_points" sample "$DATA/meshes/dragon_vrip.ply" 200000 "$OUT/dragon_200k.ply"
  inputs+=("dragon_vertices:$OUT/dragon_vertices.ply" "dragon_200k:$OUT/dragon_200k.ply")
fi
echo "machine: $(nproc) cores; commit $(git -C "$ROOT" rev-parse --short HEAD)"
printf '%-16s %-5s %-4s %7s %7s %6s %9s %7s %6s %6s %5s %5s\n' input method bin total_s folds_s \
  pairs r_v_% dropped Eb loops comps genus
for entry in "${inputs[@]}"; do
  name=${entry%%:*} input=${entry#*:}
  [ -f "$input" ] || { echo "skipping $name (needs ../shared/data)"; continue; }
  for method in hrsr rsr; do
    for bin in old new; do
      exe=$OLD
      [ "$bin" = new ] && exe=$NEW
      "$exe" reconstruct "$input" -o "$OUT/mesh.ply" --method "$method" --report "$OUT/r.json" -q \
        2> /dev/null || { echo "failed: $name $method $bin"; continue; }
      "$NEW" check "$OUT/mesh.ply" --json > "$OUT/check.json"
      /usr/bin/python3 - "$OUT/r.json" "$OUT/check.json" "$name" "$method" "$bin" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); c = json.load(open(sys.argv[2])); m = r["mesh"]; p = r["points"]
total = sum(t["seconds"] for t in r["timings"])
folds = sum(t["seconds"] for t in r["timings"] if t["phase"].startswith("fold"))
dropped = p["dropped"].get("fold", 0)
print(f"{sys.argv[3]:<16} {sys.argv[4]:<5} {sys.argv[5]:<4} {total:7.2f} {folds:7.2f} "
      f"{c['self_intersecting_pairs']:6d} {100 * p['vertex_reference_ratio']:9.4f} {dropped:7d} "
      f"{m['boundary_edges']:6d} {m['boundary_loops']:5d} {m['components']:5d} "
      f"{m['largest_component']['genus']:5d}")
PY
    done
  done
done
