"""What going back in time costs (issue 57): a trace played to its last frame,
then stepped back frame by frame (Previous Frame) and dragged back to a few
earlier times, with checkpoints (Checkpoint Memory) and without (0: every
step back replays from the start). Side by side in one process: the same
tracer settings, the same times; medians. Also the time of one step, so the
answer's time can be read in steps (K, the checkpoints' spacing, bounds it).

    with-display.sh pvpython bench/step_back.py --plugin BoundParticles.so

With --pvd FILE (a real data set, e.g. ../shared/data/gfs_wind10m.pvd) the
tracer takes its defaults on that data instead (--frames-per-step 33 makes
gfs_wind10m's 9 time steps 265 frames), and a step back's points are
compared with a fresh tracer's at the same time (CPU engine: "same bits" or
the largest difference).
"""
import argparse
import os
import statistics
import sys
import time

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tracer_costs import shear_layer, strip16_tracer  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--elements", type=int, default=4000)
parser.add_argument("--frames", type=int, default=201)
parser.add_argument("--resolution", type=int, default=64)
parser.add_argument("--back", type=int, default=10, help="Previous Frame presses timed")
parser.add_argument("--budgets", default="0,-1,4,256",
                    help="Checkpoint Memory values, MiB (-1: automatic, half the trace's size)")
parser.add_argument("--pvd", help="a data set's .pvd: the tracer's defaults on it")
parser.add_argument("--engine", default="CPU", help="CPU or GPU (with --pvd)")
parser.add_argument("--frames-per-step", type=int, default=0,
                    help="with --pvd: Frames Per Input Step (0: the default, automatic)")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

if args.pvd:
    flow = PVDReader(FileName=args.pvd)
    # Data in hand, as in the GUI after Apply: every tracer's Vectors default
    # then weighs the arrays' units alike (user guide, Input).
    flow.UpdatePipeline()
else:
    flow, dt = shear_layer(AnalyticFlow, args.resolution)


def make_tracer(budget):
    if args.pvd:
        SetActiveSource(flow)  # the Vectors default is the active source's (user guide)
        return BoundParticleTracer(Input=flow, Engine=args.engine, CheckpointMemory=budget,
                                   FramesPerInputStep=args.frames_per_step)
    return strip16_tracer(BoundParticleTracer, flow, dt, args.elements, args.frames,
                          CheckpointMemory=budget)


def points(tracer):
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    data = servermanager.Fetch(tracer)
    return vtk_to_numpy(data.GetPoints().GetData()) if data.GetPoints() else None


def against_fresh(tracer, t):
    """'same bits', or the largest difference from a fresh tracer's points at t."""
    fresh = make_tracer(0)
    fresh.UpdatePipeline(t)
    a, b = points(tracer), points(fresh)
    Delete(fresh)
    if a is None or b is None or a.shape != b.shape:
        return "differ in count"
    if a.tobytes() == b.tobytes():
        return "same bits"
    return "max |dx| %.3g" % abs(a - b).max()


def timed(tracer, t):
    start = time.perf_counter()
    tracer.UpdatePipeline(t)
    return time.perf_counter() - start


rows = []
for budget in [float(b) for b in args.budgets.split(",")]:
    tracer = make_tracer(budget)
    times = list(tracer.TimestepValues)
    start = time.perf_counter()
    tracer.UpdatePipeline(times[-1])  # the whole trace, one update
    whole = time.perf_counter() - start
    tracer.UpdatePropertyInformation()
    spacing = tracer.GetPropertyValue("CheckpointSpacing")
    step_ms = 1e3 * whole / (len(times) - 1)
    back = [timed(tracer, times[-1 - k]) for k in range(1, args.back + 1)]
    drags = [timed(tracer, times[i]) for i in (len(times) // 2, len(times) // 4, 7)]
    verdict = against_fresh(tracer, times[7]) if args.pvd and args.engine == "CPU" else "-"
    rows.append((budget, spacing, whole, step_ms, statistics.median(back), max(back),
                 statistics.median(drags), verdict, len(times)))
    Delete(tracer)
    del tracer

if args.pvd:
    print("Going back over the tracer's defaults on %s, %d frames, %s engine; seconds" % (
        os.path.basename(args.pvd), rows[0][8], args.engine))
else:
    print("Going back over a trace of %d Strip16 elements, %d frames (one step each), "
          "%d^3 shear layer; seconds" % (args.elements, args.frames, args.resolution))
print("| Checkpoint Memory (MiB) | K (steps between) | whole trace | one frame (ms) "
      "| Previous Frame, median | Previous Frame, worst | drag back, median "
      "| median / one frame | frame 7 against a fresh run |")
print("|---|---|---|---|---|---|---|---|---|")
for budget, spacing, whole, step_ms, back_med, back_max, drag_med, verdict, _ in rows:
    print("| %s | %d | %.2f | %.2f | %.3f | %.3f | %.3f | %.0f | %s |" % (
        "automatic" if budget < 0 else "%g" % budget, spacing, whole, step_ms, back_med,
        back_max, drag_med, 1e3 * back_med / step_ms, verdict))
