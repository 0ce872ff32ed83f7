# Run from the GUI's Python shell by play_updates.xml after Play (see
# play_updates_watch.py): when Play ran its frames, the GUI got no data-updated
# event of the tracer nor of its input during Play and one of the tracer's at
# its end, and the Speed colour map spans the last frame's speeds, sets the
# tracer's Coloring Axis to X, which play_updates.xml then checks.
import builtins

from paraview.simple import FindSource, GetColorTransferFunction

watch = builtins._boundparticles_play_updates
tracer = FindSource("BoundParticleTracer1")
low, high = tracer.PointData["Speed"].GetRange()
points = GetColorTransferFunction("Speed").RGBPoints
mapped = (points[0], points[-4])
print("play_updates: %s; Speed [%g, %g], colour map [%g, %g]" % (watch, low, high, *mapped))
if (
    watch["plays"] == 1
    and watch["ticks"] >= 50
    and watch["BoundParticleTracer1 during"] == 0
    and watch["AnalyticFlow1 during"] == 0
    and watch["BoundParticleTracer1 after"] >= 1
    and mapped[0] <= low
    and mapped[1] >= high
):
    tracer.ColoringAxis = 0
