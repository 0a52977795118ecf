#!/usr/bin/env bash
# Makes (or reuses) a minimal Debian root for one MeshLab release, under .deps/roots/SUITE
# (git-ignored): debootstrap from Debian's archive (the mirror of the host's bookworm entry; the
# host's apt sources are not touched), then MeshLab, the build tools and MeshLab's own source
# tarball (its plugin headers and vcglib) at /meshlab-src inside the root. Idempotent.
# Newer MeshLab binaries need a newer libc than bookworm's, hence a whole root, not a prefix.
# usage: make_root.sh SUITE      (trixie: MeshLab 2022.02, sid: MeshLab 2025.07)
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
SUITE=$1
R="$ROOT/.deps/roots/$SUITE"
# what the plugin and the host program build against (GMP: the exact predicates of hrsr_core),
# and xvfb for the GUI screenshots
PACKAGES=(meshlab g++ cmake ninja-build make qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev
          libglew-dev libeigen3-dev libgmp-dev xz-utils dpkg-dev xvfb xauth xdotool imagemagick)
MARKER="${PACKAGES[*]} and the recommended libraries"  # changes when what is installed does
source "$ROOT/scripts/debian_mirror.sh"
export DEBIAN_FRONTEND=noninteractive

[ "$(id -u)" -eq 0 ] || { echo "make_root.sh: must run as root (debootstrap, chroot)" >&2; exit 1; }
if ! command -v debootstrap >/dev/null; then
  for try in 1 2 3 4 5 6; do # another apt may hold the lock for a while
    apt-get install -y -qq --no-install-recommends debootstrap >/dev/null && break
    [ "$try" -lt 6 ] || { echo "make_root.sh: cannot install debootstrap" >&2; exit 1; }
    sleep 20; apt-get update -qq || true
  done
fi

URI=$(debian_mirror)
[ -n "$URI" ] || { echo "make_root.sh: no Debian bookworm entry in the host's apt sources" >&2; exit 1; }
if [ ! -f "$R/.debootstrap-done" ]; then
  # never into a mount (in_root.sh mounts /dev, /proc, /sys there while it runs)
  rm -rf --one-file-system "$R"; mkdir -p "$R"
  echo "make_root.sh: debootstrap $SUITE from $URI into .deps/roots/$SUITE"
  debootstrap --variant=minbase "$SUITE" "$R" "$URI" >"$R.debootstrap.log" 2>&1 || {
    tail -5 "$R.debootstrap.log" >&2
    echo "make_root.sh: FAILED: debootstrap of $SUITE from $URI (is Debian's archive reachable?)" >&2
    exit 1; }
  cat > "$R/etc/apt/sources.list" <<SRC
deb $URI $SUITE main
deb-src $URI $SUITE main
SRC
  # sid's Release file is only valid for about a week; the archive the machine reaches may be
  # older than that (a mirror snapshot), and the signatures are still checked.
  echo 'Acquire::Check-Valid-Until "false";' > "$R/etc/apt/apt.conf.d/99hrsr-valid-until"
  touch "$R/.debootstrap-done"
fi

if [ "$(cat "$R/.packages-done" 2>/dev/null)" != "$MARKER" ] ||
   [ ! -f "$R/meshlab-src/ML_VERSION" ]; then
  cp "$HERE/install_packages.sh" "$R/tmp/"
  bash "$HERE/in_root.sh" "$R" sh /tmp/install_packages.sh "${PACKAGES[@]}" || {
    echo "make_root.sh: FAILED: installing MeshLab and build tools in the $SUITE root from $URI" >&2
    exit 1; }
  echo "$MARKER" > "$R/.packages-done"
fi
echo "make_root.sh: $SUITE root ready: MeshLab $(cat "$R/meshlab-src/ML_VERSION")," \
     "package $(chroot "$R" dpkg-query -W -f='${Version}' meshlab)"
