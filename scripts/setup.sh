#!/usr/bin/env bash
# Installs every Debian package the BoundParticles build, demo and tests need,
# for the Debian suite this runs on: bookworm (ParaView 5.11, Qt 5), trixie
# (ParaView 5.13, Qt 6) or forky/sid (ParaView 6.x on the system VTK, Qt 6).
# Idempotent and quiet: it does nothing when everything is already installed.
#
#   setup.sh [PACKAGE...]    # also the packages named (scripts/package.sh: lintian)
set -euo pipefail

codename="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"

COMMON=(
  build-essential cmake ccache git pkgconf python3-dev
  paraview paraview-dev python3-paraview python3-numpy libgl1-mesa-dri
  libopenmpi-dev openmpi-bin libutfcpp-dev libglew-dev liblz4-dev libdouble-conversion-dev
  libtiff-dev libnetcdf-dev libgdal-dev libavformat-dev libavcodec-dev
  libavutil-dev libswscale-dev libgl2ps-dev libtheora-dev libeigen3-dev
  libgtest-dev libbenchmark-dev xvfb xauth
  libepoxy-dev libegl-dev libegl-mesa0
)
case "$codename" in
  bookworm)
    SUITE=(qtbase5-dev qttools5-dev qtxmlpatterns5-dev-tools libqt5svg5-dev libqt5opengl5-dev)
    ;;
  trixie)
    SUITE=(qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-5compat-dev qt6-svg-dev
      libxml2-dev libexpat1-dev libhdf5-dev libboost-dev libfreetype-dev libjpeg-dev
      libpng-dev liblzma-dev zlib1g-dev libx11-dev python3-mpi4py)
    ;;
  forky | sid) # ParaView 6 builds on the system VTK (with TBB).
    SUITE=(qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-5compat-dev qt6-svg-dev
      libvtk9-dev libtbb-dev libxml2-dev libexpat1-dev libhdf5-dev libboost-dev
      libfreetype-dev libjpeg-dev libpng-dev liblzma-dev zlib1g-dev libx11-dev libexprtk-dev
      libjsoncpp-dev libproj-dev libogg-dev libsqlite3-dev nlohmann-json3-dev python3-mpi4py
      xsltproc libvtk9-qt-dev)
    ;;
  *)
    echo "setup: Debian 12 (bookworm), 13 (trixie) or forky/sid is needed; this is" \
      "'${codename:-unknown}'. Install ParaView's development files yourself and build" \
      "with cmake (README: ParaView versions)." >&2
    exit 1
    ;;
esac
PACKAGES=("${COMMON[@]}" "${SUITE[@]}" "$@")

# Debian's trixie and forky paraview-dev name the Python modules by their plain
# file names (vtkmodules/vtkCommonCore.so) while the packages ship them as
# vtkCommonCore.cpython-3XX-ARCH.so, and CMake refuses ParaView's config until
# every named file exists: a link for each.
link_python_modules() {
  local named actual
  grep -rhoE '"[$][{]_IMPORT_PREFIX[}]/lib/python3/dist-packages/[^"]*[.]so"' \
    /usr/lib/*/cmake/paraview-* /usr/lib/*/cmake/vtk-* 2>/dev/null \
    | tr -d '"' | sed 's|^[$]{_IMPORT_PREFIX}|/usr|' | sort -u \
    | while read -r named; do
      [ -e "$named" ] && continue
      for actual in "${named%.so}".cpython-*.so; do
        if [ -e "$actual" ]; then
          $SUDO ln -sf "$(basename "$actual")" "$named"
        fi
      done
    done || true # no named modules (ParaView 5.11) is fine
}

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  link_python_modules
  exit 0
fi

echo "setup: installing ${#missing[@]} package(s) for ${codename:-this system}: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
link_python_modules
echo "setup: done"
