#!/usr/bin/env bash
# Builds the Debian package of the plugin for this machine's Debian and
# ParaView, and checks it with lintian:
#
#   bash scripts/package.sh [OUTDIR]    # writes OUTDIR/paraview-boundparticles_*.deb
#   apt install ./OUTDIR/paraview-boundparticles_*.deb
#
# Builds, or brings up to date, the build folder the test suite runs in
# (scripts/build.sh: ${BOUNDPARTICLES_BUILD_DIR:-build/}, Release with
# Debian's build flags, the tests included) and makes the package from it,
# with no second compile: installs its runtime component for the prefix /usr
# into a staging folder (in the build folder's package/) and makes the package
# with dpkg-deb. The package depends on the exact version of the ParaView
# package it was built against: apt refuses it beside any other. Its plugin
# configuration file and login scripts make every ParaView load the plugin at
# start (docs/user-guide.md, Installing). Prints the package's path last.
# Lintian's errors fail the script.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-$root/package-output}")"
name=paraview-boundparticles

say() { echo "package: $*" >&2; }
fail() {
  say "FAILED: $*"
  exit 1
}

bash "$root/scripts/setup.sh" lintian >&2
build="$(bash "$root/scripts/build.sh" | tail -n 1)" || fail "the build (scripts/build.sh)"
work="$build/package" # the staging folder and the logs
mkdir -p "$work" "$out"
# The hardening flags lintian checks come from the build's configuration
# (scripts/build-options.sh); a build folder configured without them by hand
# would make a package lintian fails.
grep -q '^CMAKE_CXX_FLAGS:STRING=.*-fstack-protector' "$build/CMakeCache.txt" \
  || fail "$build is not configured with Debian's build flags (scripts/build-options.sh)"

stage="$work/stage"
rm -rf "$stage"
DESTDIR="$stage" cmake --install "$build" --component runtime --prefix /usr >"$work/install.log"
# dh_strip's way: no symbol tables or build notes in the shipped libraries.
find "$stage" -name '*.so' -type f -exec strip --strip-unneeded \
  --remove-section=.comment --remove-section=.note {} +

# The exact ParaView package this build is for: the one that holds the
# ParaView libraries the plugin links (paraview on Debian).
paraview_dir="$(sed -n 's/^ParaView_DIR:PATH=//p' "$build/CMakeCache.txt")"
remoting="$(find "$(dirname "$(dirname "$paraview_dir")")" -maxdepth 1 \
  -name 'libvtkRemotingCore-pv*.so.*' -print -quit 2>/dev/null || true)"
[ -n "$remoting" ] || fail "no ParaView library (libvtkRemotingCore-pv*.so) beside $paraview_dir"
paraview_package="$(dpkg -S "$(realpath "$remoting")" 2>/dev/null | head -n 1 | cut -d: -f1)"
[ -n "$paraview_package" ] || fail "the ParaView built against ($paraview_dir) is not \
Debian's: $remoting belongs to no Debian package"
paraview_version="$(dpkg-query -W -f='${Version}' "$paraview_package")"
paraview_upstream="$(echo "$paraview_version" | sed -E 's/^[0-9]+://; s/[+~-].*//')"
project_version="$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")"
version="$project_version+pv$paraview_upstream"
arch="$(dpkg --print-architecture)"
# Maintainer and date: the last commit's, so the same source gives the same package.
maintainer="$(git -C "$root" log -1 --format='%an <%ae>' 2>/dev/null || true)"
maintainer="${BOUNDPARTICLES_MAINTAINER:-${maintainer:-BoundParticles maintainers <boundparticles@users.noreply.github.com>}}"
date="$(git -C "$root" log -1 --format=%aD 2>/dev/null || date -R)"
docdir="$stage/usr/share/doc/$name"

# What Debian asks of every package's documentation.
gzip -9n >"$docdir/changelog.gz" <<EOF
$name ($version) unstable; urgency=medium

  * Built from the BoundParticles source tree for ParaView $paraview_version
    ($paraview_package).

 -- $maintainer  $date
EOF
cp "$root/packaging/debian/copyright" "$docdir/copyright"

# Dependencies: the libraries the plugin links (dpkg-shlibdeps; the plugin's
# own libraries beside it need none), and the exact ParaView.
shlibs="$work/shlibdeps"
rm -rf "$shlibs"
mkdir -p "$shlibs/debian"
printf 'Source: %s\n\nPackage: %s\nArchitecture: any\n' "$name" "$name" >"$shlibs/debian/control"
libraries=()
while IFS= read -r -d '' file; do libraries+=("$file"); done \
  < <(find "$stage" -name '*.so' -type f -print0)
depends="$(cd "$shlibs" && dpkg-shlibdeps -O -S"$stage" --ignore-missing-info \
  -l"$stage/usr/lib" "${libraries[@]}" 2>"$work/shlibdeps.log" \
  | sed -n 's/^shlibs:Depends=//p')" || {
  cat "$work/shlibdeps.log" >&2
  fail "dpkg-shlibdeps"
}
# ParaView's own libraries come with the exact version instead.
depends="$(echo "$depends" | tr ',' '\n' | sed 's/^ *//' \
  | grep -v "^$paraview_package\( \|$\)" | paste -sd, | sed 's/,/, /g')"
depends="$paraview_package (= $paraview_version)${depends:+, $depends}"

mkdir -p "$stage/DEBIAN"
(cd "$stage" && find etc -type f -printf '/%p\n' 2>/dev/null | sort) >"$stage/DEBIAN/conffiles"
[ -s "$stage/DEBIAN/conffiles" ] || rm "$stage/DEBIAN/conffiles"
(cd "$stage" && find usr -type f -print0 | sort -z | xargs -0 md5sum) >"$stage/DEBIAN/md5sums"
size="$(du -sk --exclude=DEBIAN "$stage" | cut -f1)"
cat >"$stage/DEBIAN/control" <<EOF
Package: $name
Version: $version
Architecture: $arch
Maintainer: $maintainer
Installed-Size: $size
Depends: $depends
Recommends: python3-paraview
Section: science
Priority: optional
Description: ParaView plugin for flow visualization with bound particles
 Small shapes of particles (strips, crosses, paddlewheels, fish, any mesh)
 tied together by stiff springs are advected through a time-varying vector
 field and restored to their shape after every step, so that tumbling shows
 vorticity, folding shows shear and alignment shows the stream lines.
 .
 The Bound Particle Tracer filter, the Bound Particles display (a GPU engine
 drawing in ParaView's render window), the Analytic Flow source and the Raw
 Vector Volume Series reader. Built for ParaView $paraview_version; every
 ParaView started from a login shell or a desktop session loads it.
EOF
chmod -R u=rwX,go=rX "$stage"

deb="$out/${name}_${version}_${arch}.deb"
dpkg-deb --root-owner-group -Zxz --build "$stage" "$deb" >/dev/null
say "$deb: $(du -k "$deb" | cut -f1) KiB, installed $size KiB; Depends: $depends"

# Lintian's errors fail the package; its warnings are printed.
if ! lintian --fail-on error --display-info --tag-display-limit 0 "$deb" >"$work/lintian.log" 2>&1; then
  cat "$work/lintian.log" >&2
  fail "lintian found errors in $deb"
fi
sed 's/^/lintian: /' "$work/lintian.log" >&2
echo "$deb"
