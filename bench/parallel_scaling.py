"""Steps per second of one trace under pvbatch with 1, 2 and 4 MPI ranks.

Driver: /usr/bin/python3 parallel_scaling.py --plugin P [--runs 1x1 1x2 2x1 4x1].
Each run RxT is R ranks of T SMP threads: the driver runs itself under
`mpiexec -n R pvbatch ... --worker` and prints a table. The worker traces Strip16 elements on a
128^3 steady ABC flow (Euler, one averaged-Jacobi iteration), updates once to
warm up (the field is made and split, elements placed), then times updates of
a fixed number of steps; the median of the repeats is reported.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--runs", nargs="+", default=["1x1", "1x2", "2x1", "4x1"],
                    help="RANKSxTHREADS each")
parser.add_argument("--elements", type=int, default=16384)
parser.add_argument("--resolution", type=int, default=128)
parser.add_argument("--steps", type=int, default=20, help="steps per timed update")
parser.add_argument("--repeats", type=int, default=5)
parser.add_argument("--mpiexec", default="mpiexec")
parser.add_argument("--pvbatch", default="pvbatch")
parser.add_argument("--worker", action="store_true")
args = parser.parse_args()

if args.worker:
    from paraview.simple import *  # noqa: F401,F403

    LoadPlugin(args.plugin, ns=globals())
    r = args.resolution
    flow = AnalyticFlow(Flow="ABC", Resolution=[r, r, r], Bounds=[0, 1, 0, 1, 0, 1])
    # Step Size in time units and a long duration, so an update of k output
    # steps takes exactly k simulation steps.
    dt = 0.002
    tracer = BoundParticleTracer(
        Input=flow, Vectors=["POINTS", "velocity"], ElementShape="Strip16",
        NumberOfElements=args.elements, Seed=1,
        StepSizeUnit="Time", StepSize=dt, Duration=dt * 10000, NumberOfTimeSteps=10001,
        LifetimeRange=[50.0, 100.0])
    t = 0.0
    tracer.UpdatePipeline(t)  # warm-up: field, split, placement
    times = []
    for _ in range(args.repeats):
        t += args.steps * dt
        start = time.perf_counter()
        tracer.UpdatePipeline(t)
        times.append(time.perf_counter() - start)
        # This rank's output says how far it got: a failed trace must not pass for a fast one.
        reached = tracer.GetClientSideObject().GetOutputDataObject(0).GetFieldData() \
            .GetArray("SimulationTime")
        if reached is None or abs(reached.GetValue(0) - t) > 1e-9:
            sys.exit("parallel_scaling: the trace did not reach t = %g" % t)
    print("RESULT %.6f %s" % (statistics.median(times), " ".join("%.4f" % x for x in times)))
    sys.exit(0)

here = os.path.abspath(__file__)
particles = args.elements * 16
rows = []
for run in args.runs:
    ranks, threads = (int(x) for x in run.split("x"))
    environment = dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread",
                       VTK_SMP_MAX_THREADS=str(threads))
    command = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
               "-n", str(ranks),
               args.pvbatch, here, "--worker", "--plugin", args.plugin,
               "--elements", str(args.elements), "--resolution", str(args.resolution),
               "--steps", str(args.steps), "--repeats", str(args.repeats)]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          env=environment, timeout=1800)
    match = re.search(r"RESULT (\S+)", done.stdout)
    if not match:
        print(done.stdout[-3000:])
        sys.exit("parallel_scaling: the %d-rank run failed" % ranks)
    seconds = float(match.group(1)) / args.steps
    rows.append((ranks, threads, 1.0 / seconds, particles / seconds))

print("Strip16 x %d (%d particles), %d^3 steady ABC, Euler, 1 averaged-Jacobi iteration; "
      "median of %d updates of %d steps (each update also builds the output)" %
      (args.elements, particles, args.resolution, args.repeats, args.steps))
print("%6s %8s %12s %18s %12s" % ("ranks", "threads", "steps/s", "particle-steps/s", "vs first"))
for ranks, threads, rate, particle_rate in rows:
    print("%6d %8d %12.2f %18.3g %11.2fx" % (ranks, threads, rate, particle_rate,
                                             rate / rows[0][2]))
