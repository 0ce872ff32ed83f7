#!/usr/bin/env bash
# Cross-compiles the engine core and its GoogleTest suite for aarch64 and runs
# the tests under qemu-user: proof that Core builds and gives the same results
# without x86's SSE2 (it then takes its scalar paths). Needs neither ParaView
# nor the GPU engine, nor an arm64 machine. Installs what is missing (as root
# or through sudo); builds in $BOUNDPARTICLES_AARCH64_DIR (default
# build-aarch64/ in the repository), kept between runs so a second run rebuilds
# only what changed; through ccache where it is installed, so a new clone
# compiles only what changed since any earlier one.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${BOUNDPARTICLES_AARCH64_DIR:-$root/build-aarch64}"
toolchain="$root/scripts/aarch64-toolchain.cmake"
jobs="${BOUNDPARTICLES_JOBS:-$(nproc)}"

# googletest: GoogleTest's sources, built below with the cross compiler (no
# arm64 foreign architecture to add to dpkg). Eigen is header-only.
PACKAGES=(g++-aarch64-linux-gnu qemu-user cmake make googletest libeigen3-dev)
missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "aarch64-core: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Logs go to files and are printed only on failure, as in build.sh.
step() {
  local log="$1"
  shift
  if ! "$@" >"$log" 2>&1; then
    tail -n 60 "$log" >&2
    echo "aarch64-core: FAILED: $*" >&2
    exit 1
  fi
}

# ccache, as scripts/build.sh: a new clone (CI's) compiles only what changed
# since any earlier one (paths taken relative to the clone), GoogleTest too.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$root"
fi

mkdir -p "$dir"
if [ ! -f "$dir/gtest/lib/cmake/GTest/GTestConfig.cmake" ]; then
  step "$dir/gtest-configure.log" cmake -S /usr/src/googletest -B "$dir/gtest-build" \
    -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release -DBUILD_GMOCK=OFF \
    -DCMAKE_INSTALL_PREFIX="$dir/gtest" -DCMAKE_INSTALL_LIBDIR=lib "${launcher[@]}"
  step "$dir/gtest-build.log" cmake --build "$dir/gtest-build" --parallel "$jobs" --target install
fi

# The core alone: no plugin (ParaView), no GPU engine (libepoxy), and
# GTest_DIR so that the host's x86-64 GoogleTest is never picked.
step "$dir/configure.log" cmake -S "$root" -B "$dir/build" \
  -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
  -DBOUNDPARTICLES_BUILD_PLUGIN=OFF -DBOUNDPARTICLES_BUILD_GPU=OFF \
  -DGTest_DIR="$dir/gtest/lib/cmake/GTest" "${launcher[@]}"
step "$dir/build.log" cmake --build "$dir/build" --parallel "$jobs" --target BoundParticlesCoreTests

# GoogleTest's shards, one a core, each its own qemu process: every test runs
# once, in one of them. Brief: each failure and the summary only (the full
# run: rerun without it).
pids=()
for ((shard = 0; shard < jobs; shard++)); do
  GTEST_TOTAL_SHARDS="$jobs" GTEST_SHARD_INDEX="$shard" \
    qemu-aarch64 -L /usr/aarch64-linux-gnu "$dir/build/bin/BoundParticlesCoreTests" \
    --gtest_brief=1 >"$dir/test-$shard.log" 2>&1 &
  pids+=($!)
done
failed=0
for ((shard = 0; shard < jobs; shard++)); do
  wait "${pids[$shard]}" || failed=1
  cat "$dir/test-$shard.log"
done
cat "$dir"/test-*.log >"$dir/test.log"
if [ "$failed" -eq 0 ]; then
  echo "aarch64-core: passed ($(awk '/^\[==========\] [0-9]+ tests? from/ { n += $2 } END { print n }' \
    "$dir/test.log") tests in $jobs shards)"
else
  echo "aarch64-core: FAILED (log in $dir/test.log)" >&2
  exit 1
fi
