#!/usr/bin/env bash
# Set-up for a fresh Debian/Ubuntu machine (idempotent; run as root, or with sudo available).
#  1. installs every build and test dependency from Debian packages;
#  2. enables deb-src entries if none exist (needed by `apt-get source`);
#  3. fetches the MeshLab source package of the installed meshlab version into .deps/
#     (git-ignored): it bundles vcglib and the plugin headers, matching the installed binary;
#  4. fetches and builds LASzip (LAS/LAZ reading) from Debian trixie's source into .deps/laszip.
# Users with their own trees can skip step 3 and configure CMake with
#   -DMESHLAB_SOURCE_DIR=/path/to/meshlab   or   -DVCGLIB_DIR=/path/to/vcglib
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export DEBIAN_FRONTEND=noninteractive

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup.sh: run as root (or install sudo)" >&2; exit 1; }
  SUDO="sudo"
fi

PACKAGES=(
  build-essential cmake ninja-build dpkg-dev pkg-config git time python3
  libeigen3-dev libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  # PCD binary_compressed blocks (LZF); exact predicates (GMP); the CGAL agreement test and bench
  liblzf-dev libgmp-dev libcgal-dev
  clang-format clang-tidy
  # sanitizer and fuzz stage (scripts/test_sanitizers.sh): libFuzzer and OpenMP for clang
  clang-14 libclang-rt-14-dev libomp-14-dev
  # the MeshLab plugin: the installed MeshLab, and what its headers include
  meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev
  # headless runs of meshlabserver / the GUI for plugin tests and screenshots (scripts/screenshots.sh)
  xvfb xauth xdotool imagemagick
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

has_deb_src() { grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; }
if ! has_deb_src; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then        # deb822 (bookworm default)
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources |
      $SUDO tee /etc/apt/sources.list.d/hrsr-deb-src.sources >/dev/null
  elif [ -f /etc/apt/sources.list ]; then                         # one-line format
    sed -n 's/^deb /deb-src /p' /etc/apt/sources.list |
      $SUDO tee /etc/apt/sources.list.d/hrsr-deb-src.list >/dev/null
  fi
  missing+=("--refresh")   # force an update below
fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup.sh: installing ${missing[*]/--refresh/}"
  $SUDO apt-get update -qq
  pkgs=("${missing[@]/--refresh/}")
  # shellcheck disable=SC2068
  $SUDO apt-get install -y -qq --no-install-recommends ${pkgs[@]} >/dev/null
fi

# MeshLab sources (vcglib + plugin headers) for exactly the installed meshlab version.
DEPS="$ROOT/.deps"
if [ ! -e "$DEPS/meshlab-src/vcglib/vcg" ] && [ ! -e "$DEPS/meshlab-src/src/vcglib/vcg" ]; then
  V=$(dpkg-query -W -f='${Version}' meshlab)
  mkdir -p "$DEPS"
  tmp=$(mktemp -d "$DEPS/fetch.XXXXXX")
  ( cd "$tmp" && apt-get source -qq "meshlab=$V" >/dev/null 2>"$tmp/apt-source.log" ) || {
    cat "$tmp/apt-source.log" >&2
    # deb-src entries may be present but not yet in the package lists
    $SUDO apt-get update -qq
    ( cd "$tmp" && apt-get source -qq "meshlab=$V" >/dev/null )
  }
  UP=${V%-*}; UP=${UP#*:}                                   # strip Debian revision and epoch
  rm -rf "$DEPS/meshlab-$UP"
  mv "$tmp/meshlab-$UP" "$DEPS/meshlab-$UP"
  rm -rf "$tmp"
  ln -sfn "meshlab-$UP" "$DEPS/meshlab-src"
fi
echo "setup.sh: MeshLab source at .deps/meshlab-src ($(cat "$DEPS/meshlab-src/ML_VERSION" 2>/dev/null || echo '?'))"

# LASzip for LAS/LAZ input (not packaged for bookworm): built from trixie's source.
bash "$ROOT/scripts/fetch_laszip.sh"
