"""ParaView's own Particle Tracer and the Bound Particle Tracer on the same job,
side by side in one run: the unsteady double gyre, the same seed points, the
same data intervals, RK4 with two sub-steps per interval; one-particle
elements. Prints the wall times, their ratio and how far the final positions
of the two lie apart.

    pvpython bench/vs_paraview.py --plugin BoundParticles.so [--seeds N]
"""
import argparse
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--plugin", required=True)
parser.add_argument("--seeds", type=int, default=20000)
parser.add_argument("--steps", type=int, default=11, help="data time steps to trace through")
parser.add_argument("--repeats", type=int, default=3)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[128, 64, 2], Bounds=[0, 2, 0, 1, 0, 0.02],
                    NumberOfTimeSteps=args.steps)
flow.UpdatePipeline()
times = list(flow.TimestepValues)


def ours():
    tracer = BoundParticleTracer(Input=flow, ElementShape="Point", NumberOfElements=args.seeds,
                                 Integrator="Runge-Kutta 4", StepSizeUnit="Time",
                                 StepSize=(times[1] - times[0]) / 2, LifetimeRange=[1e9, 1e9],
                                 EmitterCenter=[1, 0.5, 0.01], EmitterSize=[1.8, 0.9, 0],
                                 Seed=1)
    return tracer


# The seeds: the Bound Particle Tracer's elements at the start time.
seeding = ours()
seeding.UpdatePipeline(times[0])
seed_data = servermanager.Fetch(seeding)
seed_proxy = TrivialProducer(registrationName="seeds")
seed_proxy.GetClientSideObject().SetOutput(seed_data)


def timed(tracer):
    """Steps the tracer through every data time step; the seconds and the result."""
    start = time.perf_counter()
    for t in times:
        tracer.UpdatePipeline(t)
    took = time.perf_counter() - start
    data = servermanager.Fetch(tracer)
    Delete(tracer)
    return took, data


def run_paraview():
    tracer = ParticleTracer(Input=flow, SeedSource=seed_proxy)
    tracer.SelectInputVectors = ["POINTS", "velocity"]
    tracer.StaticSeeds = 1
    tracer.MeshOverTime = "Static"
    tracer.ComputeVorticity = 0
    tracer.ForceReinjectionEveryNSteps = 0
    return timed(tracer)


def run_ours():
    return timed(ours())


pv_times, our_times = [], []
for _ in range(args.repeats):
    took, pv_data = run_paraview()
    pv_times.append(took)
    took, our_data = run_ours()
    our_times.append(took)

# Same job: compare final positions of the particles both still carry.
ids = vtk_to_numpy(pv_data.GetPointData().GetArray("ParticleId"))
pv_xyz = vtk_to_numpy(pv_data.GetPoints().GetData())
our_xyz = vtk_to_numpy(our_data.GetPoints().GetData())
distance = [float(((pv_xyz[k] - our_xyz[int(i)]) ** 2).sum() ** 0.5) for k, i in enumerate(ids)]
pv_median, our_median = statistics.median(pv_times), statistics.median(our_times)
steps = (len(times) - 1) * 2
print("job: %d seeds, %d data intervals, RK4 with 2 sub-steps each (%d steps)"
      % (args.seeds, len(times) - 1, steps))
print("ParaView Particle Tracer: %.3f s  (%.0f particle-steps/s)"
      % (pv_median, args.seeds * steps / pv_median))
print("Bound Particle Tracer:    %.3f s  (%.0f particle-steps/s)"
      % (our_median, args.seeds * steps / our_median))
print("speed-up: %.1fx (median of %d runs each, interleaved)" % (pv_median / our_median, args.repeats))
print("final positions: %d particles in both, max distance %.2e, median %.2e (domain 2 x 1)"
      % (len(distance), max(distance), statistics.median(distance)))
sys.stdout.flush()
