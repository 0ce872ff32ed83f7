"""What a user sees in the GUI's view, measured in its pixels: how the
elements stand out on the context behind them, and how their colours spread
over their colour map. Used by the check scripts (check_context.py,
check_first_look.py)."""
import os
import tempfile

import numpy
from paraview.simple import Render, SaveScreenshot
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def pixels(view):
    """The view as rendered now: an (n, 3) array of RGB in [0, 1]."""
    folder = tempfile.mkdtemp(dir=os.environ.get("GUI_RENDER_KEEP"))
    path = os.path.join(folder, "view.png")
    Render(view)
    SaveScreenshot(path, view)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    values = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
    if not os.environ.get("GUI_RENDER_KEEP"):  # a folder to keep the pictures in
        os.remove(path)
        os.rmdir(folder)
    return values.astype(numpy.float64) / 255.0


def saturation(rgb):
    """HSV saturation of each row of `rgb`."""
    top = rgb.max(axis=1)
    return numpy.where(top > 0, (top - rgb.min(axis=1)) / numpy.maximum(top, 1e-12), 0.0)


def standing_out(view, elements):
    """How the elements' pixels differ from the context under them: the
    view drawn with and without the `elements` display; the pixels that
    change are the elements'. Returns a dict: pixels (how many), element
    and context saturation (medians), distance (median RGB distance between
    an element pixel and the context pixel under it)."""
    shown = pixels(view)
    elements.Visibility = 0
    try:
        under = pixels(view)
    finally:
        elements.Visibility = 1
        Render(view)
    mask = numpy.abs(shown - under).max(axis=1) > 0.02
    if not mask.any():
        return {"pixels": 0, "element saturation": 0.0, "context saturation": 0.0,
                "distance": 0.0}
    return {
        "pixels": int(mask.sum()),
        "element saturation": float(numpy.median(saturation(shown[mask]))),
        "context saturation": float(numpy.median(saturation(under[mask]))),
        "distance": float(numpy.median(numpy.linalg.norm(shown[mask] - under[mask], axis=1))),
    }


def stands_out(measured):
    """Whether the elements read apart from their context (a measure of
    standing_out()): many element pixels, the context under them grey, the
    elements clearly more saturated and apart from it in colour."""
    return (measured["pixels"] > 500 and measured["context saturation"] < 0.1 and
            measured["element saturation"] > measured["context saturation"] + 0.2 and
            measured["distance"] > 0.2)


def lowest_bin_share(values, lut, bins=8):
    """The share of `values` that the colour map `lut` maps into its lowest
    of `bins` equal bins (its darkest blue for Cool to Warm), on its linear
    or log scale."""
    points = list(lut.RGBPoints)
    low, high = points[0], points[-4]
    values = numpy.asarray(values, dtype=numpy.float64)
    if values.size == 0 or not high > low:
        return 1.0
    if lut.UseLogScale and low > 0:
        return float((values < low * (high / low) ** (1.0 / bins)).mean())
    return float((values < low + (high - low) / bins).mean())


def unused_legends(view):
    """The titles of the legends (scalar bars) shown in `view` whose colour
    map no visible display there uses."""
    used = set()
    legends = []
    for shown in view.Representations:
        if not shown.Visibility:
            continue
        lut = shown.SMProxy.GetProperty("LookupTable")
        lut = lut.GetProxy(0) if lut is not None and lut.GetNumberOfProxies() > 0 else None
        if shown.SMProxy.GetXMLName() == "ScalarBarWidgetRepresentation":
            legends.append((shown.Title, lut))
        elif lut is not None and shown.SMProxy.GetProperty("ColorArrayName") is not None and \
                shown.ColorArrayName[1]:
            used.add(lut.GetGlobalIDAsString())
    return [title for title, lut in legends
            if lut is None or lut.GetGlobalIDAsString() not in used]
