#!/usr/bin/env bash
# The reconstruction comparison (issue 6), one command:
#   bench/compare.sh            full run on ../shared/data; rewrites the generated section of
#                               docs/BENCHMARKS.md and the plots in docs/bench/ (hours)
#   bench/compare.sh --quick    small inputs (owl 10k, kitten 5k, dragon samples 10k/20k) to test
#                               the script; the report goes to the results folder only
# Other options are passed to bench/compare.py (--methods, --datasets, --timeout S, --samples N,
# --resume, --again, --keep-meshes); --out DIR sets the results folder (default
# $HRSR_BUILD_DIR/bench-results/{full,quick}); --no-install skips the package check.
#
# 1. Installs the benchmark-only Debian packages if missing (apt-get, with sudo when not root):
#    libcgal-dev (the Advancing Front driver), python3-open3d, python3-matplotlib, plus what the
#    project's set-up already installs for MeshLab (meshlab, xvfb, xauth, time). They are not in
#    scripts/setup.sh because no test needs them.
# 2. Builds the project (Release) with the bench/ programs, reconfiguring so that CGAL is found.
# 3. Runs bench/compare.py (every method on every data set, `hrsr check` on every mesh) and
#    bench/bench_report.py (tables and plots).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
PYTHON=/usr/bin/python3 # Debian's interpreter: python3-open3d and python3-matplotlib live there

quick=0 install=1 out="" pass=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; pass+=("$1") ;;
    --no-install) install=0 ;;
    --out) out=$2; shift ;;
    --out=*) out=${1#--out=} ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) pass+=("$1") ;;
  esac
  shift
done
mode=$([ $quick = 1 ] && echo quick || echo full)
out=${out:-$BUILD/bench-results/$mode}

if [ $install = 1 ]; then
  wanted=(libcgal-dev python3-open3d python3-matplotlib meshlab xvfb xauth time)
  missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO=sudo
    echo "compare.sh: installing ${missing[*]}"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
      "${missing[@]}" >/dev/null
  fi
fi

echo "compare.sh: building into $BUILD"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DHRSR_BUILD_BENCH=ON >/dev/null
cmake --build "$BUILD" -j"$(nproc)" >/dev/null

echo "compare.sh: $mode run, results in $out"
mkdir -p "$out"
"$PYTHON" "$ROOT/bench/compare.py" --build "$BUILD" --out "$out" "${pass[@]}"
if [ $quick = 1 ]; then
  "$PYTHON" "$ROOT/bench/bench_report.py" "$out/results.json" "$out/BENCHMARKS.md" "$out/plots"
else
  "$PYTHON" "$ROOT/bench/bench_report.py" "$out/results.json" "$ROOT/docs/BENCHMARKS.md" \
    "$ROOT/docs/bench"
  cp "$out/results.json" "$ROOT/docs/bench/results.json"
fi
