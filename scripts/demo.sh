#!/usr/bin/env bash
# One command from a fresh clone to a result: set-up, build, and run the main job on the shipped
# sample (data/owl_little.ply, a 10,000-point partial scan without normals).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh" -DHRSR_BUILD_TESTS=OFF
mkdir -p "$ROOT/out"
"$BUILD/apps/hrsr" normals "$ROOT/data/owl_little.ply" -o "$ROOT/out/owl_normals.ply" \
  --report "$ROOT/out/owl_normals.json"
echo
echo "demo.sh: oriented point cloud written to $ROOT/out/owl_normals.ply"
echo "demo.sh: report (what was dropped or merged, and why) in $ROOT/out/owl_normals.json"
