#!/usr/bin/env bash
# Fetches the MeshLab 2022.02 plugin headers (src/common) and its vcglib from Debian trixie's
# meshlab source tarball into .deps/meshlab-2022.02 (git-ignored), for the compile-only check of
# filter_hrsr against the 2022.02 plugin API (ctest meshlab_api_2022). Idempotent.
#
# The tarball comes through a private apt configuration (scripts/trixie_source.sh): trixie
# binaries cannot be installed on bookworm, and the plugin is only compiled against these
# headers, never linked or run.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DEST="$ROOT/.deps/meshlab-2022.02"
[ -f "$DEST/src/common/plugins/interfaces/filter_plugin.h" ] && exit 0
# shellcheck source=scripts/trixie_source.sh
source "$ROOT/scripts/trixie_source.sh"

mkdir -p "$ROOT/.deps"
tmp=$(mktemp -d "$ROOT/.deps/fetch2022.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
tarball=$(trixie_source_tarball meshlab "$tmp") || { echo "fetch_meshlab_2022.sh: cannot fetch meshlab" >&2; exit 1; }
case "$tarball" in */meshlab_2022.02*) ;; *) echo "fetch_meshlab_2022.sh: unexpected $tarball" >&2; exit 1 ;; esac
mkdir "$tmp/x"
tar xJf "$tarball" -C "$tmp/x" --wildcards '*/ML_VERSION' '*/src/common/*' '*/src/vcglib/*'
rm -rf "$DEST"
mv "$tmp"/x/* "$DEST"
echo "fetch_meshlab_2022.sh: MeshLab $(cat "$DEST/ML_VERSION") headers at .deps/meshlab-2022.02"
