#!/usr/bin/env bash
# Sourced: debian_mirror prints the Debian mirror of the system's bookworm apt entry (deb822 or
# one-line format), so that other suites are fetched from the same archive the machine uses.
debian_mirror() {
  local f=/etc/apt/sources.list.d/debian.sources
  if [ -f "$f" ]; then
    awk '/^URIs:/{u=$2} /^Suites:.*bookworm( |$)/{print u; exit}' "$f"
  else
    awk '$1=="deb" && $3 ~ /^bookworm$/ {print $2; exit}' /etc/apt/sources.list 2>/dev/null
  fi
}
