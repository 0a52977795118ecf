#!/usr/bin/env bash
# D-26 fold repair: every input reconstructed with --fold-repair-rounds 0 and with the default,
# back to back, twice, alternating (this machine's wall times vary 10-15 % run to run). Reports
# wall time and peak RSS (/usr/bin/time -v), the repair's own counts (normalised coordinates)
# and `hrsr check`'s self-intersecting pairs of the written mesh, plus the boundary edges (flips
# must not change them).
# Usage: bench/fold_repair.sh [BUILD_DIR]   (a benchmark, not a test; ~6 min on 2 cores)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${1:-$ROOT/build}
DATA=$ROOT/../shared/data
CASES=("hrsr $ROOT/data/owl_little.ply"
       "hrsr $DATA/scans/bunny_rangescans_merged_normals.ply"
       "hrsr $DATA/scans/lion_takanawa_mvs_normals.ply"
       "rsr $DATA/scans/bunny_rangescans_merged_normals.ply")
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
echo "machine: $(nproc) cores, $(free -g | awk '/Mem:/{print $2}') GB; commit $(git -C "$ROOT" rev-parse --short HEAD)"
printf '%-38s %-6s %-7s %8s %8s %7s %7s %7s %6s %7s\n' input method rounds time_s rss_MB found left flips check Eb
for case in "${CASES[@]}"; do
  set -- $case
  method=$1 input=$2
  [ -f "$input" ] || { echo "skipping $input (needs ../shared/data)"; continue; }
  for run in 1 2; do
    for rounds in 0 default; do
      option=()
      [ "$rounds" = 0 ] && option=(--fold-repair-rounds 0)
      /usr/bin/time -v "$BUILD/apps/hrsr" reconstruct "$input" -o "$OUT/mesh.ply" --method "$method" \
        "${option[@]}" --report "$OUT/r.json" -q 2> "$OUT/time.txt" || { echo "failed: $case $rounds"; continue; }
      wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$OUT/time.txt")
      rss=$(( $(sed -n 's/.*Maximum resident set size (kbytes): //p' "$OUT/time.txt") / 1024 ))
      "$BUILD/apps/hrsr" check "$OUT/mesh.ply" --json > "$OUT/check.json"
      /usr/bin/python3 - "$OUT/r.json" "$OUT/check.json" "$(basename "$input")" "$method" "$rounds" "$wall" "$rss" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); c = json.load(open(sys.argv[2])); f = r["fold_repair"]
w = sys.argv[6].split(":"); secs = float(w[-1]) + 60 * float(w[-2]) + (3600 * float(w[-3]) if len(w) > 2 else 0)
print(f"{sys.argv[3]:<38} {sys.argv[4]:<6} {sys.argv[5]:<7} {secs:8.1f} {int(sys.argv[7]):8d} "
      f"{f['intersecting_pairs_found']:7d} {f['intersecting_pairs_after_flips']:7d} {f['flips']:7d} "
      f"{c['self_intersecting_pairs']:6d} {r['mesh']['boundary_edges']:7d}")
PY
    done
  done
done
