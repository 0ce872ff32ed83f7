"""Release Pattern = Lattice and Release Weights (issue 31, items 1 and 4)
from pvpython: a lattice on a flat slice puts each element on its point,
computed here independently from the box and the count; Release Weights
w = x shapes the release positions' histogram (on an image and through the
resampled path of an unstructured grid), which a uniform release fails; a
missing array warns and releases uniformly.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments()

import numpy  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
VELOCITY = ["POINTS", "velocity"]


def releases(tracer):
    """Each element's position at the start (Point elements: its release centre), by ElementId."""
    tracer.UpdatePipeline(tracer.TimestepValues[0])
    data = servermanager.Fetch(tracer)
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
    order = numpy.argsort(ids, kind="stable")
    return points[order], ids[order]


# A flat slice: z has one point, at z = 0.25.
flat = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[41, 21, 1],
                    Bounds=[0, 4, 0, 2, 0.25, 0.25])
flat.UpdatePipeline()
lattice = BoundParticleTracer(Input=flat, Vectors=VELOCITY, ElementShape="Point",
                              NumberOfElements=200, ReleasePattern="Lattice",
                              MinimumReleaseSpeed=0.0)
points, ids = releases(lattice)
# Independently: the spacing whose square cells of the 4 x 2 box number 200
# is 0.2; 20 x 10 cells, points at their centres, x fastest.
i = numpy.arange(200)
expected = numpy.stack([0.1 + 0.2 * (i % 20), 0.1 + 0.2 * (i // 20), numpy.full(200, 0.25)], axis=1)
bptest.check(len(points) == 200, "a lattice of 200 elements (%d)" % len(points))
if len(points) == 200:
    error = numpy.abs(points - expected).max()
    bptest.check(error < 1e-5, "every element on its lattice point (worst %.3g)" % error)
# A set spacing decides the count: 0.5 gives 8 x 4 points.
lattice.LatticeSpacing = 0.5
points, ids = releases(lattice)
bptest.check(len(points) == 32, "Lattice Spacing 0.5: 32 elements (%d)" % len(points))
bptest.check(numpy.allclose(sorted(set(numpy.round(points[:, 0], 4))), 0.25 + 0.5 * numpy.arange(8)),
             "Lattice Spacing 0.5: x at 0.25, 0.75, ... 3.75")
# Later in the animation the released elements are back on their points.
lattice.UpdatePipeline(lattice.TimestepValues[len(lattice.TimestepValues) // 2])
Delete(lattice)

# Release Weights: w = x on [0, 4] (Solid Body Rotation about the box's centre).
box = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[41, 11, 11], Bounds=[0, 4, 0, 1, 0, 1])
weighted = Calculator(Input=box, ResultArrayName="w", Function="coordsX")
weighted.UpdatePipeline()
N = 20000
# Bin b of [0.4 b, 0.4 (b + 1)] takes ((b + 1)^2 - b^2) / 100 of the releases.
shares = numpy.array([(2 * b + 1) / 100.0 for b in range(10)])


def chi_square(points, share):
    counts = numpy.histogram(points[:, 0], bins=10, range=(0.0, 4.0))[0]
    expected = share * len(points)
    return float(((counts - expected) ** 2 / expected).sum())


for name, source in (("an image", weighted),
                     ("an unstructured grid (resampled)", AppendDatasets(Input=weighted))):
    # Run before the tracer is made, as `weighted` was: ParaView 6.1's pvpython
    # gives a tracer on a source that never ran a zero-size emitter box.
    source.UpdatePipeline()
    tracer = BoundParticleTracer(Input=source, Vectors=VELOCITY, ElementShape="Point",
                                 NumberOfElements=N, MinimumReleaseSpeed=0.0,
                                 ReleaseWeights=["POINTS", "w"])
    points, ids = releases(tracer)
    chi = chi_square(points, shares)
    uniform = chi_square(points, numpy.full(10, 0.1))
    print("%s: chi-square %.3g against the weights, %.3g against uniform" % (name, chi, uniform))
    # 9 degrees of freedom: 99.9% of fair draws stay below 27.9.
    bptest.check(len(points) == N and chi < 27.9,
                 "%s: the releases follow w = x (chi-square %.3g)" % (name, chi))
    bptest.check(uniform > 1000, "%s: and not uniform (%.3g)" % (name, uniform))
    Delete(tracer)

# None releases uniformly; an array the input lacks warns and does too.
tracer = BoundParticleTracer(Input=weighted, Vectors=VELOCITY, ElementShape="Point",
                             NumberOfElements=N, MinimumReleaseSpeed=0.0)
bptest.check(tracer.ReleaseWeights[1] == "None", "the default is None (%s)" % tracer.ReleaseWeights)
points, ids = releases(tracer)
bptest.check(chi_square(points, numpy.full(10, 0.1)) < 27.9, "None: uniform releases")
tracer.ReleaseWeights = ["POINTS", "nosuch"]
with bptest.CapturedMessages() as said:
    points, ids = releases(tracer)
bptest.check(said.mentions("no point or cell array 'nosuch'"),
             "a missing array warns: %s" % said.messages)
bptest.check(chi_square(points, numpy.full(10, 0.1)) < 27.9, "a missing array: uniform releases")

# Weights of 0 everywhere warn and release uniformly.
zero = Calculator(Input=box, ResultArrayName="zero", Function="0*coordsX")
tracer.Input = zero
tracer.ReleaseWeights = ["POINTS", "zero"]
with bptest.CapturedMessages() as said:
    points, ids = releases(tracer)
bptest.check(said.mentions("is 0, NaN or Inf at every point"), "weights of 0 warn: %s" % said.messages)
bptest.check(chi_square(points, numpy.full(10, 0.1)) < 27.9, "weights of 0: uniform releases")
Delete(tracer)

# Weights honour the mask: above 0 only where vtkValidPointMask is 0 (x < 1.6),
# they warn and release uniformly over the valid part, never in the masked one.
masked = ProgrammableFilter(Input=box, OutputDataSetType="vtkImageData")
masked.Script = """import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
x = numpy.array([out.GetPoint(i)[0] for i in range(out.GetNumberOfPoints())])
def add(name, values, dtype):
    a = numpy_to_vtk(numpy.ascontiguousarray(values, dtype=dtype), deep=True)
    a.SetName(name)
    out.GetPointData().AddArray(a)
add("vtkValidPointMask", x >= 1.6, numpy.uint8)
add("there", x < 1.2, numpy.float32)
add("big", numpy.where(x > 2.0, 1e39, 0.0), numpy.float64)
add("huge", numpy.full(len(x), 1e300), numpy.float64)
# A cell array (cells of 0.1 along x): 1 for cells beyond x = 2, 0 before.
cx = numpy.array([out.GetCell(c).GetBounds()[0] for c in range(out.GetNumberOfCells())])
c = numpy_to_vtk(numpy.ascontiguousarray(cx >= 2.0, dtype=numpy.float32), deep=True)
c.SetName("cw")
out.GetCellData().AddArray(c)
"""
masked.UpdatePipeline()
tracer = BoundParticleTracer(Input=masked, Vectors=VELOCITY, ElementShape="Point",
                             NumberOfElements=2000, MinimumReleaseSpeed=0.0,
                             ReleaseWeights=["POINTS", "there"])
with bptest.CapturedMessages() as said:
    points, ids = releases(tracer)
bptest.check(said.mentions("above 0 only where releases may not land"),
             "weights only in the masked part warn: %s" % said.messages)
bptest.check(len(points) == 2000 and points[:, 0].min() >= 1.6,
             "and no release lands in the masked part (lowest x %.3g)" % points[:, 0].min())
bptest.check(numpy.histogram(points[:, 0], bins=4, range=(1.6, 4.0))[0].min() > 300,
             "releases spread uniformly over the valid part")
Delete(tracer)
# A double array beyond float's range (1e39 where x > 2, 0 elsewhere) weighs
# as it is; 1e300 everywhere is not "0, NaN or Inf". A cell array, asked as
# cells or (as ParaView's panel offers it) as points, weighs releases beyond
# x = 1.9: averaged onto an image's points, taken per cell on a mesh.
for name, source in (("an image", masked), ("a mesh", AppendDatasets(Input=masked))):
    source.UpdatePipeline()
    tracer = BoundParticleTracer(Input=source, Vectors=VELOCITY, ElementShape="Point",
                                 NumberOfElements=2000, MinimumReleaseSpeed=0.0,
                                 ReleaseWeights=["POINTS", "big"])
    with bptest.CapturedMessages() as said:
        points, ids = releases(tracer)
    bptest.check(not said.messages and points[:, 0].min() > 1.9,
                 "%s: weights of 1e39 take every release (lowest x %.3g): %s" %
                 (name, points[:, 0].min(), said.messages))
    tracer.ReleaseWeights = ["POINTS", "huge"]
    with bptest.CapturedMessages() as said:
        points, ids = releases(tracer)
    bptest.check(not said.messages, "%s: weights of 1e300 are weights: %s" % (name, said.messages))
    domain = tracer.SMProxy.GetProperty("ReleaseWeights").FindDomain("vtkSMArrayListDomain")
    offered = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]
    bptest.check("cw" in offered and "big" in offered,
                 "%s: the panel's list offers cell and point arrays: %s" % (name, offered))
    for association in ("CELLS", "POINTS"):
        tracer.ReleaseWeights = [association, "cw"]
        with bptest.CapturedMessages() as said:
            points, ids = releases(tracer)
        bptest.check(not said.messages and points[:, 0].min() > 1.85,
                     "%s: a cell array as %s weighs releases (lowest x %.3g): %s" %
                     (name, association, points[:, 0].min(), said.messages))
Delete(tracer)

# Too fine a lattice and a lattice with Linking are refused with a message
# that names what to change; the output is empty, and nothing hangs.
for properties, words in (({"LatticeSpacing": 1e-9}, "LatticeSpacing"),
                          ({"Linking": "Sheet"}, "Linking")):
    bad = BoundParticleTracer(Input=flat, Vectors=VELOCITY, ReleasePattern="Lattice", **properties)
    with bptest.CapturedMessages() as said:
        bad.UpdatePipeline(bad.TimestepValues[0])
    output = servermanager.Fetch(bad)
    bptest.check(said.mentions(words) and output.GetNumberOfPoints() == 0,
                 "%s: refused by name, empty output (%s)" % (properties, said.messages))
    Delete(bad)
bptest.finish()
