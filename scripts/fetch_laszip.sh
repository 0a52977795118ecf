#!/usr/bin/env bash
# Fetches LASzip (the LAS/LAZ library) from Debian trixie's `laszip` source package and builds
# it into .deps/laszip (git-ignored): bookworm does not package it. Idempotent.
#
# The tarball comes through a private apt configuration (scripts/trixie_source.sh) that never
# touches the system's; it is built here with the system's compiler as a static library, so
# `hrsr` needs nothing at run time.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DEST="$ROOT/.deps/laszip"
[ -f "$DEST/include/laszip/laszip_api.h" ] && exit 0
# shellcheck source=scripts/trixie_source.sh
source "$ROOT/scripts/trixie_source.sh"

mkdir -p "$ROOT/.deps"
tmp=$(mktemp -d "$ROOT/.deps/fetchlaszip.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
tarball=$(trixie_source_tarball laszip "$tmp") || { echo "fetch_laszip.sh: cannot fetch laszip" >&2; exit 1; }
mkdir "$tmp/src"
tar xf "$tarball" -C "$tmp/src" --strip-components=1
# The library's own compiler warnings are not ours to fix: shown only if the build fails.
cmake -S "$tmp/src" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release -DLASZIP_BUILD_STATIC=ON \
      -DCMAKE_POSITION_INDEPENDENT_CODE=ON -DCMAKE_INSTALL_PREFIX="$DEST.partial" \
      >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log" >&2; exit 1; }
cmake --build "$tmp/build" -j"$(nproc)" >>"$tmp/build.log" 2>&1 || { tail -50 "$tmp/build.log" >&2; exit 1; }
rm -rf "$DEST.partial"
cmake --install "$tmp/build" >>"$tmp/build.log" 2>&1 || { tail -50 "$tmp/build.log" >&2; exit 1; }
rm -rf "$DEST"
mv "$DEST.partial" "$DEST"
echo "fetch_laszip.sh: LASzip $(basename "$tarball") built into .deps/laszip"
