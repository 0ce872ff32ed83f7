"""Pictures of what a new user sees first: the tracer's defaults on every
shared data set and on an Analytic Flow, before and after issue 29.

- before: the old defaults: Random orientation, Solid Color (white), the
  input hidden (ParaView's default for a filter's input);
- after: the defaults now: Along Flow orientation, coloured by Speed (the
  output's active scalars, which the GUI picks on Apply), the input kept as
  context: a 3D field's outline, a 2D field's slice a hundredth of its size
  behind the elements' plane (what the GUI does on Apply; gui.defaults
  checks both).

Each picture is taken a few frames into the offered time line, as a user sees
it after pressing Play, from ParaView's default camera.

    with-display.sh pvpython bench/first_minutes.py --plugin BoundParticles.so \\
        --data ../shared/data --pictures OUT
writes OUT/before/<data set>.png and OUT/after/<data set>.png.
"""
import argparse
import os

import paraview.simple
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--pictures", required=True)
parser.add_argument("--frame", type=int, default=5,
                    help="which offered frame to draw (default 5)")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()

DATA_SETS = ["combustor.vti", "office.vti", "carotid.vti", "nek_eddy.pvd", "gfs_wind10m.pvd",
             "AnalyticFlow"]


def open_data(name):
    if name == "AnalyticFlow":
        return AnalyticFlow()
    return OpenDataFile(os.path.join(args.data, name))


def picture(name, after):
    reader = open_data(name)
    reader.UpdatePipeline()
    tracer = BoundParticleTracer(Input=reader)
    if not after:
        tracer.ReleaseOrientation = "Random"
    times = list(tracer.TimestepValues) or [0.0]
    time = times[min(args.frame, len(times) - 1)]
    view = CreateRenderView()
    view.ViewSize = [640, 480]
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    if after:
        context = Show(reader, view)
        bounds = reader.GetDataInformation().GetBounds()
        spans = [bounds[2 * a + 1] - bounds[2 * a] for a in range(3)]
        if 0.0 in spans:
            # As the GUI's first Apply: behind the plane, seen from +z.
            flat = spans.index(0.0)
            position = [0.0, 0.0, 0.0]
            position[flat] = -0.01 * max(spans)
            # Translation from ParaView 5.13 on, Position before.
            if hasattr(context, "Translation"):
                context.Translation = position
            else:
                context.Position = position
        else:
            context.SetRepresentationType("Outline")
    display = Show(tracer, view)
    if after:
        ColorBy(display, ("POINTS", "Speed"))
        display.RescaleTransferFunctionToDataRange(True, False)
    else:
        ColorBy(display, None)
    view.ResetCamera()
    Render(view)
    folder = os.path.join(args.pictures, "after" if after else "before")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, name.split(".")[0] + ".png")
    SaveScreenshot(path, view)
    Delete(view)
    Delete(tracer)
    Delete(reader)
    print("%-14s %-6s t = %-10.4g -> %s" % (name, "after" if after else "before", time, path))


for name in DATA_SETS:
    for after in (False, True):
        picture(name, after)
