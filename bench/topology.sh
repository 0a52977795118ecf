#!/usr/bin/env bash
# Topology at the defaults (issue 15): analytic surfaces × size × density × noise × normals,
# each reconstructed by HRsR at p = 0.5 / 0.25 / 0.125 and by RsR with every other option at its
# default, and by CGAL's Advancing Front for reference. Prints expected and found genus, boundary
# edges and time per cell; writes topology.json and topology.md (the table of docs/BENCHMARKS.md).
#
#   bench/topology.sh [--install] [--full] [--out DIR] [topology.py options]
#     --install   install libcgal-dev first (Debian), so the CGAL column is built
#     --full      sizes 5k, 20k, 100k and 1M (default: 5k, 20k, 100k)
#     topology.py options: --shapes, --sizes, --densities, --noise, --normals, --methods
#                          (comma-separated), --no-cgal, --jobs N, --timeout S, --hrsr BINARY
#                          (another build of hrsr, e.g. an older one for a before/after table)
# Needs python3. Builds the project into build/ (or $HRSR_BUILD_DIR) first.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
out="" install=0 pass=()
while [ $# -gt 0 ]; do
  case "$1" in
    --install) install=1 ;;
    --full) pass+=(--sizes 5000,20000,100000,1000000) ;;
    --out) out=$2; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) pass+=("$1") ;;
  esac
  shift
done
if [ $install = 1 ] && ! dpkg-query -W -f='${Status}' libcgal-dev 2>/dev/null | grep -q "install ok installed"; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends libcgal-dev >/dev/null
fi
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hrsr bench_points $(
  dpkg-query -W -f='${Status}' libcgal-dev 2>/dev/null | grep -q "install ok installed" &&
  echo cgal_advancing_front) >/dev/null
out=${out:-$BUILD/bench-results/topology}
mkdir -p "$out"
exec python3 "$ROOT/bench/topology.py" --build "$BUILD" --out "$out" "${pass[@]}"
