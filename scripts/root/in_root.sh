#!/usr/bin/env bash
# Runs a command as root inside a Debian root made by scripts/root/make_root.sh, with /proc, /sys
# and /dev mounted (apt's maintainer scripts and Qt need them). The mounts live in a private
# mount namespace (unshare -m): they vanish with the command, even when it is killed, never
# show on the host, and concurrent runs do not unmount each other's.
# usage: in_root.sh ROOT_DIR COMMAND [ARG...]
set -euo pipefail
R=$(cd "$1" && pwd); shift
cp /etc/resolv.conf "$R/etc/resolv.conf" # the host's name server, for apt inside the root
exec env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive QT_QPA_PLATFORM=offscreen R="$R" \
  unshare --mount --propagation private sh -ec '
    mount -t proc proc "$R/proc"; mount -t sysfs sysfs "$R/sys"; mount --rbind /dev "$R/dev"
    exec env -u R chroot "$R" "$@"' in_root "$@"
