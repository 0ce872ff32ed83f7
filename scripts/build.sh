#!/usr/bin/env bash
# Installs what is missing, then configures and builds BoundParticles (Release,
# with Debian's build flags: scripts/build-options.sh) in
# ${BOUNDPARTICLES_BUILD_DIR:-build/}. The test suite runs in this build and
# scripts/package.sh makes the Debian package from it. Prints the build folder
# last.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BOUNDPARTICLES_BUILD_DIR:-$root/build}"

t0=$SECONDS
bash "$root/scripts/setup.sh"
echo "build: packages ready in $((SECONDS - t0)) s" >&2
mkdir -p "$build"
source "$root/scripts/build-options.sh"
build_options "$root"
if ! cmake -S "$root" -B "$build" "${build_options[@]}" >"$build/configure.log" 2>&1; then
  cat "$build/configure.log" >&2
  exit 1
fi
cmake --build "$build" --parallel "$(nproc)" -- --no-print-directory >"$build/build.log" 2>&1 || {
  tail -n 60 "$build/build.log" >&2
  exit 1
}
echo "build: configured and built in $((SECONDS - t0)) s in all" >&2
echo "$build"
