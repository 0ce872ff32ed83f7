#!/usr/bin/env bash
# Plays a recorded GUI test (ParaView's XML events and checks) in the ParaView
# GUI under Xvfb, with the plugin on PV_PLUGIN_PATH: usage
#   run_gui_playback.sh PLUGIN_DIR DATA_DIR TEST.xml [EXTRA_PLUGIN_DIR]
# (EXTRA_PLUGIN_DIR: a test-only plugin loaded beside it).
# ($PARAVIEW_DATA_ROOT in the events is DATA_DIR.)
# An event on a widget that does not exist, or a failed check, makes ParaView
# exit non-zero, and so this script.
#
# The events are recorded in ParaView 5.11. From ParaView 6 on, a box
# widget's Translate, Rotate and Scale fields sit on the "Fields" page of a
# tab widget: their object paths are rewritten for the ParaView that plays;
# from 5.13 on, Reset Session's confirmation is not played (none comes).
set -u
plugin_dir="$1"
data_dir="$2"
script="$3"
export PV_PLUGIN_PATH="$plugin_dir${4:+:$4}"
# The check scripts the playback runs import gui_check.py from beside them,
# and what they share with the pvpython tests (state_file.py) from there.
export PYTHONPATH="$data_dir/GUI:$data_dir/Python${PYTHONPATH:+:$PYTHONPATH}"
# An installed package's plugin (its login script sets PV_PLUGIN_CONFIG_FILE)
# must not load beside the one under test.
unset PV_PLUGIN_CONFIG_FILE
# A fresh settings folder keeps the user's ParaView settings out of the test.
export HOME="$(mktemp -d)"
trap 'rm -rf "$HOME"' EXIT
version="$(pvpython --version 2>/dev/null | sed -nE 's/.*version ([0-9]+)[.]([0-9]+).*/\1 \2/p')"
read -r major minor <<<"${version:-0 0}"
played="$HOME/$(basename "$script")"
cp "$script" "$played"
if [ "$major" -ge 6 ]; then
  sed -i -E 's#(BoundParticleEmitterBox)/((translate|rotate|scale)[XYZ])#\1/tabWidget/qt_tabwidget_stackedwidget/fieldsPage/\2#g' \
    "$played"
fi
# From ParaView 5.13 on, Edit > Reset Session asks nothing: its
# confirmation's Yes (the message box after actionDelete_All) is not played.
if [ "$major" -ge 6 ] || { [ "$major" -eq 5 ] && [ "$minor" -ge 13 ]; }; then
  sed -i -E '/actionDelete_All/{n;/1QMessageBox0\/qt_msgbox_buttonbox/d}' "$played"
fi
# $BOUNDPARTICLES_DATA_DIR in the events (the shared data sets) is filled in.
if [ -n "${BOUNDPARTICLES_DATA_DIR:-}" ]; then
  sed -i "s#\$BOUNDPARTICLES_DATA_DIR#$(cd "$BOUNDPARTICLES_DATA_DIR" && pwd)#g" "$played"
fi
# $BOUNDPARTICLES_SCRATCH in the events: this run's scratch folder ($HOME).
sed -i "s#\$BOUNDPARTICLES_SCRATCH#$HOME#g" "$played"
script="$played"
timeout 300 bash "$(dirname "$0")/../../scripts/with-display.sh" \
  paraview --dr --data-directory="$data_dir" --test-directory="$HOME" \
  --test-script="$script" --exit
