"""What a ParaView frame of Play costs, and where it goes.

For each element count, engine and display, one process, side by side:
- frame:  advance the view time by one step and Render (what Play does);
- update: the tracer's update to the next step with nothing shown (median
          of at least 30);
- step:   the engine's share of an update (a 20-step update / 20; median
          of 5);
- draw:   Render again with only the camera moved (no step, no new data).
The targets (issue 16): with the CPU engine, frame <= 1.3 x (update + draw)
and update <= 1.5 x step; with the GPU engine no CPU step per frame, so the
frame costs the GPU passes plus the draw. The CPU rows run twice: with every
output array (the default) and with Output Arrays cut to what is drawn
(Normals for the shading, Force for the colour). Medians over the frames after a
warm-up; the 128^3 shear layer, Strip16, one step per frame, coloured by
Force, 1024x768.

    with-display.sh pvpython bench/play_frames.py --plugin BoundParticles.so
"""
import argparse
import os
import statistics
import sys
import time

import paraview.simple
from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tracer_costs import shear_layer, strip16_tracer, update_and_step_ms  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--counts", default="4096,65536")
parser.add_argument("--frames", type=int, default=12)
parser.add_argument("--resolution", type=int, default=128)
parser.add_argument("--csv", help="also write the table here")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()

res = args.resolution
flow, dt = shear_layer(AnalyticFlow, res)
frames = args.frames
warmup = 3
UPDATES = max(frames, 30)  # one-step updates timed (cheap, and the noisiest figure)
LONG = 20  # steps in the update that measures the engine's step
REPEATS = 5  # such updates, the median taken
steps = warmup + max(UPDATES, frames) + LONG * REPEATS + 2


def median_ms(values):
    return 1e3 * statistics.median(values)


ALL = None
DRAWN = ["Normals", "Force"]


def new_tracer(count, engine, arrays=ALL):
    tracer = strip16_tracer(BoundParticleTracer, flow, dt, count, steps, Engine=engine)
    if arrays is not None:
        tracer.OutputArrays = arrays
    return tracer


def new_view():
    view = CreateRenderView(ViewSize=[1024, 768])
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [2.5, 2.0, 4.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    return view


def engine_costs(count, arrays=ALL):
    """update and step of the CPU engine, nothing shown."""
    tracer = new_tracer(count, "CPU", arrays)
    costs = update_and_step_ms(tracer, warmup, UPDATES, LONG, REPEATS)
    Delete(tracer)
    return costs


def display_costs(count, engine, representation, arrays=ALL):
    """frame and draw of one engine and display."""
    tracer = new_tracer(count, engine, arrays)
    view = new_view()
    shown = Show(tracer, view)
    shown.SetRepresentationType(representation)
    ColorBy(shown, ("POINTS", "Force"))
    times = list(tracer.TimestepValues)
    played = []
    for k in range(warmup + frames):
        view.ViewTime = times[k + 1]
        start = time.perf_counter()
        Render(view)
        played.append(time.perf_counter() - start)
    drawn = []
    camera = view.GetActiveCamera()
    for k in range(warmup + frames):
        camera.Azimuth(1.0)
        start = time.perf_counter()
        Render(view)
        drawn.append(time.perf_counter() - start)
    Delete(shown)
    Delete(view)
    Delete(tracer)
    return median_ms(played[warmup:]), median_ms(drawn[warmup:])


rows = []
print("Play in ParaView: %d^3 shear layer, Strip16, one step per frame, coloured by Force, "
      "1024x768; medians of %d frames, ms" % (res, frames))
header = ("elements", "engine", "display", "arrays", "frame", "update", "step", "draw",
          "frame/(update+draw)", "update/step")
print("%9s %-6s %-15s %-6s %8s %8s %8s %8s %20s %12s" % header)
for count in [int(c) for c in args.counts.split(",")]:
    costs = {label: engine_costs(count, arrays) for label, arrays in (("all", ALL), ("drawn", DRAWN))}
    for engine, representation, label, arrays in (
            ("CPU", "Surface", "all", ALL), ("CPU", "Surface", "drawn", DRAWN),
            ("CPU", "Bound Particles", "all", ALL), ("CPU", "Bound Particles", "drawn", DRAWN),
            ("GPU", "Bound Particles", "all", ALL)):
        update, step = costs[label]
        frame, draw = display_costs(count, engine, representation, arrays)
        # The GPU engine steps in the draw of a new time, not in an update.
        own_update = update if engine == "CPU" else 0.0
        ratio = frame / (own_update + draw)
        row = (count, engine, representation, label, frame, own_update, step, draw, ratio,
               update / step if engine == "CPU" else float("nan"))
        rows.append(row)
        print("%9d %-6s %-15s %-6s %8.1f %8.1f %8.1f %8.1f %20.2f %12.2f" % row, flush=True)

if args.csv:
    with open(args.csv, "w") as out:
        out.write(",".join(h.replace("/", "_per_") for h in header) + "\n")
        for row in rows:
            out.write(",".join(str(v) for v in row) + "\n")
