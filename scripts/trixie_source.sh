#!/usr/bin/env bash
# Sourced by the fetch_*.sh scripts: trixie_source_tarball PACKAGE DIR downloads the upstream
# tarball of Debian trixie's source package PACKAGE into DIR and prints its path.
#
# The system's apt configuration is not touched: a private source list (deb-src only, trixie,
# same mirror as the system's bookworm entry) and private package lists under DIR/apt are
# used, so no trixie binary can ever be installed by it. Only the upstream tarball is taken
# (apt-get source --tar-only).

trixie_mirror() { # the Debian mirror of the system's bookworm entry (deb822 or one-line format)
  local f=/etc/apt/sources.list.d/debian.sources
  if [ -f "$f" ]; then
    awk '/^URIs:/{u=$2} /^Suites:.*bookworm( |$)/{print u; exit}' "$f"
  else
    awk '$1=="deb" && $3 ~ /^bookworm$/ {print $2; exit}' /etc/apt/sources.list 2>/dev/null
  fi
}

trixie_source_tarball() {
  local package=$1 dir=$2 uri apt
  uri=$(trixie_mirror)
  [ -n "$uri" ] || { echo "no Debian bookworm entry in the apt sources" >&2; return 1; }
  apt="$dir/apt"
  chmod 755 "$dir" # apt downloads as the _apt user (mktemp folders are private)
  mkdir -p "$apt/parts" "$apt/lists/partial" "$apt/cache/archives/partial"
  cat > "$apt/parts/trixie-src.sources" <<SOURCES
Types: deb-src
URIs: $uri
Suites: trixie
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
  local opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$apt/parts"
              -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache" -o Debug::NoLocking=1)
  apt-get "${opts[@]}" update -qq >&2
  ( cd "$dir" && apt-get "${opts[@]}" source --tar-only -qq "$package" >/dev/null 2>"$dir/apt.log" ) || {
    cat "$dir/apt.log" >&2; return 1; }
  ls "$dir/${package}_"*.orig.tar.*
}
