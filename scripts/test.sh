#!/usr/bin/env bash
# One command from a fresh clone to a green test run: set-up, build, ctest.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
start=$(date +%s)
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh"
echo "test.sh: set-up and build took $(( $(date +%s) - start )) s"
cd "$BUILD"
ctest --output-on-failure --timeout 600
echo "test.sh: total $(( $(date +%s) - start )) s"
