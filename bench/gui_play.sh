#!/usr/bin/env bash
# Frames per second of Play with the defaults in the real ParaView GUI, beside
# pvpython doing the same (bench/gui_play.py says what is measured):
#   bash bench/gui_play.sh [--plugin PLUGIN.so] [--data DIR] [--frames N]
#                          [--repeats R] [--only a.vti,b.pvd] [--out DIR] [--gui-only]
#                          [--setup FILE.py]
# The GUI runs under its own Xvfb (scripts/with-display.sh) with a fresh HOME
# and --dr, so no user settings (nor the welcome dialog) get in. It plays a
# generated QtTesting event file: File > Open and Apply, Filters > Bound
# Particle Tracer and Apply, the VCR toolbar's Play. Nothing is built: the
# plugin is the one in build/ (build/plugin-path.txt) unless --plugin says.
# Defaults: 50 frames a play, 3 plays per display; about 4 minutes in all.
# --setup FILE.py runs before each data set's plays in both (names: simple,
# tracer, reader, view, scene, gui), to measure a setting: e.g.
#   if gui: simple.SetActiveSource(None)
# (nothing of the GUI reacts to the tracer's data every frame then).
# --out DIR keeps the logs and gui.json / pvpython.json there.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
plugin=""
data="$root/../shared/data"
frames=50
repeats=3
only="combustor.vti,office.vti,carotid.vti,nek_eddy.pvd,gfs_wind10m.pvd"
out=""
gui_only=0
setup=""
while [ $# -gt 0 ]; do
  case "$1" in
    --plugin) plugin="$2"; shift 2 ;;
    --data) data="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --gui-only) gui_only=1; shift ;;
    --setup) setup="$(realpath "$2")"; shift 2 ;;
    *) echo "gui_play.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
if [ -z "$plugin" ]; then
  plugin="$(cat "$root/build/plugin-path.txt")"
fi
data="$(realpath "$data")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="${out:-$work}"
mkdir -p "$out"
bench="$root/bench/gui_play.py"

# The GUI: a fresh settings folder, the plugin on PV_PLUGIN_PATH.
/usr/bin/python3 "$bench" xml --output "$work/play.xml" --data "$data" \
  --data-sets "$only" --repeats "$repeats"
mkdir -p "$work/home"
config="$(/usr/bin/python3 -c 'import json,sys
print(json.dumps({"frames": int(sys.argv[1]), "output": sys.argv[2],
                  "data_sets": sys.argv[3].split(","), "setup": sys.argv[4]}))' \
  "$frames" "$out/gui.json" "$only" "$setup")"
start=$SECONDS
HOME="$work/home" PV_PLUGIN_PATH="$(dirname "$plugin")" BOUNDPARTICLES_GUI_PLAY="$config" \
  timeout 600 bash "$root/scripts/with-display.sh" \
  paraview --dr --test-directory="$work/home" --test-script="$work/play.xml" --exit \
  >"$out/gui.log" 2>&1 || echo "gui_play: the GUI exited with $? (log: $out/gui.log)" >&2
echo "gui_play: GUI done in $((SECONDS - start)) s" >&2

# pvpython: the same plays in a render view of the GUI's view size.
size="$(/usr/bin/python3 -c 'import json,sys
try:
    rows = json.load(open(sys.argv[1])); print(*rows[0]["view_size"])
except Exception:
    print(844, 527)' "$out/gui.json")"
if [ "$gui_only" = 0 ]; then
  start=$SECONDS
  timeout 600 bash "$root/scripts/with-display.sh" pvpython "$bench" pvpython \
    --plugin "$plugin" --data "$data" --data-sets "$only" --frames "$frames" \
    --repeats "$repeats" --view-size $size --output "$out/pvpython.json" \
    ${setup:+--setup "$setup"} \
    >"$out/pvpython.log" 2>&1 || echo "gui_play: pvpython exited with $? (log: $out/pvpython.log)" >&2
  echo "gui_play: pvpython done in $((SECONDS - start)) s" >&2
fi
/usr/bin/python3 "$bench" table "$out/gui.json" "$out/pvpython.json"
