# Run from the GUI's Python shell by play_updates.xml after Play (see
# play_updates_watch.py): when Play ran its frames, the GUI got no data-updated
# event of the tracer nor of its input during Play and one of the tracer's at
# its end, and the Speed colour map spans the last frame's speeds, sets the
# tracer's Coloring Axis to X, which play_updates.xml then checks.
import builtins

import gui_check
from paraview.simple import FindSource, GetColorTransferFunction

watch = builtins._boundparticles_play_updates
tracer = FindSource("BoundParticleTracer1")
low, high = tracer.PointData["Speed"].GetRange()
points = GetColorTransferFunction("Speed").RGBPoints
mapped = (points[0], points[-4])
found = {
    "played once": watch["plays"] == 1,
    "50 ticks or more": watch["ticks"] >= 50,
    "no tracer update reached the GUI during Play": watch["BoundParticleTracer1 during"] == 0,
    "no flow update reached the GUI during Play": watch["AnalyticFlow1 during"] == 0,
    "the tracer's update reached it after": watch["BoundParticleTracer1 after"] >= 1,
    "the colour map covers Speed": mapped[0] <= low and mapped[1] >= high,
}
seen = {"watch": watch, "Speed": "[%g, %g]" % (low, high), "colour map": "[%g, %g]" % mapped}
if gui_check.passed("play_updates", found, seen):
    tracer.ColoringAxis = 0
