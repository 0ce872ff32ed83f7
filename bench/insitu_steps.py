"""In situ against post hoc (issue 42): what one time step costs the Bound
Particle Tracer when the steps arrive one at a time through a trivial producer
(as Catalyst hands them over) and when the same steps are read from disk and
the tracer is asked for each in turn. Both trace the double gyre's steps with
the same settings, on the CPU engine; the in situ steps are in memory before
the clock starts (the simulation's own work is not the tracer's), the post
hoc ones are read by the PVD reader (its reading is part of a post hoc step).
Also the process's resident memory over the in situ run, which must stay flat.

    pvpython bench/insitu_steps.py --plugin BoundParticles.so [--steps 500] [--elements 2000]
"""
import argparse
import os
import statistics
import tempfile
import time

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--steps", type=int, default=500)
parser.add_argument("--elements", type=int, default=2000)
args = parser.parse_args()

from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLImageDataWriter  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
SETTINGS = dict(Vectors=["POINTS", "velocity"], ElementShape="Paddlewheel", NumberOfElements=args.elements,
                Seed=3, Engine="CPU", LifetimeRange=[2.0, 4.0])


def resident_mib():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


# The same steps on disk, as a simulation that writes them would leave them.
flow = AnalyticFlow(Flow="Double Gyre", Resolution=[128, 64, 2], Bounds=[0, 2, 0, 1, 0, 0.05],
                    NumberOfTimeSteps=args.steps)
flow.UpdatePipeline()
times = list(flow.TimestepValues)
work = tempfile.mkdtemp(prefix="bp-insitu-bench-")
with open(os.path.join(work, "flow.pvd"), "w") as pvd:
    pvd.write('<VTKFile type="Collection" version="0.1"><Collection>\n')
    for k, t in enumerate(times):
        flow.UpdatePipeline(t)
        writer = vtkXMLImageDataWriter()
        writer.SetInputData(flow.GetClientSideObject().GetOutputDataObject(0))
        writer.SetFileName(os.path.join(work, "f%04d.vti" % k))
        writer.Write()
        pvd.write('<DataSet timestep="%.17g" file="f%04d.vti"/>\n' % (t, k))
    pvd.write("</Collection></VTKFile>\n")


def load(k):
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(work, "f%04d.vti" % k))
    reader.Update()
    return reader.GetOutput()


# Post hoc: the tracer asked for each data time step in turn.
posthoc = BoundParticleTracer(Input=PVDReader(FileName=os.path.join(work, "flow.pvd")), **SETTINGS)
posthoc_ms = []
for t in times:
    start = time.perf_counter()
    posthoc.UpdatePipeline(t)
    posthoc_ms.append(1e3 * (time.perf_counter() - start))
Delete(posthoc)

# In situ: each step handed to a trivial producer, then the tracer updated.
producer = PVTrivialProducer()
insitu = BoundParticleTracer(Input=producer, **SETTINGS)
insitu_ms, memory = [], []
for k, t in enumerate(times):
    data = load(k)
    start = time.perf_counter()
    producer.GetClientSideObject().SetOutput(data, t)
    producer.MarkModified(producer)
    insitu.UpdatePipeline(t)
    insitu_ms.append(1e3 * (time.perf_counter() - start))
    if k in (args.steps // 10, args.steps // 2, args.steps - 1):
        memory.append((k + 1, resident_mib()))

skip = min(10, args.steps // 5)  # the first steps start the trace
post, situ = statistics.median(posthoc_ms[skip:]), statistics.median(insitu_ms[skip:])
print("%d steps of the double gyre (128 x 64 x 2), %d Paddlewheel elements, CPU engine" % (args.steps, args.elements))
print("%-28s %12s" % ("one time step", "median ms"))
print("%-28s %12.2f" % ("post hoc (PVD reader)", post))
print("%-28s %12.2f" % ("in situ (trivial producer)", situ))
print("%-28s %12.2f" % ("in situ / post hoc", situ / post))
print("%-28s %12s" % ("in situ resident memory", "MiB"))
for step, mib in memory:
    print("%-28s %12.1f" % ("after step %d" % step, mib))
