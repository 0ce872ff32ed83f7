# Run from the GUI's Python shell by defaults.xml after the tracer was applied
# to an Analytic Flow with its defaults: when the flow's outline is still shown
# and the tracer's display is coloured by Speed, sets the tracer's Coloring
# Axis to X, which defaults.xml then checks.
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties

view = GetActiveView()
flow = GetDisplayProperties(FindSource("AnalyticFlow1"), view)
tracer = FindSource("BoundParticleTracer1")
elements = GetDisplayProperties(tracer, view)
if (
    flow.Visibility == 1
    and flow.Representation == "Outline"
    and list(elements.ColorArrayName) == ["POINTS", "Speed"]
):
    tracer.ColoringAxis = 0
