#!/usr/bin/env bash
# Installs and builds if needed, then runs the whole test suite with ctest:
# GoogleTest for the engine core and the VTK filter, pvpython under xvfb-run
# for the plugin and the demo.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(bash "$root/scripts/build.sh" | tail -n 1)"
cd "$build"
t0=$SECONDS
ctest --output-on-failure --parallel "$(nproc)" --timeout 600
echo "test: the suite ran in $((SECONDS - t0)) s"
