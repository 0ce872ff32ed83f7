#!/usr/bin/env bash
# The GPU bundle's rehearsal (issue 55): builds the bundle here
# (bench/gpu-bundle.sh) and runs its real_gpu.sh, with a short budget, in a
# Debian chroot that holds no ParaView, no compiler, no GLVND loader and none of
# the project's dependencies: only Mesa's EGL vendor library and drivers
# (libegl-mesa0, libgl1-mesa-dri) stand in for a GPU's driver, and the
# software-renderer refusal is switched off. Every section must end "ok".
#
#   bash scripts/bundle-rehearsal.sh            # build the bundle, run it in the chroot
#   bash scripts/bundle-rehearsal.sh --prepare  # only make the chroot (.ci/run, beside the suite)
#
# The chroot is made once (debootstrap --variant=minbase bookworm, from the
# mirror this machine's apt sources name) and kept in
# $BOUNDPARTICLES_CHROOT_DIR/bundle-minbase (default
# /var/cache/boundparticles/chroots). Inside, the bundle is bind-mounted
# read-only in a private mount namespace, so nothing stays mounted after a run.
# BOUNDPARTICLES_BUNDLE_BUDGET (default 60) is the bench budget in seconds;
# BOUNDPARTICLES_BUNDLE_DIR a bundle already built to run instead. Needs root.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
chroots="${BOUNDPARTICLES_CHROOT_DIR:-/var/cache/boundparticles/chroots}"
name=bundle-minbase
dir="$chroots/$name"
suite=bookworm
start=$SECONDS

say() { echo "bundle-rehearsal: $*"; }
fail() {
  say "FAILED: $*" >&2
  exit 1
}
if [ "$(id -u)" != 0 ]; then
  say "skipped: needs root (debootstrap, chroot)"
  exit 77
fi

# debian_mirror: the mirror this machine's own apt sources name.
source "$(dirname "${BASH_SOURCE[0]}")/debian-mirror.sh"

# What the chroot must not hold: a loader or library the bundle has to carry.
check_bare() {
  local found
  found="$(cd "$dir" && ls -d usr/lib/x86_64-linux-gnu/libEGL.so.1* \
    usr/lib/x86_64-linux-gnu/libGLdispatch.so* usr/lib/x86_64-linux-gnu/libOpenGL.so* \
    usr/lib/x86_64-linux-gnu/libGL.so.1* usr/lib/x86_64-linux-gnu/libepoxy.so* \
    usr/lib/x86_64-linux-gnu/libbenchmark.so* usr/bin/gcc usr/bin/g++ usr/bin/cc \
    usr/bin/pvpython usr/bin/cmake 2>/dev/null || true)"
  [ -z "$found" ] || fail "the chroot is not bare, it holds: $(echo $found)"
  [ -e "$dir/usr/share/glvnd/egl_vendor.d/50_mesa.json" ] \
    || fail "the chroot lacks Mesa's EGL vendor file (libegl-mesa0)"
}

make_chroot() {
  if ! command -v debootstrap >/dev/null; then
    # As in the other suites' chroots (scripts/chroot-test.sh), where no
    # debootstrap is installed: the host's suite runs the rehearsal.
    say "skipped: no chroot yet and no debootstrap to make one (scripts/setup.sh debootstrap)"
    exit 77
  fi
  say "debootstrap --variant=minbase $suite into $dir"
  umount -R "$dir.partial/proc" "$dir.partial/sys" 2>/dev/null || true
  rm -rf --one-file-system "$dir.partial"
  debootstrap --variant=minbase "$suite" "$dir.partial" "$(debian_mirror)" \
    >"$chroots/$name-debootstrap.log" 2>&1 \
    || { tail -n 30 "$chroots/$name-debootstrap.log" >&2; fail "debootstrap"; }
  echo 'Acquire::Check-Valid-Until "false";' >"$dir.partial/etc/apt/apt.conf.d/99boundparticles"
  echo force-unsafe-io >"$dir.partial/etc/dpkg/dpkg.cfg.d/99boundparticles"
  printf '#!/bin/sh\nexit 101\n' >"$dir.partial/usr/sbin/policy-rc.d"
  chmod +x "$dir.partial/usr/sbin/policy-rc.d"
  cp /etc/resolv.conf "$dir.partial/etc/resolv.conf" 2>/dev/null || true
  # Mesa's EGL vendor library and its drivers, nothing recommended beside them.
  # proc and sys for apt only, in a mount namespace of its own.
  unshare -m bash -c '
    set -e
    mount --make-rprivate /
    mount -t proc proc "$1/proc"
    mount --rbind /sys "$1/sys"
    chroot "$1" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin DEBIAN_FRONTEND=noninteractive \
      bash -c "apt-get update -qq && apt-get install -y -qq --no-install-recommends \
        libegl-mesa0 libgl1-mesa-dri && apt-get clean"' \
    unshare-apt "$dir.partial" >>"$chroots/$name-debootstrap.log" 2>&1 \
    || { tail -n 30 "$chroots/$name-debootstrap.log" >&2; fail "installing libegl-mesa0 and libgl1-mesa-dri"; }
  mv "$dir.partial" "$dir"
}

mkdir -p "$chroots"
exec 9>"$chroots/$name.lock"
flock 9
[ -d "$dir" ] || make_chroot
check_bare
if [ "${1:-}" = --prepare ]; then
  say "chroot ready in $((SECONDS - start)) s ($dir)"
  exit
fi

# The bundle, built here unless one is given.
bundle="${BOUNDPARTICLES_BUNDLE_DIR:-}"
if [ -z "$bundle" ]; then
  bundle="${BOUNDPARTICLES_BUILD_DIR:-$root/build}/gpu-bundle"
  bash "$root/bench/gpu-bundle.sh" "$bundle" || fail "building the bundle"
fi
bundle="$(realpath "$bundle")"
say "bundle $bundle ($(du -sm "$bundle" | cut -f1) MiB) ready after $((SECONDS - start)) s"

budget="${BOUNDPARTICLES_BUNDLE_BUDGET:-60}"
out="$(mktemp -d "${TMPDIR:-/tmp}/bundle-rehearsal.XXXXXX")"
trap 'rm -rf "$out"' EXIT
# Inside: the bundle read-only at /bundle, its output folder at /out, /proc
# (nproc, the bench's memory figures) and /dev (Mesa's llvmpipe opens no device,
# but /dev/null and /dev/shm are needed); all in a private mount namespace.
rc=0
unshare -m bash -c '
  set -e
  dir="$1" bundle="$2" out="$3" budget="$4"
  mount --make-rprivate /
  mount -t proc proc "$dir/proc"
  mount --rbind /dev "$dir/dev"
  mkdir -p "$dir/bundle" "$dir/out"
  mount --bind "$bundle" "$dir/bundle"
  mount -o remount,bind,ro "$dir/bundle"
  mount --bind "$out" "$dir/out"
  exec chroot "$dir" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    BOUNDPARTICLES_ALLOW_SOFTWARE_GPU=1 BOUNDPARTICLES_BENCH_BUDGET="$budget" \
    bash /bundle/real_gpu.sh /out' \
  unshare-run "$dir" "$bundle" "$out" "$budget" || rc=$?
files=$(find "$out" -type f | wc -l)
say "real_gpu.sh exited $rc after $((SECONDS - start)) s; $files files in its output folder"
summary="$out/summary.txt"
[ -f "$summary" ] || fail "real_gpu.sh wrote no summary.txt"
grep '^section ' "$summary" || true
[ "$files" -le 8 ] || fail "real_gpu.sh wrote $files files (at most 8 come back from a lent machine)"
sections=$(grep -c '^section ' "$summary" || true)
bad=$(grep '^section ' "$summary" | grep -vEc ': ok( \(.*\))?$' || true)
[ "$sections" -gt 0 ] || fail "no section line in summary.txt"
if [ "$bad" -gt 0 ] || [ "$rc" -ne 0 ]; then
  for f in "$out"/*; do
    echo "----- $(basename "$f") (last 40 lines)"
    tail -n 40 "$f"
  done
  fail "$bad of $sections sections did not end ok (real_gpu.sh exit $rc)"
fi
say "passed: $sections sections ok in $((SECONDS - start)) s"
