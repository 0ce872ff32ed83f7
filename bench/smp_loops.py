"""The tracer's parallel loops on the plugin's own thread pool against VTK's
vtkSMPTools, side by side in one process, on whatever ParaView runs this.

The tracer picks one (Filters/TracerSteppers.h: VTK's loops from VTK 9.3 on,
its pool on VTK 9.2); BOUNDPARTICLES_SMP_LOOPS=pool or =vtk overrides that,
and this bench switches between the two in turn, so the machine's noise falls
on both alike. For each element count: the one-step update (median of 30) and
the engine's step (a 20-step update / 20, median of 5), CPU engine, Strip16,
the 128^3 shear layer, the output arrays cut to Normals and Force, nothing
drawn.

    with-display.sh pvpython bench/smp_loops.py --plugin BoundParticles.so
"""
import argparse
import os
import statistics
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tracer_costs import shear_layer, strip16_tracer, update_and_step_ms  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--counts", default="4096,65536")
parser.add_argument("--rounds", type=int, default=3, help="alternations of pool and vtk")
parser.add_argument("--resolution", type=int, default=128)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

res = args.resolution
flow, dt = shear_layer(AnalyticFlow, res)
UPDATES, LONG, REPEATS, WARMUP = 30, 20, 5, 3
steps = WARMUP + UPDATES + LONG * REPEATS + 2


def costs(count):
    tracer = strip16_tracer(BoundParticleTracer, flow, dt, count, steps, Engine="CPU",
                            OutputArrays=["Normals", "Force"])
    result = update_and_step_ms(tracer, WARMUP, UPDATES, LONG, REPEATS)
    Delete(tracer)
    return result


pm = servermanager.vtkSMProxyManager.GetProxyManager()
version = "%d.%d.%d" % (pm.GetVersionMajor(), pm.GetVersionMinor(), pm.GetVersionPatch())
from vtkmodules.vtkCommonCore import vtkSMPTools, vtkVersion  # noqa: E402

print("ParaView %s, VTK %s, SMP backend %s (%d threads), %d cores" % (
    version, vtkVersion.GetVTKVersion(), vtkSMPTools.GetBackend(),
    vtkSMPTools.GetEstimatedNumberOfThreads(), os.cpu_count()))
print("%9s %-5s %12s %12s %12s" % ("elements", "loops", "update ms", "step ms", "update/step"))
for count in [int(c) for c in args.counts.split(",")]:
    results = {"pool": [], "vtk": []}
    for _ in range(args.rounds):
        for loops in ("pool", "vtk"):
            os.environ["BOUNDPARTICLES_SMP_LOOPS"] = loops
            time.sleep(1.1)  # the tracer looks at its loop settings at most once a second
            results[loops].append(costs(count))
    for loops, runs in results.items():
        update = statistics.median(u for u, _ in runs)
        step = statistics.median(s for _, s in runs)
        print("%9d %-5s %12.2f %12.2f %12.2f" % (count, loops, update, step, update / step))
os.environ.pop("BOUNDPARTICLES_SMP_LOOPS", None)
