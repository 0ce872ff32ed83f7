#!/usr/bin/env bash
# The main job: installs and builds if needed, then traces bound particles through
# the built-in hurricane-like flow and writes bound-particles.png,
# bound-particles-gpu.png and bound-particles.vtp to the folder given
# (default: demo-output/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-$root/demo-output}")"
build="$(bash "$root/scripts/build.sh" | tail -n 1)"
plugin="$(cat "$build/plugin-path.txt")"
# The build's plugin alone: an installed package's (PV_PLUGIN_CONFIG_FILE, set
# by its login script) would load first and lend it its libraries.
unset PV_PLUGIN_CONFIG_FILE
bash "$root/scripts/with-display.sh" --unless-egl \
  pvpython "$root/demo/demo.py" --plugin "$plugin" --output "$out"
