#!/usr/bin/env bash
# Runs gui_test.py in the ParaView GUI under Xvfb with the plugin on
# PV_PLUGIN_PATH, and passes when the script wrote its marker.
set -u
plugin_dir="$1"
marker="$2"
rm -f "$marker"
export PV_PLUGIN_PATH="$plugin_dir" BOUNDPARTICLES_GUI_MARKER="$marker"
# An installed package's plugin (its login script sets PV_PLUGIN_CONFIG_FILE)
# must not load beside the one under test.
unset PV_PLUGIN_CONFIG_FILE
# A fresh settings folder keeps the user's ParaView settings out of the test.
export HOME="$(mktemp -d)"
timeout 300 bash "$(dirname "$0")/../../scripts/with-display.sh" \
  paraview --script="$(dirname "$0")/gui_test.py"
if [ ! -s "$marker" ]; then
  echo "the GUI did not run the test script (no marker at $marker)" >&2
  exit 1
fi
cat "$marker"
grep -q "^traced" "$marker"
