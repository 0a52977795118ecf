#!/usr/bin/env bash
# Runs a command as root inside a Debian root made by scripts/root/make_root.sh, with /proc, /sys
# and /dev mounted for the command's duration (apt's maintainer scripts and Qt need them).
# usage: in_root.sh ROOT_DIR COMMAND [ARG...]
set -euo pipefail
R=$(cd "$1" && pwd); shift
mounted=()
cleanup() { for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" || true; done; }
trap cleanup EXIT
mountpoint -q "$R/proc" || { mount -t proc proc "$R/proc" && mounted+=("$R/proc"); }
mountpoint -q "$R/sys" || { mount -t sysfs sysfs "$R/sys" && mounted+=("$R/sys"); }
mountpoint -q "$R/dev" || { mount --rbind /dev "$R/dev" && mounted+=("$R/dev"); }
cp /etc/resolv.conf "$R/etc/resolv.conf" # the host's name server, for apt inside the root
env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
  DEBIAN_FRONTEND=noninteractive QT_QPA_PLATFORM=offscreen chroot "$R" "$@"
