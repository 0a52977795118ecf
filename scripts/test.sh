#!/usr/bin/env bash
# One command from a fresh clone to a green test run: set-up, build, ctest.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
start=$(date +%s)
bash "$ROOT/scripts/setup.sh"
# Issue 19's Debian roots need only Debian's archive, not our build: made in the background while
# the project builds and its tests run (about 330 s of debootstrap and apt, mostly waiting on the
# network and the disk). The roots stage below calls make_root.sh again, which finds them ready,
# or makes what failed here again in the foreground, with its error.
with_roots=false # Issue 19's stage below: always in CI, skipped locally with HRSR_SKIP_MESHLAB_ROOTS=1
if [ "${CI:-}" = true ] || [ "${HRSR_SKIP_MESHLAB_ROOTS:-0}" != 1 ]; then with_roots=true; fi
if [ "$with_roots" = true ]; then
  roots_log="$ROOT/.deps/make_roots.log"
  mkdir -p "$ROOT/.deps"
  # its own process group (setsid), so that a failing stage stops debootstrap and apt with it;
  # at the lowest priority, so that it takes only what the build and the tests leave (at normal
  # priority, set-up and build took 480 s in b7b1247's fresh clone; the build alone about 250 s)
  nice -n 19 setsid bash -c 'for suite in trixie sid; do bash "$1/scripts/root/make_root.sh" "$suite" || exit 1; done' \
    _ "$ROOT" >"$roots_log" 2>&1 &
  roots_pid=$!
  trap 'kill -- -"$roots_pid" 2>/dev/null || kill "$roots_pid" 2>/dev/null || true' EXIT
fi
bash "$ROOT/scripts/build.sh"
echo "test.sh: set-up and build took $(( $(date +%s) - start )) s"
cd "$BUILD"
# One test at a time: the tests already keep both cores busy (session 55, fresh clone: 612 s
# serial; with -j2 608 s, each test 1.8 times slower).
ctest --output-on-failure --timeout 600
echo "test.sh: ctest done after $(( $(date +%s) - start )) s"
# Issue 7: Debug vs Release output, the ASan/UBSan build and the fuzzers. Always in CI; a local
# run may skip them with HRSR_SKIP_EXTRA_TESTS=1 (they take several minutes).
if [ "${CI:-}" = true ] || [ "${HRSR_SKIP_EXTRA_TESTS:-0}" != 1 ]; then
  bash "$ROOT/scripts/test_determinism.sh"
  bash "$ROOT/scripts/test_sanitizers.sh"
else
  echo "test.sh: HRSR_SKIP_EXTRA_TESTS=1: Debug/Release, sanitizer and fuzz stages skipped"
fi
# Issue 19: the filter built and run in MeshLab 2022.02 and 2025.07 (Debian trixie and sid roots
# made with debootstrap; needs root and Debian's archive on the first run). Always in CI, where
# it fails (not skips) when the archive cannot be reached; a local run may skip it with
# HRSR_SKIP_MESHLAB_ROOTS=1.
if [ "$with_roots" = true ]; then
  stage=$(date +%s)
  if wait "$roots_pid"; then
    echo "test.sh: the roots made in the background were ready after $(( $(date +%s) - stage )) s more"
  else
    tail -20 "$roots_log" >&2
    echo "test.sh: the roots made in the background failed (above); trying again" >&2
  fi
  bash "$ROOT/scripts/test_meshlab_roots.sh"
  echo "test.sh: MeshLab 2022.02 and 2025.07 stage took $(( $(date +%s) - stage )) s"
else
  echo "test.sh: HRSR_SKIP_MESHLAB_ROOTS=1: MeshLab 2022.02/2025.07 stage skipped"
fi
echo "test.sh: total $(( $(date +%s) - start )) s"
