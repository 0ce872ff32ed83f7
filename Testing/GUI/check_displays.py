# Run from the GUI's Python shell by displays.xml after each Apply; sets the
# tracer's Coloring Axis to what displays.xml checks next, when the step holds
# (what it found is written to the terminal):
#  X: traced with Vectors 'fast' (1e7 times the velocity), coloured by Speed
#     over a range beyond 1e5;
#  Y: then with 'velocity': the colour map rescaled to its speed (below 10);
#  Z: then with Engine GPU: the display moved to Bound Particles.
import gui_check
from paraview.simple import (FindSource, GetActiveView, GetColorTransferFunction,
                             GetDisplayProperties)

tracer = FindSource("BoundParticleTracer1")
display = GetDisplayProperties(tracer, GetActiveView())
top = GetColorTransferFunction("Speed").RGBPoints[-4]
vectors = tracer.Vectors[1]
seen = {"vectors": vectors, "engine": tracer.Engine, "representation": display.Representation,
        "colour": list(display.ColorArrayName), "top of the colour map": top}
coloured = list(display.ColorArrayName) == ["POINTS", "Speed"]
if tracer.Engine == "GPU":
    found = {"GPU engine in Bound Particles": display.Representation == "Bound Particles"}
    axis = 2
elif vectors == "fast":
    found = {"coloured by Speed": coloured, "colour map rescaled up": top > 1e5,
             "Surface kept": display.Representation == "Surface"}
    axis = 0
else:
    found = {"vectors velocity": vectors == "velocity", "coloured by Speed": coloured,
             "colour map rescaled down": top < 10}
    axis = 1
if gui_check.passed("check_displays", found, seen):
    tracer.ColoringAxis = axis
