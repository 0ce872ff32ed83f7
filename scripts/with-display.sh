#!/usr/bin/env bash
# Runs a command with a private Xvfb display of 24-bit colour (ParaView 5.11
# and 5.13 from Debian are GLX-only, so pvpython, pvbatch and the GUI need
# one). Xvfb picks a free display number itself (-displayfd), so parallel runs
# cannot collide, and no temporary X authority is involved, so nothing is left
# to clean up.
#
#   with-display.sh [--unless-egl] COMMAND...
#
# --unless-egl: ParaView 6 and later fall back to EGL when there is no X
# display, so pvpython and pvbatch need no X server there: the command then
# runs as is, with DISPLAY unset. The ParaView is the one whose pvpython is on
# PATH, or BOUNDPARTICLES_PARAVIEW_MAJOR (its major version) when set.
# The GUI always needs X.
#
# -noreset: by default an X server resets itself whenever its last client
# disconnects, and drops any connection that arrives meanwhile (ECONNRESET or
# EAGAIN). VTK then aborts with "bad X server connection". That hit every
# run whose processes come and go: a test starting one pvpython per case, or
# MPI ranks that open and close windows at different moments.
set -u

if [ "${1:-}" = --unless-egl ]; then
  shift
  major="${BOUNDPARTICLES_PARAVIEW_MAJOR:-$(pvpython --version 2>/dev/null \
    | sed -nE 's/.*version ([0-9]+).*/\1/p')}"
  if [ "${major:-0}" -ge 6 ]; then
    unset DISPLAY
    exec "$@"
  fi
fi

ready="$(mktemp)"
Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp -noreset 3>"$ready" >/dev/null 2>&1 &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; rm -f "$ready"' EXIT
for _ in $(seq 200); do
  [ -s "$ready" ] && break
  kill -0 "$xvfb" 2>/dev/null || break
  sleep 0.05
done
display="$(head -n 1 "$ready" 2>/dev/null)"
if [ -z "$display" ]; then
  echo "with-display: Xvfb did not start" >&2
  exit 1
fi
DISPLAY=":$display" "$@"
