#!/usr/bin/env bash
# HRsR at p = 0.5, 0.25, 0.125 against our RsR, on the bunny range scans (362k, with normals)
# and the dragon's vertices (437k, no normals): wall time and peak RSS (/usr/bin/time -v),
# r_v, boundary edges, non-manifold counts and (from the report) the re-expansion accounting.
# One run per configuration, all in this run, so the ratios compare like with like.
# Usage: bench/hrsr_vs_rsr.sh [BUILD_DIR]   (a benchmark, not a test; ~5 min on 2 cores)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${1:-$ROOT/build}
DATA=$ROOT/../shared/data
INPUTS=("$DATA/scans/bunny_rangescans_merged_normals.ply" "$DATA/meshes/dragon_vrip.ply")
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
echo "machine: $(nproc) cores, $(free -g | awk '/Mem:/{print $2}') GB; commit $(git -C "$ROOT" rev-parse --short HEAD)"
printf '%-34s %-10s %8s %8s %9s %7s %6s %6s %s\n' input method time_s rss_MB r_v Eb loops nm "replayed/records (failed)"
for input in "${INPUTS[@]}"; do
  [ -f "$input" ] || { echo "skipping $input (needs ../shared/data)"; continue; }
  for config in "rsr 1" "hrsr 0.5" "hrsr 0.25" "hrsr 0.125"; do
    set -- $config
    /usr/bin/time -v "$BUILD/apps/hrsr" reconstruct "$input" -o "$OUT/mesh.ply" --method "$1" \
      --collapse-ratio "$2" --report "$OUT/r.json" -q 2> "$OUT/time.txt" || { echo "failed: $input $config"; continue; }
    wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$OUT/time.txt")
    rss=$(( $(sed -n 's/.*Maximum resident set size (kbytes): //p' "$OUT/time.txt") / 1024 ))
    /usr/bin/python3 - "$OUT/r.json" "$(basename "$input")" "$1 p=$2" "$wall" "$rss" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); m = r["mesh"]; h = r["hrsr"]
w = sys.argv[4].split(":"); secs = float(w[-1]) + 60 * float(w[-2]) + (3600 * float(w[-3]) if len(w) > 2 else 0)
failed = sum(h["records_failed"].values())
print(f"{sys.argv[2]:<34} {sys.argv[3]:<10} {secs:8.1f} {int(sys.argv[5]):8d} {100*r['points']['vertex_reference_ratio']:8.3f}% "
      f"{m['boundary_edges']:7d} {m['boundary_loops']:6d} {m['non_manifold_edges'] + m['non_manifold_vertices']:6d} "
      f"{h['records_replayed']}/{h['records']} ({failed})")
PY
  done
done
