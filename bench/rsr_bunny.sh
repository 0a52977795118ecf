#!/usr/bin/env bash
# RsR on the 362k-point bunny range scans (with scanner normals): wall time and peak memory of
# the whole run (/usr/bin/time -v), per-phase times and quality from hrsr's JSON report.
# Usage: bench/rsr_bunny.sh [BUILD_DIR] [INPUT.ply]   (a benchmark, not a test)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${1:-$ROOT/build}
INPUT=${2:-$ROOT/../shared/data/scans/bunny_rangescans_merged_normals.ply}
[ -f "$INPUT" ] || { echo "rsr_bunny.sh: $INPUT not found (needs ../shared/data)"; exit 0; }
command -v /usr/bin/time >/dev/null || { echo "rsr_bunny.sh: needs /usr/bin/time (Debian package 'time')" >&2; exit 1; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
/usr/bin/time -v "$BUILD/apps/hrsr" reconstruct "$INPUT" -o "$OUT/mesh.ply" --method rsr \
  --report "$OUT/report.json" -q 2> "$OUT/time.txt"
wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$OUT/time.txt")
rss_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$OUT/time.txt")
echo "input: $INPUT"
echo "machine: $(nproc) cores, $(free -g | awk '/Mem:/{print $2}') GB; commit $(git -C "$ROOT" rev-parse --short HEAD)"
echo "wall time: $wall   peak RSS: $((rss_kb / 1024)) MB"
/usr/bin/python3 - "$OUT/report.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); m = r["mesh"]; p = r["points"]
print(f"points: {p['input']} input, {p['used']} used, dropped {p['dropped']}, merged {p['merged_duplicates']}")
print(f"r_v = {100 * p['vertex_reference_ratio']:.3f} %")
print(f"mesh: V={m['vertices']} F={m['faces']} boundary edges={m['boundary_edges']} loops={m['boundary_loops']} "
      f"non-manifold edges={m['non_manifold_edges']} vertices={m['non_manifold_vertices']} components={m['components']}")
print(f"rsr: {r['rsr']}")
for t in r["timings"]:
    print(f"  {t['phase']:<22} {t['seconds']:7.2f} s")
PY
