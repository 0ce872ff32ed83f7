# Run from the GUI's Python shell by defaults.xml, twice. First, after a second
# tracer was applied to a 2D Analytic Flow (shown as a slice in the elements'
# plane): when that slice is still shown, moved along Z away from the camera
# by a hundredth of its size, the first flow's outline still shown and the
# second tracer's elements shown, sets the second tracer's Coloring Axis to X.
# Then, after a third tracer was applied to a tetrahedral mesh shown as a
# surface: when the mesh is shown as its outline (not hidden, not covering
# the elements), sets the third tracer's Coloring Axis to X. defaults.xml
# checks the axis each time; what failed is printed.
import os

from paraview.simple import FindSource, GetActiveView, GetDisplayProperties

view = GetActiveView()
mesh = FindSource("Tetrahedralize1")
if mesh is None:
    outline = GetDisplayProperties(FindSource("AnalyticFlow1"), view)
    plane = GetDisplayProperties(FindSource("AnalyticFlow2"), view)
    tracer = FindSource("BoundParticleTracer2")
    elements = GetDisplayProperties(tracer, view)
    behind = list(plane.Position)
    found = {
        "slice kept": plane.Representation == "Slice" and plane.Visibility == 1,
        "slice behind": behind[0] == 0 and behind[1] == 0 and abs(abs(behind[2]) - 0.02) < 1e-9,
        "outline kept": outline.Representation == "Outline" and outline.Visibility == 1,
        "elements shown": elements.Visibility == 1,
    }
else:
    tracer = FindSource("BoundParticleTracer3")
    shown = GetDisplayProperties(mesh, view)
    found = {
        "mesh as its outline": shown.Representation == "Outline" and shown.Visibility == 1,
        "elements shown": GetDisplayProperties(tracer, view).Visibility == 1,
    }
os.write(2, ("check_context: %s\n" % found).encode())  # the terminal, not the shell
if all(found.values()):
    tracer.ColoringAxis = 0
