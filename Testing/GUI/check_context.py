# Run from the GUI's Python shell by defaults.xml, twice. First, after a second
# tracer was applied to a 2D Analytic Flow (shown as a slice in the elements'
# plane): when that slice is still shown, moved along Z away from the camera
# by a hundredth of its size, the first flow's outline still shown and the
# second tracer's elements shown, and those elements stand out on the slice
# under them, shown as a Slice and as a Surface (the slice in greys, the
# elements' pixels far more saturated and clearly apart: issue 53 item 9),
# sets the second tracer's Number Of Elements to 998.
# Then, after a third tracer was applied to a tetrahedral mesh shown as a
# surface: when the mesh is shown as its outline (not hidden, not covering
# the elements), sets the third tracer's Number Of Elements to 997.
# defaults.xml checks the count each time; what failed is printed.
import gui_check
import gui_render
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties


def check():
    view = GetActiveView()
    mesh = FindSource("Tetrahedralize1")
    if mesh is None:
        outline = GetDisplayProperties(FindSource("AnalyticFlow1"), view)
        plane = GetDisplayProperties(FindSource("AnalyticFlow2"), view)
        tracer = FindSource("BoundParticleTracer2")
        elements = GetDisplayProperties(tracer, view)
        # The display's offset: Translation from ParaView 5.13 on, Position before.
        behind = list(plane.Translation if hasattr(plane, "Translation") else plane.Position)
        # Only the second flow and its elements in the view while measuring.
        outline.Visibility = 0
        first = GetDisplayProperties(FindSource("BoundParticleTracer1"), view)
        first.Visibility = 0
        kind = plane.SMProxy.GetProperty("Representation").GetElement(0)
        try:
            on_slice = gui_render.standing_out(view, elements)
            plane.Representation = "Surface"
            on_surface = gui_render.standing_out(view, elements)
        finally:
            plane.Representation = kind
            outline.Visibility = 1
            first.Visibility = 1
        gui_check.say("check_context", "on the slice %s; on the surface %s" % (on_slice, on_surface))
        found = {
            "slice kept": plane.Representation == "Slice" and plane.Visibility == 1,
            "slice behind": behind[0] == 0 and behind[1] == 0 and abs(abs(behind[2]) - 0.02) < 1e-9,
            "outline kept": outline.Representation == "Outline" and outline.Visibility == 1,
            "elements shown": elements.Visibility == 1,
            "elements stand out on the Slice": gui_render.stands_out(on_slice),
            "elements stand out on the Surface": gui_render.stands_out(on_surface),
        }
    else:
        tracer = FindSource("BoundParticleTracer3")
        shown = GetDisplayProperties(mesh, view)
        found = {
            "mesh as its outline": shown.Representation == "Outline" and shown.Visibility == 1,
            "elements shown": GetDisplayProperties(tracer, view).Visibility == 1,
        }
    if gui_check.passed("check_context", found):
        # Number Of Elements, as check_defaults.py says why.
        tracer.NumberOfElements = 997 if mesh is not None else 998


gui_check.run("check_context", check)
