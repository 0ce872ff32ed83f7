"""How evenly MPI ranks share the elements over a run of the hurricane flow,
where elements crowd toward the eye.

Driver: /usr/bin/python3 parallel_balance.py --plugin P [--ranks 2 4].
For each rank count it runs itself under `mpiexec -n R pvbatch ... --worker`:
the worker traces crosses through the Analytic Flow's Hurricane over its
default bounds [-1, 1]^3 and, at every offered time, reads the output's
ElementsPerProcess field data (every rank's element count). The driver prints
max/mean per frame and a summary row per rank count.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--ranks", nargs="+", type=int, default=[2, 4])
parser.add_argument("--elements", type=int, default=4000)
parser.add_argument("--frames", type=int, default=21)
parser.add_argument("--duration", type=float, default=6.0)
parser.add_argument("--mpiexec", default="mpiexec")
parser.add_argument("--pvbatch", default="pvbatch")
parser.add_argument("--worker", action="store_true")
args = parser.parse_args()

if args.worker:
    from paraview.simple import *  # noqa: F401,F403

    LoadPlugin(args.plugin, ns=globals())
    flow = AnalyticFlow(Flow="Hurricane", Resolution=[48, 48, 32])
    flow.UpdatePipeline()
    # Long lifetimes, so elements stay where the flow takes them instead of
    # being released again uniformly.
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"], ElementShape="Cross",
                                 NumberOfElements=args.elements, Seed=2,
                                 Duration=args.duration, NumberOfTimeSteps=args.frames,
                                 LifetimeRange=[args.duration, args.duration])
    for t in tracer.TimestepValues:
        tracer.UpdatePipeline(t)
        counts = tracer.GetClientSideObject().GetOutputDataObject(0).GetFieldData() \
            .GetArray("ElementsPerProcess")
        if counts is None:
            sys.exit("parallel_balance: no ElementsPerProcess at t = %g" % t)
        values = [int(counts.GetValue(k)) for k in range(counts.GetNumberOfValues())]
        print("FRAME %g %s" % (t, " ".join(str(v) for v in values)), flush=True)
    sys.exit(0)

here = os.path.abspath(__file__)
print("Crosses x %d in the Hurricane over [-1, 1]^3 (48x48x32), lifetimes %g, %d frames "
      "over [0, %g]: elements per rank" % (args.elements, args.duration, args.frames,
                                          args.duration))
summary = []
for ranks in args.ranks:
    command = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
               "-n", str(ranks), args.pvbatch, here, "--worker", "--plugin", args.plugin,
               "--elements", str(args.elements), "--frames", str(args.frames),
               "--duration", str(args.duration)]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=1800)
    frames = [line.split()[1:] for line in done.stdout.splitlines()
              if line.startswith("FRAME") and len(line.split()) == ranks + 2]
    # Every rank prints the same gathered counts: keep one line per time.
    seen, rows = set(), []
    for fields in frames:
        if fields[0] not in seen:
            seen.add(fields[0])
            rows.append((float(fields[0]), [int(v) for v in fields[1:]]))
    if len(rows) != args.frames:
        print(done.stdout[-3000:])
        sys.exit("parallel_balance: the %d-rank run failed" % ranks)
    print("\n%d ranks\n%8s  %-32s %9s" % (ranks, "time", "elements per rank", "max/mean"))
    ratios = []
    for t, counts in sorted(rows):
        ratio = max(counts) / statistics.mean(counts)
        ratios.append(ratio)
        print("%8.2f  %-32s %9.2f" % (t, " ".join("%6d" % c for c in counts), ratio))
    summary.append((ranks, statistics.median(ratios), max(ratios), sorted(rows)[-1][1]))

print("\n%6s %16s %14s   %s" % ("ranks", "median max/mean", "worst max/mean",
                                 "elements per rank at the end"))
for ranks, median, worst, last in summary:
    print("%6d %16.2f %14.2f   %s" % (ranks, median, worst, " ".join(str(c) for c in last)))
