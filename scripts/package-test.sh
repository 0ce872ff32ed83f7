#!/usr/bin/env bash
# Builds the Debian package (scripts/package.sh), installs it with apt, and
# checks it as a user meets it, in new login shells with nothing set by hand:
# pvpython traces and draws with the GPU display, pvbatch too, and the GUI
# offers the tracer in its Filters menu (Testing/Install/). Then purges the
# package and checks that nothing of it is left. Needs root. The package is
# purged however the checks end.
#
#   bash scripts/package-test.sh [OUTDIR]    # the .deb stays in OUTDIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-${BOUNDPARTICLES_BUILD_DIR:-$root/build}/package/deb}")"
name=paraview-boundparticles
codename="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"

say() { echo "package-test[$codename]: $*"; }
fail() {
  say "FAILED: $*" >&2
  exit 1
}
installed() { dpkg-query -W -f='${Status}' "$name" 2>/dev/null | grep -q "install ok installed"; }
purge() {
  DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq "$name" >/dev/null 2>&1 || true
}

start=$SECONDS
deb="$(bash "$root/scripts/package.sh" "$out" | tail -n 1)"
say "built $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB) in $((SECONDS - start)) s"
paraview_package="$(dpkg-deb -f "$deb" Depends | grep -oE '^[a-z0-9.+-]+ \(= [^)]*\)')" \
  || fail "the package does not depend on one exact ParaView: $(dpkg-deb -f "$deb" Depends)"
say "depends on $paraview_package"

installed && purge
trap purge EXIT
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$deb" >"$out/apt-install.log" 2>&1 || {
  cat "$out/apt-install.log" >&2
  fail "apt-get install $deb"
}

# A new login shell: only what the system's login scripts set.
work="$(mktemp -d)"
login() {
  timeout 600 env -i HOME="$work" TERM=dumb PATH=/usr/local/bin:/usr/bin:/bin LANG=C.UTF-8 \
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    bash -l -c 'cd "$HOME" && "$@"' login "$@"
}
check() { # check WHAT COMMAND...: the command's output, and fail on its failure
  local log="$work/$1.log"
  shift
  if ! "$@" >"$log" 2>&1; then
    cat "$log" >&2
    return 1
  fi
  grep -h "installed plugin" "$log" || true
}
display=(bash "$root/scripts/with-display.sh")
check pvpython login "${display[@]}" --unless-egl pvpython "$root/Testing/Install/check_installed.py" "$work" \
  || fail "pvpython in a login shell"
check pvbatch login "${display[@]}" --unless-egl pvbatch "$root/Testing/Install/check_installed.py" "$work" \
  || fail "pvbatch in a login shell"
check paraview login "${display[@]}" paraview --dr --test-script="$root/Testing/Install/filters_menu.xml" --exit \
  || fail "the GUI's Filters menu does not offer the Bound Particle Tracer"
say "the GUI's Filters menu offers the Bound Particle Tracer"
# A desktop session's environment (systemd's user manager), where systemd is.
generator=/usr/lib/systemd/user-environment-generators/30-systemd-environment-d-generator
if [ -x "$generator" ]; then
  env -i "$generator" | grep -q "^PV_PLUGIN_CONFIG_FILE=/usr/lib/.*/BoundParticles.plugins.xml" \
    || fail "a desktop session's environment does not name the plugin: $(env -i "$generator")"
  say "a desktop session's environment names the plugin"
fi

# Its files, and its own folders (the others are ParaView's or the system's).
files="$(dpkg -L "$name" | while read -r f; do
  if [ -f "$f" ] || [[ "${f,,}" == *boundparticles* ]]; then echo "$f"; fi
done)"
purge
trap - EXIT
installed && fail "still installed after apt-get purge"
left="$(for f in $files; do [ -e "$f" ] && echo "$f"; done || true)"
[ -z "$left" ] || fail "left behind by apt-get purge: $left"
dpkg-query -W -f='${Status}' "$name" 2>/dev/null | grep -q . \
  && fail "dpkg still knows $name after purge: $(dpkg-query -W -f='${Status}' "$name")"
[ -z "$(login printenv PV_PLUGIN_CONFIG_FILE || true)" ] \
  || fail "a login shell still sets PV_PLUGIN_CONFIG_FILE after purge"
rm -rf "$work"
say "installed, found with no LoadPlugin, purged with nothing left, in $((SECONDS - start)) s"
