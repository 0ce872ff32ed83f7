# Run from the GUI's Python shell by defaults.xml after a second tracer was
# applied to a 2D Analytic Flow (shown as a slice): when that flow's slice is
# hidden, the first flow's outline still shown and the second tracer's
# elements shown, sets the second tracer's Coloring Axis to X, which
# defaults.xml then checks.
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties

view = GetActiveView()
outline = GetDisplayProperties(FindSource("AnalyticFlow1"), view)
plane = GetDisplayProperties(FindSource("AnalyticFlow2"), view)
tracer = FindSource("BoundParticleTracer2")
elements = GetDisplayProperties(tracer, view)
if (
    plane.Representation == "Slice"
    and plane.Visibility == 0
    and outline.Representation == "Outline"
    and outline.Visibility == 1
    and elements.Visibility == 1
):
    tracer.ColoringAxis = 0
