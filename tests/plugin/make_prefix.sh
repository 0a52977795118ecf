#!/bin/sh
# A private MeshLab prefix that loads our plugin next to the system ones (MeshLab 2020.09 only
# looks in <dir of the executable>/../lib/<multiarch>/meshlab/plugins; docs/MESHLAB.md §1.4).
# usage: make_prefix.sh PLUGIN.so PREFIX   (PLUGIN "-": only the system plugins, e.g. to install
# ours into PREFIX with `DESTDIR=... cmake --install`)
set -eu
PLUGIN=$1
[ "$PLUGIN" = - ] || PLUGIN=$(readlink -f "$PLUGIN")
PREFIX=$2
MA=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch)
SYS=/usr/lib/$MA/meshlab
rm -rf "$PREFIX"
mkdir -p "$PREFIX/bin" "$PREFIX/lib/$MA/meshlab/plugins"
cp /usr/bin/meshlab /usr/bin/meshlabserver "$PREFIX/bin/"   # copies: a symlink would resolve to /usr
ln -s "$SYS/libmeshlab-common.so" "$PREFIX/lib/$MA/meshlab/"
for p in "$SYS"/plugins/*.so; do   # not an installed copy of ours: the prefix gets its own
  [ "$(basename "$p")" = libfilter_hrsr.so ] || ln -s "$p" "$PREFIX/lib/$MA/meshlab/plugins/"
done
[ "$PLUGIN" = - ] || ln -sf "$PLUGIN" "$PREFIX/lib/$MA/meshlab/plugins/$(basename "$PLUGIN")"
