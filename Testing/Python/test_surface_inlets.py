"""Seed Type Surface on a mesh's own boundary and on volumes: an inlet patch
lying on the side of a tetrahedral box turned 30 degrees about z (its
resampled cells there straddle the mesh's side and are outside the flow)
is sampled a cell into the flow and releases there. A multiblock volume
(two halves of a box, grouped) releases on its outer faces only, not the
face between its blocks; a mirrored (left-handed) grid's boundary points
outward; a plane most of whose flux crosses it against its normals is
warned about; with Linking the Surface is not used.
"""
import math
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
N = 2000


def released(tracer):
    """The release centres of Point elements at the start, and the messages said."""
    with bptest.CapturedMessages() as said:
        tracer.UpdatePipeline(tracer.TimestepValues[0])
        data = servermanager.Fetch(tracer)
    if data.GetNumberOfPoints() == 0:
        return numpy.zeros((0, 3)), said
    return vtk_to_numpy(data.GetPoints().GetData()).astype(float), said


# A box [0, 2] x [0, 1] x [0, 1] of tetrahedra turned 30 degrees about z, the
# flow along its own x axis: v = (cos 30, sin 30, 0).
c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
cube = Wavelet(WholeExtent=[0, 8, 0, 4, 0, 4])
scaled = Transform(Input=cube)
scaled.Transform.Scale = [0.25, 0.25, 0.25]
turned = Transform(Input=Tetrahedralize(Input=scaled))
turned.Transform.Rotate = [0, 0, 30]
mesh = Calculator(Input=turned, ResultArrayName="v", Function="%r*iHat + %r*jHat" % (c, s))
mesh.UpdatePipeline()


def turn(x, y, z):
    return [c * x - s * y, s * x + c * y, z]


# Its own x = 0 face as the inlet, the normal (Point1 - Origin) x (Point2 -
# Origin) along +x' (into the box, with the flow).
inlet = Plane(Origin=turn(0, 0, 0), Point1=turn(0, 1, 0), Point2=turn(0, 0, 1), XResolution=8,
              YResolution=8)
tracer = BoundParticleTracer(Input=mesh, Vectors=["POINTS", "v"], ElementShape="Point",
                             NumberOfElements=N, SeedType="Surface", SeedSource=inlet, Seed=5,
                             ResampleDimensions=[24, 24, 12])
points, said = released(tracer)
# Before, every centroid fell in a cell across the mesh's side: "lies outside
# the field", nothing released. Now only triangles along the face's edges
# (where the next side's cells straddle too) are left out, with a warning.
bptest.check(not said.mentions("releases nothing") and len(points) == N,
             "an inlet on the mesh's own side releases (%d of %d; %s)" %
             (len(points), N, said.messages))
left = [m for m in said.messages if "surface triangles" in m]
bptest.check(len(left) == 1 and "24 lie outside" in left[0],
             "only the triangles along the face's edges left out (%s)" % left)
if len(points):
    # In the box's own frame: x' a short way in (about a cell), y', z' across the face.
    own = numpy.stack([c * points[:, 0] + s * points[:, 1], -s * points[:, 0] + c * points[:, 1],
                       points[:, 2]], axis=1)
    bptest.check(own[:, 0].min() > 0.0 and own[:, 0].max() < 0.3 and
                 own[:, 1].min() > -1e-5 and own[:, 1].max() < 1 + 1e-5,
                 "a short way into the flow (x' from %.3g to %.3g), across the face" %
                 (own[:, 0].min(), own[:, 0].max()))
    bptest.check(own[:, 1].std() > 0.2,
                 "spread over the face (y' deviation %.3g)" % own[:, 1].std())
Delete(tracer)

# A uniform flow along +x through the box [0, 20]^3.
flow = Calculator(Input=Wavelet(WholeExtent=[0, 20, 0, 20, 0, 20]), ResultArrayName="v",
                  Function="iHat")
flow.UpdatePipeline()

# Two halves of [5, 15]^3 (x below and above 10) as one multiblock, Flip
# Normals counting the inflow: all on the x = 5 face, none on the face
# x = 10 between the blocks (half the releases were there).
halves = GroupDatasets(Input=[ExtractSubset(Input=flow, VOI=[5, 10, 5, 15, 5, 15]),
                              ExtractSubset(Input=flow, VOI=[10, 15, 5, 15, 5, 15])])
tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "v"], ElementShape="Point",
                             NumberOfElements=N, SeedType="Surface", SeedSource=halves, Seed=5)
tracer.SeedType.FlipNormals = 1
points, said = released(tracer)
bptest.check(len(points) == N and numpy.allclose(points[:, 0], 5.0, atol=1e-4),
             "a multiblock's inflow face only (%d points, x from %.3g to %.3g)" %
             (len(points), points[:, 0].min() if len(points) else 0,
              points[:, 0].max() if len(points) else 0))

# The box [5, 15]^3 mirrored in x (Scale x = -1, then moved back: a
# left-handed structured grid whose cells' faces point inward): its
# boundary points outward all the same, so without Flip Normals the flow
# leaves through x = 15 (it released on x = 5).
mirrored = Transform(Input=ExtractSubset(Input=flow, VOI=[5, 15, 5, 15, 5, 15]))
mirrored.Transform.Translate = [20, 0, 0]
mirrored.Transform.Scale = [-1, 1, 1]
mirrored.UpdatePipeline()
bptest.check(mirrored.GetDataInformation().GetDataSetTypeAsString() == "vtkStructuredGrid",
             "the mirror is a structured grid (%s)" %
             mirrored.GetDataInformation().GetDataSetTypeAsString())
tracer.SeedSource = mirrored
tracer.SeedType.FlipNormals = 0
points, said = released(tracer)
bptest.check(len(points) == N and numpy.allclose(points[:, 0], 15.0, atol=1e-4),
             "a left-handed grid's outflow face (%d points, x from %.3g to %.3g)" %
             (len(points), points[:, 0].min() if len(points) else 0,
              points[:, 0].max() if len(points) else 0))

# A plane at x = 10 across v = (y - 15) / 5 along x (normal +x): along it
# above y = 15 (a flux of 12.5 / 5), against it below (112.5 / 5): warned.
sheared = Calculator(Input=flow, ResultArrayName="w", Function="(coordsY - 15) / 5 * iHat")
tracer.Input = sheared
tracer.Vectors = ["POINTS", "w"]
tracer.SeedSource = Plane(Origin=[10, 0, 0], Point1=[10, 20, 0], Point2=[10, 0, 20],
                          XResolution=20, YResolution=2)
points, said = released(tracer)
bptest.check(len(points) == N and points[:, 1].min() > 15 - 1e-4 and
             said.mentions("Most of the flow through the Seed Source's surface crosses it "
                           "against its normals") and said.mentions("set Flip Normals"),
             "mostly against the normals: released where along, warned (%s)" % said.messages)
Delete(tracer)

# With Linking a super set is placed in the emitter box: the Surface is not
# used, said as for the other Seed Types, and the trace runs, even where the
# Surface would release nothing (a plane the flow runs along: it failed).
linked = BoundParticleTracer(Input=flow, Vectors=["POINTS", "v"], ElementShape="Cross",
                             NumberOfElements=20, Linking="Chain", SeedType="Surface",
                             SeedSource=Plane(Origin=[2, 2, 2], Point1=[18, 2, 2],
                                              Point2=[2, 18, 2]))
points, said = released(linked)
bptest.check(said.mentions("the Surface is not used") and not said.mentions("ERROR") and
             len(points) > 0, "Linking ignores the Surface (%d points; %s)" %
             (len(points), said.messages))
Delete(linked)
bptest.finish()
