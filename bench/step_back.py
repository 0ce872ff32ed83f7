"""What going back in time costs (issue 57): a trace played to its last frame,
then stepped back frame by frame (Previous Frame) and dragged back to a few
earlier times, with checkpoints (Checkpoint Memory) and without (0: every
step back replays from the start). Side by side in one process: the same
tracer settings, the same times; medians. Also the time of one step, so the
answer's time can be read in steps (K, the checkpoints' spacing, bounds it).

    with-display.sh pvpython bench/step_back.py --plugin BoundParticles.so
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
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

flow, dt = shear_layer(AnalyticFlow, args.resolution)


def timed(tracer, t):
    start = time.perf_counter()
    tracer.UpdatePipeline(t)
    return time.perf_counter() - start


rows = []
for budget in [float(b) for b in args.budgets.split(",")]:
    tracer = strip16_tracer(BoundParticleTracer, flow, dt, args.elements, args.frames,
                            CheckpointMemory=budget)
    times = list(tracer.TimestepValues)
    start = time.perf_counter()
    tracer.UpdatePipeline(times[-1])  # the whole trace, one update
    whole = time.perf_counter() - start
    tracer.UpdatePropertyInformation()
    spacing = tracer.GetPropertyValue("CheckpointSpacing")
    step_ms = 1e3 * whole / (len(times) - 1)
    back = [timed(tracer, times[-1 - k]) for k in range(1, args.back + 1)]
    drags = [timed(tracer, times[i]) for i in (len(times) // 2, len(times) // 4, 7)]
    rows.append((budget, spacing, whole, step_ms, statistics.median(back), max(back),
                 statistics.median(drags)))
    Delete(tracer)
    del tracer

print("Going back over a trace of %d Strip16 elements, %d frames (one step each), "
      "%d^3 shear layer; seconds" % (args.elements, args.frames, args.resolution))
print("| Checkpoint Memory (MiB) | K (steps between) | whole trace | one step (ms) "
      "| Previous Frame, median | Previous Frame, worst | drag back, median "
      "| median / one step |")
print("|---|---|---|---|---|---|---|---|")
for budget, spacing, whole, step_ms, back_med, back_max, drag_med in rows:
    print("| %s | %d | %.2f | %.2f | %.3f | %.3f | %.3f | %.0f |" % (
        "automatic" if budget < 0 else "%g" % budget, spacing, whole, step_ms, back_med,
        back_max, drag_med, 1e3 * back_med / step_ms))
