#!/usr/bin/env bash
# Builds BoundParticles and runs its whole test suite against the ParaView of
# another Debian suite, in a chroot made from Debian's archive:
#
#   bash scripts/chroot-test.sh trixie    # ParaView 5.13, VTK 9.3, Qt 6
#   bash scripts/chroot-test.sh forky     # ParaView 6.1,  VTK 9.6, Qt 6
#   bash scripts/chroot-test.sh forky COMMAND...   # build, then run COMMAND
#                                                  # inside (in the repository)
#   bash scripts/chroot-test.sh forky --package    # the Debian package: make it from
#                                  # the suite's build (/build, brought up to date),
#                                  # install, check and purge it (scripts/package-test.sh)
#   bash scripts/chroot-test.sh forky --prepare    # only make the chroot and install
#                                  # its packages (.ci/run does this beside the host's suite)
#
# The chroot is kept between runs in $BOUNDPARTICLES_CHROOT_DIR (default
# /var/cache/boundparticles/chroots/SUITE); a kept one is updated only when
# scripts/setup.sh asks for packages it lacks. Inside, the repository and the
# shared data beside it are bind-mounted read-only and the build folder is kept
# in the chroot (/build), so a second run rebuilds only what changed. The
# engine core's own tests (Testing/Core) are not built there
# (BOUNDPARTICLES_CORE_TESTS=OFF): they cannot differ between ParaView
# versions, and the host's suite and scripts/aarch64-core.sh run them.
# Every failure is printed with the suite's name. Needs root.
set -euo pipefail

suite="${1:?usage: chroot-test.sh SUITE [COMMAND...] (SUITE: trixie or forky)}"
shift
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
shared="$(cd "$root/.." && pwd)/shared"
chroots="${BOUNDPARTICLES_CHROOT_DIR:-/var/cache/boundparticles/chroots}"
dir="$chroots/$suite"

say() { echo "chroot-test[$suite]: $*"; }
fail() {
  say "FAILED: $*" >&2
  exit 1
}

# debian_mirror: the mirror this machine's own apt sources name.
source "$(dirname "${BASH_SOURCE[0]}")/debian-mirror.sh"

mounted=()
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -l "${mounted[$i]}" 2>/dev/null || true
  done
}
trap unmount_all EXIT

bind() { # bind SOURCE TARGET [ro]: a recursive bind (/dev brings /dev/pts and /dev/shm)
  # A run killed before its trap (SIGKILL) leaves its binds; one whose source
  # was deleted since cannot be bound over. This run holds the suite's lock,
  # so whatever is mounted there is such a leftover.
  umount -l "$2" 2>/dev/null || true
  mkdir -p "$2"
  mount --rbind "$1" "$2"
  mount --make-rslave "$2"
  mounted+=("$2")
  if [ "${3:-}" = ro ]; then
    mount -o remount,bind,ro "$2"
  fi
}

make_chroot() {
  command -v debootstrap >/dev/null || {
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
  }
  # A suite newer than this machine's debootstrap uses sid's script.
  local script=()
  [ -e "/usr/share/debootstrap/scripts/$suite" ] || script=(/usr/share/debootstrap/scripts/sid)
  say "debootstrap into $dir"
  # A debootstrap killed midway may have left its own mounts there.
  umount -R "$dir.partial/proc" "$dir.partial/sys" 2>/dev/null || true
  rm -rf --one-file-system "$dir.partial"
  mkdir -p "$chroots"
  debootstrap --variant=minbase "$suite" "$dir.partial" "$(debian_mirror)" "${script[@]}" \
    >"$chroots/$suite-debootstrap.log" 2>&1 \
    || { tail -n 30 "$chroots/$suite-debootstrap.log" >&2; fail "debootstrap"; }
  # An archive snapshot may serve a Release past its Valid-Until date.
  echo 'Acquire::Check-Valid-Until "false";' >"$dir.partial/etc/apt/apt.conf.d/99boundparticles"
  mv "$dir.partial" "$dir"
}

start=$SECONDS
mkdir -p "$chroots"
# One run per suite at a time: two would share the chroot's /build.
exec 9>"$chroots/$suite.lock"
flock 9
[ -d "$dir" ] || make_chroot
cp /etc/resolv.conf "$dir/etc/resolv.conf" 2>/dev/null || true
# Packages installed inside start no services (there is no init to run them).
printf '#!/bin/sh\nexit 101\n' >"$dir/usr/sbin/policy-rc.d"
chmod +x "$dir/usr/sbin/policy-rc.d"
# A chroot for tests need not survive a crash: dpkg unpacks without syncing
# each file (the first run installs some 4 GB of packages).
echo force-unsafe-io >"$dir/etc/dpkg/dpkg.cfg.d/99boundparticles"

bind /proc "$dir/proc"
bind /sys "$dir/sys"
bind /dev "$dir/dev"
bind "$root" "$dir/work/main" ro
if [ -d "$shared" ]; then
  bind "$shared" "$dir/work/shared" ro
fi

# Inside: install what the suite needs (scripts/setup.sh knows each suite's
# packages), then build in /build and run ctest: the README's test command.
inside() {
  chroot "$dir" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    HOME=/root LANG=C.UTF-8 BOUNDPARTICLES_BUILD_DIR=/build BOUNDPARTICLES_CORE_TESTS=OFF \
    CI="${CI:-}" "$@"
}
# An install interrupted in an earlier run leaves packages half-configured.
inside dpkg --configure -a >/dev/null 2>&1 || true
if [ "${1:-}" = --prepare ]; then
  inside bash /work/main/scripts/setup.sh lintian || fail "installing the suite's packages"
  say "ready in $((SECONDS - start)) s"
  exit
fi
if [ "${1:-}" = --package ]; then
  say "the Debian package (chroot ready after $((SECONDS - start)) s)"
  inside bash /work/main/scripts/package-test.sh || fail "the Debian package (see above)"
  say "package passed in $((SECONDS - start)) s"
  exit
fi
if [ $# -gt 0 ]; then
  inside bash -c 'cd /work/main && bash scripts/build.sh >/dev/null && exec "$@"' command "$@"
  exit
fi
say "build and test (chroot ready after $((SECONDS - start)) s)"
if ! inside bash /work/main/scripts/test.sh; then
  fail "the build or the test suite failed (see above; build logs in $dir/build)"
fi
say "passed in $((SECONDS - start)) s"
