# Run twice from the GUI's Python shell by trails.xml. First (Trails just
# ticked and applied, Coloring Axis Z, the default): when the tracer's display
# became Bound Particles, turns it back to Surface and sets Coloring Axis to
# X. Second (a new Trail Length applied since): when the display stayed
# Surface, sets Coloring Axis to Z. trails.xml checks the axis each time.
import gui_check
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties, Render

tracer = FindSource("BoundParticleTracer1")
display = GetDisplayProperties(tracer, GetActiveView())
seen = {"representation": display.Representation}
if tracer.ColoringAxis == "Z":
    found = {"Trails on": tracer.Trails == 1,
             "moved to Bound Particles": display.Representation == "Bound Particles"}
    if gui_check.passed("check_trails (first)", found, seen):
        display.SetRepresentationType("Surface")
        Render()
        tracer.ColoringAxis = "X"
else:
    found = {"Trail Length 4": tracer.TrailLength == 4,
             "Surface kept": display.Representation == "Surface"}
    if gui_check.passed("check_trails (second)", found, seen):
        tracer.ColoringAxis = "Z"
