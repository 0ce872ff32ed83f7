#!/usr/bin/env bash
# Installs what is missing, then configures and builds BoundParticles (Release)
# in ${BOUNDPARTICLES_BUILD_DIR:-build/}. Prints the build folder last.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BOUNDPARTICLES_BUILD_DIR:-$root/build}"

t0=$SECONDS
bash "$root/scripts/setup.sh"
echo "build: packages ready in $((SECONDS - t0)) s" >&2
mkdir -p "$build"
# ccache (setup.sh installs it): a clone elsewhere, or the same sources built
# again, compiles only what changed (paths taken relative to the clone).
export CCACHE_BASEDIR="$root"
if ! cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  >"$build/configure.log" 2>&1; then
  cat "$build/configure.log" >&2
  exit 1
fi
cmake --build "$build" --parallel "$(nproc)" -- --no-print-directory >"$build/build.log" 2>&1 || {
  tail -n 60 "$build/build.log" >&2
  exit 1
}
echo "build: configured and built in $((SECONDS - t0)) s in all" >&2
echo "$build"
