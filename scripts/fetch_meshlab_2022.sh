#!/usr/bin/env bash
# Fetches the MeshLab 2022.02 plugin headers (src/common) and its vcglib from Debian trixie's
# meshlab source tarball into .deps/meshlab-2022.02 (git-ignored), for the compile-only check of
# filter_hrsr against the 2022.02 plugin API (ctest meshlab_api_2022). Idempotent.
#
# The system's apt configuration is not touched: a private source list (deb-src only, trixie,
# same mirror as the system's bookworm entry) and private package lists under .deps/apt-trixie
# are used, so no trixie binary can ever be installed by it. Only the upstream tarball is taken
# (apt-get source --tar-only): trixie binaries cannot be installed on bookworm, and the plugin
# is only compiled against these headers, never linked or run.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DEST="$ROOT/.deps/meshlab-2022.02"
[ -f "$DEST/src/common/plugins/interfaces/filter_plugin.h" ] && exit 0

source "$ROOT/scripts/debian_mirror.sh"
URI=$(debian_mirror)
[ -n "$URI" ] || { echo "fetch_meshlab_2022.sh: no Debian bookworm entry in the apt sources" >&2; exit 1; }

APT="$ROOT/.deps/apt-trixie"
mkdir -p "$APT/parts" "$APT/lists/partial" "$APT/cache/archives/partial"
cat > "$APT/parts/trixie-src.sources" <<EOF
Types: deb-src
URIs: $URI
Suites: trixie
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$APT/parts"
      -o "Dir::State::Lists=$APT/lists" -o "Dir::Cache=$APT/cache" -o Debug::NoLocking=1)
apt-get "${opts[@]}" update -qq
tmp=$(mktemp -d "$ROOT/.deps/fetch2022.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
( cd "$tmp" && apt-get "${opts[@]}" source --tar-only -qq meshlab 2>"$tmp/apt.log" ) || {
  cat "$tmp/apt.log" >&2; exit 1; }
tarball=$(ls "$tmp"/meshlab_2022.02*.orig.tar.xz)
mkdir "$tmp/x"
tar xJf "$tarball" -C "$tmp/x" --wildcards '*/ML_VERSION' '*/src/common/*' '*/src/vcglib/*'
rm -rf "$DEST"
mv "$tmp"/x/* "$DEST"
rm -rf "$APT"   # the private package lists are not needed any more
echo "fetch_meshlab_2022.sh: MeshLab $(cat "$DEST/ML_VERSION") headers at .deps/meshlab-2022.02"
