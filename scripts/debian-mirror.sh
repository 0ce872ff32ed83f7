#!/usr/bin/env bash
# Sourced by the scripts that make chroots (chroot-test.sh,
# bundle-rehearsal.sh): debian_mirror prints the Debian mirror this
# machine's own apt sources name, or Debian's default one.
debian_mirror() {
  local uri
  uri="$(grep -hsE '^(URIs:|deb )' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list \
    | grep -m1 -E 'debian/?( |$)' | sed -E 's/^URIs: *//; s/^deb +(\[[^]]*\] +)?//; s/ .*//')"
  echo "${uri:-http://deb.debian.org/debian}"
}
