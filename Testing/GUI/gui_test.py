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
    if points == 50 * 12 and times == 101:
        return "traced %d points, %d time values" % (points, times)
    return "wrong result: %d points, %d time values" % (points, times)


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
