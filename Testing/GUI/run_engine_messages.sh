#!/usr/bin/env bash
# gui.engine_messages (issue 53, item 11): plays engine_messages.xml and
# counts, in ParaView's terminal output, the lines its output window passed
# on to Output Messages (a line it would suppress is written nowhere): on a
# software renderer one line that Engine Automatic traces on the CPU engine
# and why (none on a GPU, where the GPU engine runs), and one line that names
# the GPU engine's path, whatever the renderer.
#   run_engine_messages.sh PLUGIN_DIR TESTING_DIR LOG
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
log="$3"
bash "$here/run_gui_playback.sh" "$1" "$2" "$here/engine_messages.xml" >"$log" 2>&1
rc=$?
cat "$log"
software=$(grep -c "check_engine_messages: software renderer: yes" "$log")
engine=$(grep -c "^Bound Particle Tracer: Engine is Automatic and this render window draws" "$log")
path=$(grep -c "^BoundParticles GPU engine: the " "$log")
expected=0
[ "$software" -gt 0 ] && expected=1
echo "engine_messages: software renderer checks $software; Automatic's line $engine time(s)" \
  "(expected $expected); the GPU path's line $path time(s) (expected 1)"
[ "$engine" -eq "$expected" ] || rc=1
[ "$path" -eq 1 ] || rc=1
exit $rc
