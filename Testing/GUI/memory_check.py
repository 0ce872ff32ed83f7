# Run from the GUI's Python shell by memory.xml after Edit > Reset Session: a new
# tracer whose Coloring Axis becomes X (which memory.xml checks) when the
# memory of the deleted traces went back to the system. The process holds a
# deleted trace's display until the view next updates, so a reading may hold
# the last cycle's; but over the 20 cycles (memory_cycle.py's readings) what
# is held must not grow (the last ten readings within 50 MiB of the first
# five), and after Reset Session the process holds at most 60 MiB more than
# before the first trace. Written to the terminal.
import os

import gui_check
from paraview.simple import AnalyticFlow, BoundParticleTracer, SetActiveSource

with open(os.path.join(os.environ["HOME"], "memory.txt")) as saved:
    readings = [float(x) for x in saved.read().split()]
after_reset = gui_check.resident_mib()
complete = len(readings) == 21
growth = max(readings[11:]) - max(readings[1:6]) if complete else float("inf")
kept = after_reset - readings[0]
seen = {"readings": len(readings), "before, MiB": "%.0f" % readings[0],
        "cycles 1-5 up to": "%.0f" % max(readings[1:6] or [0]),
        "cycles 10-19 up to": "%.0f" % max(readings[11:] or [0]),
        "after Reset Session": "%.0f" % after_reset}
found = {"21 readings": complete, "grew under 50 MiB (%.0f)" % growth: growth < 50.0,
         "kept under 60 MiB after Reset Session (%.0f)" % kept: kept < 60.0}
tracer = BoundParticleTracer(Input=AnalyticFlow())
SetActiveSource(tracer)
if gui_check.passed("memory_check", found, seen):
    tracer.ColoringAxis = 0
