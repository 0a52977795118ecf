#!/usr/bin/env bash
# Issue 7 item 4: a Debug build of `hrsr` writes the same bytes as the Release build (from
# scripts/build.sh) on the shipped sample, for both methods. Builds only the hrsr target.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
RELEASE=${HRSR_BUILD_DIR:-$ROOT/build}
DEBUG=${HRSR_DEBUG_BUILD_DIR:-$ROOT/build-debug}
SAMPLE="$ROOT/data/owl_little.ply"
start=$(date +%s)
# A unity build, as scripts/build.sh makes (the same bytes are part of what this checks).
cmake -S "$ROOT" -B "$DEBUG" -DCMAKE_BUILD_TYPE=Debug -DHRSR_BUILD_TESTS=OFF \
  -DHRSR_BUILD_PLUGIN=OFF -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build "$DEBUG" -j"$(nproc)" --target hrsr >/dev/null
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
status=0
for method in hrsr rsr; do
  "$RELEASE/apps/hrsr" reconstruct "$SAMPLE" -q --method "$method" -o "$WORK/release.ply"
  "$DEBUG/apps/hrsr" reconstruct "$SAMPLE" -q --method "$method" -o "$WORK/debug.ply"
  if cmp -s "$WORK/release.ply" "$WORK/debug.ply"; then
    echo "test_determinism.sh: $method: Debug and Release outputs are identical ($(stat -c %s "$WORK/release.ply") bytes)"
  else
    echo "test_determinism.sh: FAILED: $method: Debug and Release outputs differ" >&2
    status=1
  fi
done
echo "test_determinism.sh: took $(( $(date +%s) - start )) s"
exit $status
