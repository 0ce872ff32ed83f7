"""Heavy particles as Play meets them (issue 44): the tracer's one-step update
and its engine step with Inertia = None against Maxey-Riley, the default
Output Arrays, side by side in one process: the two tracers are updated in
turn, update by update, so that the machine's noise falls on both alike. CPU engine, 65,536 Strip16 (a million particles)
on the 128^3 shear layer, Euler (the default), the heavy settings of
BoundParticlesInertiaBench (tau 0.05, density ratio 1000, gravity -z).

    with-display.sh pvpython bench/inertia_update.py --plugin BoundParticles.so
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
parser.add_argument("--elements", type=int, default=65536)
parser.add_argument("--rounds", type=int, default=3, help="fresh pairs of tracers")
parser.add_argument("--resolution", type=int, default=128)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

res = args.resolution
flow, dt = shear_layer(AnalyticFlow, res)
UPDATES, LONG, REPEATS, WARMUP = 20, 20, 3, 3
steps = WARMUP + UPDATES + LONG * REPEATS + 2


def tracer(heavy):
    """A fresh tracer, with or without inertia."""
    t = strip16_tracer(BoundParticleTracer, flow, dt, args.elements, steps, Engine="CPU")
    if heavy:
        t.Inertia = "Maxey-Riley"
        t.ResponseTime = 0.05
        t.DensityRatio = 1000.0
        t.Gravity = [0.0, 0.0, -1.0]
    return t


def timed_ms(t, time_value):
    start = time.perf_counter()
    t.UpdatePipeline(time_value)
    return 1e3 * (time.perf_counter() - start)


def alternated(rounds):
    """Per tracer (off, on): the one-step updates' and the steps' milliseconds,
    the two tracers updated in turn, update by update."""
    updates = {False: [], True: []}
    per_step = {False: [], True: []}
    for r in range(rounds):
        pair = {heavy: tracer(heavy) for heavy in (False, True)}
        times = list(pair[False].TimestepValues)
        for heavy in (False, True):
            pair[heavy].UpdatePipeline(times[0])
        for k in range(1, WARMUP + UPDATES + 1):
            for heavy in (False, True):
                ms = timed_ms(pair[heavy], times[k])
                if k > WARMUP:
                    updates[heavy].append(ms)
        for j in range(1, REPEATS + 1):
            for heavy in (False, True):
                ms = timed_ms(pair[heavy], times[WARMUP + UPDATES + j * LONG])
                per_step[heavy].append(ms / LONG)
        for heavy in (False, True):
            Delete(pair[heavy])
    return updates, per_step


updates, per_step = alternated(args.rounds)
print("%d Strip16 elements, %d^3 shear layer, default Output Arrays, CPU engine, "
      "the two tracers updated in turn, %d rounds; medians" % (args.elements, res, args.rounds))
print("%-12s %12s %12s %12s" % ("inertia", "update ms", "step ms", "update/step"))
median = {}
for heavy in (False, True):
    median[heavy] = (statistics.median(updates[heavy]), statistics.median(per_step[heavy]))
    print("%-12s %12.1f %12.1f %12.2f" % ("Maxey-Riley" if heavy else "None", median[heavy][0],
                                          median[heavy][1], median[heavy][0] / median[heavy][1]))
print("inertia on / off: one-step update %.2f, step %.2f (target <= 1.3)" % (
    median[True][0] / median[False][0], median[True][1] / median[False][1]))
