#!/usr/bin/env bash
# HRsR, Screened Poisson and Ball Pivoting on the same cloud through meshlabserver, with
# scripts/meshlab_compare.mlx; writes OUT/hrsr.ply, OUT/poisson.ply, OUT/ball_pivoting.ply and
# OUT/log.txt (each filter's log: HRsR's report summary, Ball Pivoting's face count).
# usage: meshlab_compare.sh CLOUD.ply OUT [PLUGIN.so]
#   CLOUD needs oriented normals (Poisson and Ball Pivoting use them): `hrsr normals` makes them.
#   With PLUGIN, a private MeshLab prefix loads it (nothing installed); without, the system's
#   meshlabserver is used (after `cmake --install build`).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ $# -ge 2 ] || { echo "usage: meshlab_compare.sh CLOUD.ply OUT [PLUGIN.so]" >&2; exit 2; }
CLOUD=$(readlink -f "$1")
mkdir -p "$2"
OUT=$(cd "$2" && pwd)
if ! head -c 4096 "$CLOUD" | grep -aq '^property .* nx'; then
  echo "meshlab_compare.sh: $1 has no normals; make them first: hrsr normals $1 -o cloud.ply" >&2
  exit 1
fi
SERVER=meshlabserver
if [ $# -ge 3 ]; then
  sh "$ROOT/tests/plugin/make_prefix.sh" "$3" "$OUT/.prefix"
  SERVER="$OUT/.prefix/bin/meshlabserver"
fi
rm -f "$OUT/hrsr.ply" "$OUT/poisson.ply" "$OUT/ball_pivoting.ply"
cd "$OUT"   # Screened Poisson writes temporary files into the current folder
# passive OpenMP waiting: Poisson's spinning threads otherwise crawl on a busy machine
OMP_WAIT_POLICY=passive xvfb-run -a "$SERVER" -l "$OUT/log.txt" -i "$CLOUD" \
  -s "$ROOT/scripts/meshlab_compare.mlx" \
  -o "$OUT/hrsr.ply" -l 1 -m vn -o "$OUT/poisson.ply" -l 2 -m vn \
  -o "$OUT/ball_pivoting.ply" -l 3 -m vn > "$OUT/meshlabserver.txt" 2>&1 || {
  cat "$OUT/log.txt" >&2; exit 1; }
rm -rf "$OUT/.prefix"
for f in hrsr poisson ball_pivoting; do
  [ -s "$OUT/$f.ply" ] || { echo "meshlab_compare.sh: $f.ply not written; see $OUT/log.txt" >&2; exit 1; }
  echo "$OUT/$f.ply: $(sed -n 's/^element face //p' "$OUT/$f.ply" | head -1) triangles"
done
