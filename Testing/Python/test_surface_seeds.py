"""Seed Type Surface, an inlet (issue 58, part 4) from pvpython: releases
spread over the Seed Source's surface by the flux through it. A Plane across a
flow whose normal velocity grows linearly across it (w = 1 + 3x) takes
releases only on the plane, in each band of x by its share of the flux (a
chi-square test, which a uniform spread fails); the same Seed gives the same
releases; the surface's own normals decide the side (a Box's outward faces,
Flip Normals for its inflow face); on a 2D field a Plane standing across
the slice releases on its line; Orientation = Along Flow turns the
elements onto the flow; no Seed Source, or no flux along the normals, is
refused by name with an empty output; a state file brings it back.
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
V = ["POINTS", "v"]
N = 5000


def released(tracer):
    """The output's points and ElementId at the start (Point elements: the release centres)."""
    tracer.UpdatePipeline(tracer.TimestepValues[0])
    data = servermanager.Fetch(tracer)
    if data.GetNumberOfPoints() == 0:
        return numpy.zeros((0, 3)), numpy.zeros(0, dtype=int)
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
    order = numpy.argsort(ids, kind="stable")
    return points[order], ids[order]


# v = (0.3, 0, 1 + 3x): through the plane z = 0 (normal +z) the flux at x is
# 1 + 3x, and the band [x0, x1] of x in [0, 1] takes
# ((x1 - x0) + 1.5 (x1^2 - x0^2)) / 2.5 of it.
base = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[21, 21, 21], Bounds=[-0.5, 1.5, -0.5, 1.5, -1, 1])
flow = Calculator(Input=base, ResultArrayName="v", Function="0.3*iHat + (1 + 3*coordsX)*kHat")
flow.UpdatePipeline()
plane = Plane(Origin=[0, 0, 0], Point1=[1, 0, 0], Point2=[0, 1, 0], XResolution=10,
              YResolution=10)
edges = numpy.linspace(0.0, 1.0, 11)
shares = ((edges[1:] - edges[:-1]) + 1.5 * (edges[1:] ** 2 - edges[:-1] ** 2)) / 2.5


def chi_square(points, share):
    counts = numpy.histogram(points[:, 0], bins=10, range=(0.0, 1.0))[0]
    expected = share * len(points)
    return float(((counts - expected) ** 2 / expected).sum()), counts


tracer = BoundParticleTracer(Input=flow, Vectors=V, ElementShape="Point", NumberOfElements=N,
                             SeedType="Surface", SeedSource=plane, Seed=11)
bptest.check(tracer.SeedType.GetXMLLabel() == "Surface", "Seed Type set by name")
bptest.check(tracer.SeedType.NumberOfPoints == 10000 and tracer.SeedType.FlipNormals == 0,
             "defaults: 10000 points, normals as they are")
with bptest.CapturedMessages() as said:
    points, ids = released(tracer)
bptest.check(not said.messages, "a plane in the flow says nothing: %s" % said.messages)
bptest.check(len(points) == N, "%d elements released (%d)" % (N, len(points)))
if len(points):
    bptest.check(numpy.abs(points[:, 2]).max() < 1e-5 and points[:, 0].min() >= -1e-5 and
                 points[:, 0].max() <= 1 + 1e-5 and points[:, 1].min() >= -1e-5 and
                 points[:, 1].max() <= 1 + 1e-5,
                 "every release on the plane (|z| up to %.3g)" % numpy.abs(points[:, 2]).max())
    chi, counts = chi_square(points, shares)
    uniform, _ = chi_square(points, numpy.full(10, 0.1))
    print("chi-square %.3g against the flux, %.3g against uniform; counts %s" %
          (chi, uniform, list(counts)))
    # 9 degrees of freedom: 99.9% of fair draws stay below 27.9.
    bptest.check(chi < 27.9, "the releases follow the flux (chi-square %.3g)" % chi)
    bptest.check(uniform > 500, "and not a uniform spread (%.3g)" % uniform)
    bptest.check(counts[-1] > 3 * counts[0],
                 "more where the flux is higher (%d in the last band, %d in the first)" %
                 (counts[-1], counts[0]))
    # Each element at a point of its own (10000 points for 5000 elements).
    bptest.check(len(numpy.unique(points.round(7), axis=0)) == N, "a point each")
    # The same Seed, the same releases; another Seed, others.
    again, _ = released(tracer)
    bptest.check(numpy.array_equal(points, again), "the same Seed gives the same releases")
    tracer.Seed = 12
    other, _ = released(tracer)
    bptest.check(len(other) == N and not numpy.allclose(points, other),
                 "another Seed, other releases")
    tracer.Seed = 11

# The surface's own normals: a Box's faces point outward, so the flow (up
# along z, and along x at 0.3) leaves through its top face (flux 2.5 x 0.25
# at its mean x = 0.5) and its +x face (0.3 x 0.25): 2.5 / 2.8 of the
# releases on the top, the rest on the +x side, none elsewhere. Flip Normals
# mirrors it: its bottom and -x faces, where the flow enters.
box = Box(Center=[0.5, 0.5, 0.0], XLength=0.5, YLength=0.5, ZLength=0.5)
tracer.SeedSource = box
for flip, (face, side) in ((0, (0.25, 0.75)), (1, (-0.25, 0.25))):
    tracer.SeedType.FlipNormals = flip
    points, _ = released(tracer)
    on_face = numpy.isclose(points[:, 2], face, atol=1e-5)
    on_side = numpy.isclose(points[:, 0], side, atol=1e-5)
    share = on_face.mean() if len(points) else 0.0
    # Binomial(5000, 0.893): a standard deviation of 0.0044 in the share.
    bptest.check(len(points) == N and (on_face | on_side).all() and abs(share - 2.5 / 2.8) < 0.025,
                 "Flip Normals %d: releases on the faces the flow %s through (%.3f on z = %g)" %
                 (flip, "enters" if flip else "leaves", share, face))

# Flip Normals on the plane: no flow crosses it that way. Refused by name,
# nothing released.
tracer.SeedSource = plane
with bptest.CapturedMessages() as said:
    points, _ = released(tracer)
bptest.check(said.mentions("No flow crosses the Seed Source's surface") and
             said.mentions("Unset the Surface's Flip Normals") and len(points) == 0,
             "flux against the normals: said, empty output (%s)" % said.messages)
tracer.SeedType.FlipNormals = 0

# No Seed Source: said, nothing released.
tracer.SeedSource = None
with bptest.CapturedMessages() as said:
    points, _ = released(tracer)
bptest.check(said.mentions("no Seed Source is connected") and len(points) == 0,
             "no Seed Source: said, empty output (%s)" % said.messages)
Delete(tracer)

# Orientation = Along Flow turns each released strip onto the flow at its
# release centre: its ends lie along v there.
strips = BoundParticleTracer(Input=flow, Vectors=V, ElementShape="Strip8", NumberOfElements=50,
                             SeedType="Surface", SeedSource=plane, ReleaseOrientation="Along Flow")
strips.UpdatePipeline(strips.TimestepValues[0])
data = servermanager.Fetch(strips)
positions = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
element = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
worst = 0.0
for e in numpy.unique(element):
    p = positions[element == e]
    centre = p.mean(axis=0)
    axis = numpy.linalg.svd(p - centre)[2][0]  # the strip's long axis
    v = numpy.array([0.3, 0.0, 1.0 + 3.0 * centre[0]])
    cosine = abs(axis.dot(v)) / (numpy.linalg.norm(axis) * numpy.linalg.norm(v))
    worst = max(worst, 1.0 - cosine)
bptest.check(len(numpy.unique(element)) == 50 and worst < 1e-3,
             "Along Flow: every strip along the flow at its release (worst 1 - cos %.3g)" % worst)

# On a 2D field (z one point, at 0.25) a Plane standing across the slice is
# an inlet line: the releases lie on the field's plane, where the solid-body
# rotation about (2, 1) crosses x = 1 along the plane's normal +x (y < 1).
flat = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[41, 21, 1],
                    Bounds=[0, 4, 0, 2, 0.25, 0.25])
wall = Plane(Origin=[1, 0.2, -1], Point1=[1, 1.8, -1], Point2=[1, 0.2, 1], XResolution=8,
             YResolution=2)
sliced = BoundParticleTracer(Input=flat, Vectors=["POINTS", "velocity"], ElementShape="Point",
                             NumberOfElements=300, SeedType="Surface", SeedSource=wall)
points, _ = released(sliced)
bptest.check(len(points) == 300 and numpy.allclose(points[:, 2], 0.25) and
             numpy.allclose(points[:, 0], 1.0, atol=1e-5) and points[:, 1].max() < 1.0 + 1e-5,
             "a 2D field: releases on its plane, where the flow crosses along the normal")
Delete(sliced)

# A state file brings back the Surface, its parameters and its Seed Source,
# and the same releases.
strips.SeedType.NumberOfPoints = 300
strips.SeedType.FlipNormals = 0
strips.UpdatePipeline(strips.TimestepValues[0])
before = vtk_to_numpy(servermanager.Fetch(strips).GetPoints().GetData()).astype(float)
state = os.path.join(bptest.scratch("bp-surface-seeds-"), "surface.pvsm")
SaveState(state)
ResetSession()
LoadPlugin(args.plugin, ns=globals())
LoadState(state)
loaded = [s for s in GetSources().values() if s.GetXMLName() == "BoundParticleTracer"][0]
bptest.check(loaded.SeedType.GetXMLLabel() == "Surface" and loaded.SeedType.NumberOfPoints == 300
             and loaded.SeedSource is not None, "the state brings back the Surface and its source")
loaded.UpdatePipeline(loaded.TimestepValues[0])
after = vtk_to_numpy(servermanager.Fetch(loaded).GetPoints().GetData()).astype(float)
bptest.check(numpy.array_equal(before, after), "and the same releases")
bptest.finish()
