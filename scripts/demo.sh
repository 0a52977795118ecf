#!/usr/bin/env bash
# One command from a fresh clone to a result: set-up, build, and reconstruct the shipped sample
# (data/owl_little.ply, a 10,000-point partial scan without normals) into a triangle mesh with
# HRsR (the default method).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh" hrsr
mkdir -p "$ROOT/out"
"$BUILD/apps/hrsr" reconstruct "$ROOT/data/owl_little.ply" -o "$ROOT/out/owl_mesh.ply" \
  --report "$ROOT/out/owl_mesh.json"
echo
echo "demo.sh: mesh written to $ROOT/out/owl_mesh.ply (open it in MeshLab)"
echo "demo.sh: report (topology, r_v, what was dropped and why, timings) in $ROOT/out/owl_mesh.json"
