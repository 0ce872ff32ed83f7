# Run twice from the GUI's Python shell by trails.xml. First (Trails just
# ticked and applied, Coloring Axis Z, the default): when the tracer's display
# became Bound Particles, turns it back to Surface and sets Coloring Axis to
# X. Second (a new Trail Length applied since): when the display stayed
# Surface, sets Coloring Axis to Z. trails.xml checks the axis each time.
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties, Render

tracer = FindSource("BoundParticleTracer1")
display = GetDisplayProperties(tracer, GetActiveView())
if tracer.ColoringAxis == "Z":
    if tracer.Trails == 1 and display.Representation == "Bound Particles":
        display.SetRepresentationType("Surface")
        Render()
        tracer.ColoringAxis = "X"
elif tracer.TrailLength == 4 and display.Representation == "Surface":
    tracer.ColoringAxis = "Z"
