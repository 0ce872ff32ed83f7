"""In situ on meshes (issue 42, item 2): an unstructured grid (the double gyre
through Tetrahedralize), handed to the tracer one step at a time through a
trivial producer, goes through the tracer's resampler and gets the elements a
post hoc trace of the same mesh series gets, matched by ElementId and
ParticleIndex within 1e-4 of the domain; with point vectors and with cell
vectors (the same mesh's Point Data to Cell Data). Nothing is said on the way.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--steps")

from paraview.simple import *  # noqa: E402,F401,F403
from insitu_feed import copy_of, elements, farthest, feed  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
STEPS = int(args.steps or 12)
DOMAIN = 2.0
SETTINGS = dict(ElementShape="Paddlewheel", NumberOfElements=150, Seed=5, Engine="CPU",
                LifetimeRange=[2.0, 4.0])

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[24, 12, 2], Bounds=[0, 2, 0, 1, 0, 0.05],
                    NumberOfTimeSteps=STEPS)
mesh = Tetrahedralize(Input=flow)
mesh.UpdatePipeline()
cells = PointDatatoCellData(Input=mesh)
times = list(flow.TimestepValues)
info = mesh.GetDataInformation()
print("the mesh: %s, %d cells, %d steps" % (info.GetDataSetTypeAsString(),
                                           info.GetNumberOfCells(), len(times)))
bptest.check(info.GetDataSetTypeAsString() == "vtkUnstructuredGrid" and
             100 <= info.GetNumberOfCells() <= 5000,
             "the input is an unstructured grid of a few hundred to thousands of cells")


def compare(label, series, vectors):
    """Traces `series` post hoc and, fed step by step, in situ; checks the
    elements at half way and at the last step."""
    posthoc = BoundParticleTracer(Input=series, Vectors=vectors, **SETTINGS)
    checked = (times[STEPS // 2], times[-1])
    reference = {t: elements(posthoc, t) for t in checked}
    producer = PVTrivialProducer()
    insitu = BoundParticleTracer(Input=producer, Vectors=vectors, **SETTINGS)
    with bptest.CapturedMessages() as said:
        for t in times:
            feed(producer, copy_of(series, t), t)
            got = elements(insitu, t)
            if t in reference:
                gap = farthest(got, reference[t])
                print("%s, t = %g: %d particles in situ, %d post hoc, %g apart"
                      % (label, t, len(got), len(reference[t]), gap))
                bptest.check(gap <= 1e-4 * DOMAIN, "%s: in situ equals post hoc at t = %g "
                             "(%d and %d particles, %g apart)"
                             % (label, t, len(got), len(reference[t]), gap))
    said.messages = [m for m in said.messages if "New time step is not" not in m]
    bptest.check(not said.messages, "%s: nothing said in situ: %s" % (label, said.messages[:3]))
    # The trace moved: the elements at the end are not where they were released.
    first = elements(BoundParticleTracer(Input=series, Vectors=vectors, **SETTINGS), times[1])
    moved = [k for k in first if k in reference[times[-1]]]
    bptest.check(moved and farthest({k: first[k] for k in moved},
                                    {k: reference[times[-1]][k] for k in moved}) > 0.05,
                 "%s: the elements moved over the steps" % label)


compare("point vectors", mesh, ["POINTS", "velocity"])
compare("cell vectors", cells, ["CELLS", "velocity"])
bptest.finish()
