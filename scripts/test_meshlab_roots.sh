#!/usr/bin/env bash
# The filter in today's MeshLab: for each of MeshLab 2022.02 (Debian trixie) and 2025.07 (sid),
# make or reuse its root (scripts/root/make_root.sh), build the plugin and meshlab_host there
# against that release, run tests/plugin/test_meshlab_root.cpp against it; then check that a
# plugin built for one release is refused by the other. Prints the time of each step.
# Assumes scripts/build.sh ran (the host's hrsr and test_meshlab_root). usage: [SUITE...]
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${HRSR_BUILD_DIR:-$ROOT/build}
suites=(trixie sid)
[ $# -eq 0 ] || suites=("$@")
cmake --build "$BUILD" --target hrsr test_meshlab_root >/dev/null
for suite in "${suites[@]}"; do
  t0=$(date +%s)
  bash "$ROOT/scripts/root/make_root.sh" "$suite"
  t1=$(date +%s)
  bash "$ROOT/scripts/root/build_in_root.sh" "$suite" >/dev/null
  t2=$(date +%s)
  HRSR_MESHLAB_ROOT="$ROOT/.deps/roots/$suite" "$BUILD/tests/plugin/test_meshlab_root"
  t3=$(date +%s)
  echo "test_meshlab_roots.sh: $suite: root $((t1 - t0)) s, build $((t2 - t1)) s, tests $((t3 - t2)) s"
done

# A plugin is refused unless built for the exact MeshLab version that loads it.
if [ -d "$ROOT/.deps/roots/trixie/hrsr/build" ] && [ -d "$ROOT/.deps/roots/sid/hrsr/build" ]; then
  plugin=filter_hrsr/libfilter_hrsr.so
  cp "$ROOT/.deps/roots/trixie/hrsr/build/$plugin" "$ROOT/.deps/roots/sid/tmp/libfilter_hrsr_2022.so"
  out=$(bash "$ROOT/scripts/root/in_root.sh" "$ROOT/.deps/roots/sid" \
    /hrsr/build/filter_hrsr/host/meshlab_host /tmp/libfilter_hrsr_2022.so \
    "Surface Reconstruction: HRsR" --list 2>&1) && rc=0 || rc=$?
  rm "$ROOT/.deps/roots/sid/tmp/libfilter_hrsr_2022.so"
  if [ "$rc" -ne 1 ] || ! grep -q "has different version from the running MeshLab" <<<"$out"; then
    echo "FAILED: MeshLab 2025.07 did not refuse the plugin built for 2022.02 (exit $rc):" >&2
    echo "$out" >&2
    exit 1
  fi
  echo "test_meshlab_roots.sh: MeshLab 2025.07 refuses the plugin built for 2022.02, as it should"
fi
