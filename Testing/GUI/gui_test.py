"""Run by the ParaView GUI at start-up (paraview --script): the plugin, loaded
through PV_PLUGIN_PATH, traces in the GUI application. The script reports
through a marker file and then ends the application itself (Debian's build
does not play Python --test-script files)."""
import os
import traceback

from paraview.simple import *  # noqa: F401,F403


def trace():
    flow = AnalyticFlow(Flow="Shear Layer", Resolution=[16, 16, 16])
    flow.UpdatePipeline()
    tracer = BoundParticleTracer(Input=flow, ElementShape="Cross", NumberOfElements=50)
    display = Show(tracer)
    ColorBy(display, ("POINTS", "Force"))
    # Setting the animation scene's time from a start-up script never returns
    # in the 5.11 GUI (with any time source), so drive the view's time instead.
    tracer.UpdatePipeline(1.0)
    GetActiveViewOrCreate("RenderView").ViewTime = 1.0
    Render()
    points = tracer.GetDataInformation().GetNumberOfPoints()
    times = len(tracer.TimestepValues)
    if points != 50 * 12 or times != 101:
        return "wrong result: %d points, %d time values" % (points, times)
    # The GPU engine in the GUI's own render window (a Qt OpenGL widget).
    if "Bound Particles" not in display.Representation.Available:
        return "no Bound Particles representation: %s" % list(display.Representation.Available)
    tracer.Engine = "GPU"
    display.SetRepresentationType("Bound Particles")
    view = GetActiveViewOrCreate("RenderView")
    view.ViewTime = 2.0
    Render()
    image = os.environ["BOUNDPARTICLES_GUI_MARKER"] + ".png"
    SaveScreenshot(image, view, ImageResolution=[300, 300])
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(image)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    drawn = (abs(pixels - pixels[0]).max(axis=1) > 8).mean()
    if drawn < 0.001:
        return "the GPU engine drew nothing in the GUI (%.4f of the pixels)" % drawn
    return "traced %d points, %d time values; GPU display covers %.3f of the view" % (
        points, times, drawn)


marker = os.environ["BOUNDPARTICLES_GUI_MARKER"]
try:
    result = trace()
except Exception:
    result = "failed:\n" + traceback.format_exc()
# The runner passes only on a marker that starts with "traced".
with open(marker, "w") as out:
    out.write(result + "\n")
# Leave at once: the GUI would otherwise wait for a user.
os._exit(0)
