"""Steps per second of one trace under pvbatch with 1, 2 and 4 MPI ranks.

Driver (any python with numpy not needed): /usr/bin/python3 parallel_scaling.py
--plugin P [--ranks 1 2 4] [--threads 1]. It runs itself under
`mpiexec -n R pvbatch ... --worker` for each R, one SMP thread per rank unless
told otherwise, and prints a table. The worker traces Strip16 elements on a
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
parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
parser.add_argument("--threads", type=int, default=1, help="SMP threads per rank")
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
        Input=flow, ElementShape="Strip16", NumberOfElements=args.elements, Seed=1,
        StepSizeUnit="Time", StepSize=dt, Duration=dt * 100000, NumberOfTimeSteps=100001,
        LifetimeRange=[50.0, 100.0])
    t = 0.0
    tracer.UpdatePipeline(t)  # warm-up: field, split, placement
    times = []
    for _ in range(args.repeats):
        t += args.steps * dt
        start = time.perf_counter()
        tracer.UpdatePipeline(t)
        times.append(time.perf_counter() - start)
    print("RESULT %.6f %s" % (statistics.median(times), " ".join("%.4f" % x for x in times)))
    sys.exit(0)

here = os.path.abspath(__file__)
environment = dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread",
                   VTK_SMP_MAX_THREADS=str(args.threads))
particles = args.elements * 16
rows = []
for ranks in args.ranks:
    command = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks),
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
    rows.append((ranks, 1.0 / seconds, particles / seconds))

print("Strip16 x %d (%d particles), %d^3 steady ABC, Euler, 1 averaged-Jacobi iteration, "
      "%d SMP thread(s) per rank; median of %d updates of %d steps" %
      (args.elements, particles, args.resolution, args.threads, args.repeats, args.steps))
print("%6s %12s %22s %10s" % ("ranks", "steps/s", "particle-steps/s", "vs 1 rank"))
for ranks, rate, particle_rate in rows:
    print("%6d %12.2f %22.3g %9.2fx" % (ranks, rate, particle_rate, rate / rows[0][1]))
