#!/usr/bin/env bash
# Installs every Debian 12 package the BoundParticles build, demo and tests need.
# Idempotent and quiet: it does nothing when everything is already installed.
set -euo pipefail

PACKAGES=(
  build-essential cmake git
  paraview paraview-dev python3-paraview python3-numpy libgl1-mesa-dri
  qtbase5-dev qttools5-dev qtxmlpatterns5-dev-tools libqt5svg5-dev libqt5opengl5-dev
  libopenmpi-dev openmpi-bin libutfcpp-dev libglew-dev liblz4-dev libdouble-conversion-dev
  libtiff-dev libnetcdf-dev libgdal-dev libavformat-dev libavcodec-dev
  libavutil-dev libswscale-dev libgl2ps-dev libtheora-dev libeigen3-dev
  libgtest-dev xvfb xauth
  libepoxy-dev libegl-dev libegl-mesa0
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
echo "setup: installing ${#missing[@]} package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
