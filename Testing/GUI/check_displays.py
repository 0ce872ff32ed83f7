# Run from the GUI's Python shell by displays.xml after each Apply; sets the
# tracer's Coloring Axis to what displays.xml checks next, when the step holds
# (what it found is written to the terminal):
#  X: traced with Vectors 'fast' (1e7 times the velocity), coloured by Speed
#     over a range beyond 1e5;
#  Y: then with 'velocity': the colour map rescaled to its speed (below 10);
#  Z: then with Engine GPU: the display moved to Bound Particles.
import os

from paraview.simple import (FindSource, GetActiveView, GetColorTransferFunction,
                             GetDisplayProperties)

tracer = FindSource("BoundParticleTracer1")
display = GetDisplayProperties(tracer, GetActiveView())
top = GetColorTransferFunction("Speed").RGBPoints[-4]
vectors = tracer.Vectors[1]
found = {"vectors": vectors, "engine": tracer.Engine, "representation": display.Representation,
         "colour": list(display.ColorArrayName), "top of the colour map": top}
os.write(2, ("check_displays: %s\n" % found).encode())  # the terminal, not the shell
coloured = list(display.ColorArrayName) == ["POINTS", "Speed"]
if tracer.Engine == "GPU":
    if display.Representation == "Bound Particles":
        tracer.ColoringAxis = 2
elif vectors == "fast" and coloured and top > 1e5 and display.Representation == "Surface":
    tracer.ColoringAxis = 0
elif vectors == "velocity" and coloured and top < 10:
    tracer.ColoringAxis = 1
