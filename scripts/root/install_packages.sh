#!/bin/sh
# Runs INSIDE a root (make_root.sh copies it there): installs the given packages and the
# libraries of MeshLab's own plugins (which the meshlab package only recommends; not the GLES
# alternative of Qt's GUI library, which would replace the desktop one), then unpacks the
# release's own source tarball (plugin headers, vcglib) at /meshlab-src.
# usage: install_packages.sh PACKAGE...
set -eu
apt-get update -qq
apt-get install -y -qq --no-install-recommends "$@" >/dev/null
libraries=$(apt-cache depends meshlab |
  awk '$1 == "Recommends:" && $2 ~ /^lib/ && $2 !~ /gles/ {print $2}')
# shellcheck disable=SC2086
apt-get install -y -qq --no-install-recommends $libraries >/dev/null
rm -rf /meshlab-src /tmp/meshlab-source && mkdir /tmp/meshlab-source && cd /tmp/meshlab-source
apt-get source --tar-only -qq meshlab 2>/dev/null
mkdir /meshlab-src
tar xJf meshlab_*.orig.tar.xz -C /meshlab-src --strip-components=1 \
  --wildcards '*/ML_VERSION' '*/src/common/*' '*/src/vcglib/*'
cd / && rm -rf /tmp/meshlab-source /var/cache/apt/archives/*.deb
