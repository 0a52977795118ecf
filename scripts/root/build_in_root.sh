#!/usr/bin/env bash
# Builds the filter plugin and the host program (filter_hrsr/host) inside a root made by
# make_root.sh, against that root's MeshLab: its headers and vcglib (/meshlab-src, from the same
# release's source tarball) and its libmeshlab-common. A plugin is refused unless built for the
# exact MeshLab version that loads it, so the bookworm build cannot be reused.
# The working tree (not only what is committed) is copied to /hrsr/src; the build is /hrsr/build.
# usage: build_in_root.sh SUITE
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
R="$ROOT/.deps/roots/$1"
[ -f "$R/.packages-done" ] || { echo "build_in_root.sh: no $1 root; run make_root.sh $1" >&2; exit 1; }
mkdir -p "$R/hrsr/src"
tar -C "$ROOT" --exclude=./.deps --exclude=./.git --exclude='./build*' --exclude=./out -cf - . |
  tar -C "$R/hrsr/src" -xf -
bash "$HERE/in_root.sh" "$R" sh -ec '
  cmake -S /hrsr/src -B /hrsr/build -G Ninja -DCMAKE_BUILD_TYPE=Release -DMESHLAB_SOURCE_DIR=/meshlab-src \
        -DHRSR_BUILD_APPS=OFF -DHRSR_BUILD_TESTS=OFF -DHRSR_BUILD_BENCH=OFF \
        -DCMAKE_UNITY_BUILD=ON >/dev/null
  nice cmake --build /hrsr/build -j"$(nproc)" --target filter_hrsr meshlab_host'
echo "build_in_root.sh: $1: /hrsr/build/filter_hrsr/libfilter_hrsr.so and meshlab_host built"
