#!/usr/bin/env bash
# Configure and build (Release) into build/ (or $HRSR_BUILD_DIR). Assumes scripts/setup.sh ran.
# Arguments are build targets (default: everything).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
# A unity build by default (CMake joins each target's sources eight at a time, so that vcglib, Eigen
# and the standard headers are parsed once per eight files): a fresh build takes about 60 % of
# the time. HRSR_UNITY_BUILD=OFF when changing one file at a time.
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE="${HRSR_BUILD_TYPE:-Release}" \
  -DCMAKE_UNITY_BUILD="${HRSR_UNITY_BUILD:-ON}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$BUILD" -j"$(nproc)" "${targets[@]}"
