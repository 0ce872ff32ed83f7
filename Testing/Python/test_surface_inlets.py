"""Seed Type Surface on a mesh's own boundary and on volumes: an inlet patch
lying on the side of a tetrahedral box turned 30 degrees about z (its
resampled cells there straddle the mesh's side and are outside the flow)
is sampled a cell into the flow and releases there.
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

# With Linking a super set is placed in the emitter box: the Surface is not
# used, said as for the other Seed Types, and the trace runs, even where the
# Surface would release nothing (a plane the flow runs along: it failed).
flow = Calculator(Input=Wavelet(WholeExtent=[0, 10, 0, 10, 0, 10]), ResultArrayName="v",
                  Function="iHat + 0.1*jHat")
linked = BoundParticleTracer(Input=flow, Vectors=["POINTS", "v"], ElementShape="Cross",
                             NumberOfElements=20, Linking="Chain", SeedType="Surface",
                             SeedSource=Plane(Origin=[2, 2, 2], Point1=[8, 2, 2],
                                              Point2=[2, 8, 2]))
points, said = released(linked)
bptest.check(said.mentions("the Surface is not used") and not said.mentions("ERROR") and
             len(points) > 0, "Linking ignores the Surface (%d points; %s)" %
             (len(points), said.messages))
Delete(linked)
bptest.finish()
