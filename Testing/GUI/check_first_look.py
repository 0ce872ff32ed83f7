# Run from the GUI's Python shell by first_look.xml, twice, after a tracer
# was applied with its defaults to a shared data set opened and applied in
# the GUI (issue 53 items 9 and 12).
# First on office.vti, whose speeds a few fast points stretch: no more than a
# quarter of the elements' points in the lowest eighth of the colour map
# (its darkest blue). Sets the tracer's Number Of Elements to 995, then
# hides office and its elements.
# Then on gfs_wind10m, a 2D map that ParaView shows as a slice coloured by
# velocity magnitude: the elements, coloured by Speed, must stand out on the
# map kept behind them, shown as a Slice and as a Surface: the map under the
# elements in greys (its own colour map), the elements' pixels far more
# saturated than the map under them and clearly apart from it, and no
# legend left of the colour map the map no longer uses. Sets the
# second tracer's Number Of Elements to 996.
# first_look.xml checks each count; what was measured is printed.
import gui_check
import gui_render
import numpy
from paraview import servermanager
from paraview.simple import (FindSource, GetActiveView, GetColorTransferFunction,
                             GetDisplayProperties, GetSources, Hide)
from vtkmodules.util.numpy_support import vtk_to_numpy

SCRIPT = "check_first_look"


def check_map():
    view = GetActiveView()
    tracer = FindSource("BoundParticleTracer2")
    wind = tracer.Input
    context = GetDisplayProperties(wind, view)
    elements = GetDisplayProperties(tracer, view)
    kind = context.SMProxy.GetProperty("Representation").GetElement(0)
    on_slice = gui_render.standing_out(view, elements)
    context.Representation = "Surface"
    try:
        on_surface = gui_render.standing_out(view, elements)
    finally:
        context.Representation = kind
    found = {
        "map kept": context.Visibility == 1 and kind == "Slice",
        "elements stand out on the Slice": gui_render.stands_out(on_slice),
        "elements stand out on the Surface": gui_render.stands_out(on_surface),
        "no legend of an unused colour map": not gui_render.unused_legends(view),
    }
    seen = {"on the slice": on_slice, "on the surface": on_surface,
            "map": "%s, coloured by %s" % (kind, list(context.ColorArrayName)),
            "unused legends": gui_render.unused_legends(view)}
    if gui_check.passed(SCRIPT, found, seen):
        tracer.NumberOfElements = 996


def check_office():
    tracer = FindSource("BoundParticleTracer1")
    elements = GetDisplayProperties(tracer, GetActiveView())
    output = servermanager.Fetch(tracer)
    speed = output.GetPointData().GetArray("Speed")
    values = vtk_to_numpy(speed) if speed is not None else numpy.zeros(0)
    lut = GetColorTransferFunction("Speed")
    share = gui_render.lowest_bin_share(values, lut)
    found = {
        "coloured by Speed": list(elements.ColorArrayName) == ["POINTS", "Speed"],
        "a quarter at most in the lowest eighth": share <= 0.25,
    }
    seen = {"lowest eighth": "%.3f" % share,
            "colour range": "%g to %g" % (lut.RGBPoints[0], lut.RGBPoints[-4]),
            "speeds": "%g to %g" % (values.min(), values.max()) if values.size else "none"}
    if gui_check.passed(SCRIPT, found, seen):
        tracer.NumberOfElements = 995
    # gfs_wind10m comes next, in a view of its own.
    for source in GetSources().values():
        Hide(source)


# The second tracer is gfs_wind10m's.
gui_check.run(SCRIPT, check_map if FindSource("BoundParticleTracer2") is not None else check_office)
