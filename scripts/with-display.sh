#!/usr/bin/env bash
# Runs a command with a private Xvfb display of 24-bit colour (Debian's VTK is
# GLX-only, so pvpython, pvbatch and the GUI need one). Xvfb picks a free
# display number itself (-displayfd), so parallel runs cannot collide, and no
# temporary X authority is involved, so nothing is left to clean up.
#
# About one start in 25 here, more under load, VTK fails to open the display
# ("bad X server connection"; xvfb-run shows it too, and a later connection
# to the same server succeeds). Such a run is repeated on a new server, up to
# three attempts in all, and says so; any other failure is returned as it is.
set -u

start_xvfb() {
  local ready
  ready="$(mktemp)"
  Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp 3>"$ready" >/dev/null 2>&1 &
  xvfb=$!
  for _ in $(seq 200); do
    [ -s "$ready" ] && break
    kill -0 "$xvfb" 2>/dev/null || break
    sleep 0.05
  done
  display="$(head -n 1 "$ready" 2>/dev/null)"
  rm -f "$ready"
  if [ -z "$display" ]; then
    echo "with-display: Xvfb did not start" >&2
    kill "$xvfb" 2>/dev/null
    exit 1
  fi
}

stop_xvfb() {
  kill "$xvfb" 2>/dev/null
  wait "$xvfb" 2>/dev/null
}

log="$(mktemp)"
trap 'rm -f "$log"' EXIT
attempts=3
for attempt in $(seq "$attempts"); do
  start_xvfb
  : >"$log"
  DISPLAY=":$display" "$@" > >(tee -a "$log") 2> >(tee -a "$log" >&2)
  status=$?
  stop_xvfb
  wait # for the tee processes
  if [ "$status" -ne 0 ] && [ "$attempt" -lt "$attempts" ] && grep -q "bad X server connection" "$log"; then
    echo "with-display: the X display was unusable; running the command again on a new one" >&2
    continue
  fi
  break
done
exit "$status"
