"""ParaView's own Particle Tracer and the Bound Particle Tracer on the same job,
side by side in one run: the unsteady double gyre, the same seed points, the
same data intervals, RK4 with two sub-steps per interval; one-particle
elements; both with their fastest settings (no vorticity output). The job
runs two ways: frame by frame (an update per data time step, as Play does)
and in one update to the last time (as a pvbatch script does). Prints the
wall times, their ratio and how far the final positions of the two lie
apart. Then ParaView's Stream Tracer against the Bound Particle Tracer on the
steady field: integration points per second.

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
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                 ElementShape="Point", NumberOfElements=args.seeds,
                                 Integrator="Runge-Kutta 4", StepSizeUnit="Time",
                                 StepSize=(times[1] - times[0]) / 2, LifetimeRange=[1e9, 1e9],
                                 EmitterCenter=[1, 0.5, 0.01], EmitterSize=[1.8, 0.9, 0],
                                 Seed=1, ComputeVorticity=0)
    return tracer


# The seeds: the Bound Particle Tracer's elements at the start time.
seeding = ours()
seeding.UpdatePipeline(times[0])
seed_data = servermanager.Fetch(seeding)
seed_proxy = TrivialProducer(registrationName="seeds")
seed_proxy.GetClientSideObject().SetOutput(seed_data)


def timed(tracer, frames):
    """Steps the tracer through every data time step, or to the last one in
    one update; the seconds and the result."""
    start = time.perf_counter()
    for t in (times if frames else times[-1:]):
        tracer.UpdatePipeline(t)
    took = time.perf_counter() - start
    data = servermanager.Fetch(tracer)
    Delete(tracer)
    return took, data


def run_paraview(frames):
    tracer = ParticleTracer(Input=flow, SeedSource=seed_proxy)
    tracer.SelectInputVectors = ["POINTS", "velocity"]
    tracer.StaticSeeds = 1
    tracer.MeshOverTime = "Static"
    tracer.ComputeVorticity = 0
    tracer.ForceReinjectionEveryNSteps = 0
    return timed(tracer, frames)


def run_ours(frames):
    return timed(ours(), frames)



def report(frames, pv_times, our_times, pv_data, our_data):
    # Same job: compare final positions of the particles both still carry.
    ids = vtk_to_numpy(pv_data.GetPointData().GetArray("ParticleId"))
    pv_xyz = vtk_to_numpy(pv_data.GetPoints().GetData())
    our_xyz = vtk_to_numpy(our_data.GetPoints().GetData())
    distance = [float(((pv_xyz[k] - our_xyz[int(i)]) ** 2).sum() ** 0.5)
                for k, i in enumerate(ids)]
    pv_median, our_median = statistics.median(pv_times), statistics.median(our_times)
    print("%s:" % ("frame by frame, %d updates" % len(times) if frames
                   else "one update to the last time"))
    print("  ParaView Particle Tracer: %.3f s  (%.0f particle-steps/s)"
          % (pv_median, args.seeds * steps / pv_median))
    print("  Bound Particle Tracer:    %.3f s  (%.0f particle-steps/s)"
          % (our_median, args.seeds * steps / our_median))
    print("  speed-up: %.1fx (median of %d runs each, interleaved)"
          % (pv_median / our_median, args.repeats))
    print("  final positions: %d particles in both, max distance %.2e, median %.2e (domain 2 x 1)"
          % (len(distance), max(distance), statistics.median(distance)))
    sys.stdout.flush()


steps = (len(times) - 1) * 2
print("job: %d seeds, %d data intervals, RK4 with 2 sub-steps each (%d steps)"
      % (args.seeds, len(times) - 1, steps))
for frames in (True, False):
    pv_times, our_times = [], []
    for _ in range(args.repeats):
        took, pv_data = run_paraview(frames)
        pv_times.append(took)
        took, our_data = run_ours(frames)
        our_times.append(took)
    report(frames, pv_times, our_times, pv_data, our_data)

# The Stream Tracer: integration points per second on a steady field (the ABC
# flow over the same box, 3 cells deep), the same seeds, RK4 with a fixed step
# of half a cell and at most 40 steps; against the Bound Particle Tracer's
# particle-steps per second on that field, 40 RK4 steps of a fixed time step.
steady = AnalyticFlow(Flow="ABC", Resolution=[128, 64, 4], Bounds=[0, 2, 0, 1, 0, 0.05])
steady.UpdatePipeline()
stream_rates, our_rates = [], []
for _ in range(args.repeats):
    streams = StreamTracerWithCustomSource(Input=steady, SeedSource=seed_proxy)
    streams.Vectors = ["POINTS", "velocity"]
    streams.IntegratorType = "Runge-Kutta 4"
    streams.IntegrationStepUnit = "Cell Length"
    streams.InitialStepLength = 0.5
    streams.MaximumSteps = 40
    streams.MaximumStreamlineLength = 100.0
    streams.IntegrationDirection = "FORWARD"
    streams.ComputeVorticity = 0
    start = time.perf_counter()
    streams.UpdatePipeline()
    took = time.perf_counter() - start
    stream_rates.append(streams.GetDataInformation().GetNumberOfPoints() / took)
    Delete(streams)
    tracer = BoundParticleTracer(Input=steady, Vectors=["POINTS", "velocity"],
                                 ElementShape="Point", NumberOfElements=args.seeds,
                                 Integrator="Runge-Kutta 4", StepSizeUnit="Time", StepSize=0.001,
                                 Duration=0.04, NumberOfTimeSteps=2, LifetimeRange=[1e9, 1e9],
                                 EmitterCenter=[1, 0.5, 0.01], EmitterSize=[1.8, 0.9, 0], Seed=1,
                                 ComputeVorticity=0)
    tracer.UpdatePipeline(0.0)
    start = time.perf_counter()
    tracer.UpdatePipeline(0.04)
    took = time.perf_counter() - start
    our_rates.append(args.seeds * 40 / took)
    Delete(tracer)
stream, our = statistics.median(stream_rates), statistics.median(our_rates)
print("steady ABC flow, RK4, %d seeds, 40 steps each:" % args.seeds)
print("  ParaView Stream Tracer: %.0f integration points/s" % stream)
print("  Bound Particle Tracer:  %.0f particle-steps/s" % our)
print("  ratio: %.1fx (median of %d runs each, interleaved)" % (our / stream, args.repeats))
sys.stdout.flush()
