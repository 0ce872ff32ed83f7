"""Any mesh a ParaView user opens, traced straight: each kind of data made
here (no downloads) and checked against the image path on the same flow.

- tets: the ABC flow's image cut into tetrahedra; on a grid of the image's
  points the trace is the image's; on the automatic grid, close to it;
- curvilinear: a curved annulus (a structured grid with a hole) in solid-body
  rotation: elements circle at the rotation rate, never in the hole;
- zones: a multiblock of two curvilinear zones sharing a face: the image's trace;
- cells: cell-only vectors (no Cell Data to Point Data): elements move with the flow;
- flat: a triangulated plane at z = 0.5: a one-layer grid, elements in the plane;
- unsteady: the double gyre's time steps on a tetrahedral mesh: the image's
  time line and trace.
"""
import math
import os
import sys
import tempfile

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())


def updated(source):
    source.UpdatePipeline()
    return source


def traced(source, time=None, vectors=("POINTS", "velocity"), **properties):
    """A tracer on `source`, run to `time` (default: the middle of its range):
    (positions as elements x particles x 3, output, messages)."""
    tracer = BoundParticleTracer(Input=source, Vectors=list(vectors), **properties)
    times = list(tracer.TimestepValues)
    with bptest.CapturedMessages() as log:
        tracer.UpdatePipeline(times[len(times) // 2] if time is None else time)
    output = servermanager.Fetch(tracer)
    elements = tracer.NumberOfElements
    xyz = vtk_to_numpy(output.GetPoints().GetData()).astype(float)
    result = dict(xyz=xyz.reshape(elements, -1, 3) if len(xyz) else xyz, output=output,
                  messages=log.messages, times=times)
    Delete(tracer)
    return result


def field(output, name):
    array = output.GetFieldData().GetArray(name)
    return None if array is None else [array.GetValue(i) for i in range(array.GetNumberOfValues())]


def no_messages(name, result):
    bptest.check(not result["messages"], "%s: messages %s" % (name, result["messages"]))


def check_close(name, result, reference, share, percentile=100):
    """`percentile`% of the elements within `share` of the field's diagonal
    of the reference's."""
    a, b = result["xyz"], reference["xyz"]
    if a.shape != b.shape or not len(a):
        bptest.check(False, "%s: %s points, the image path %s" % (name, a.shape, b.shape))
        return
    diagonal = numpy.linalg.norm(b.reshape(-1, 3).max(0) - b.reshape(-1, 3).min(0))
    # On another grid, an element the chaotic flow parts from its twin, or
    # one released again elsewhere, differs whole: most must stay close.
    error = float(numpy.percentile(abs(a - b).max(axis=(1, 2)), percentile))
    print("%s: %g%% of elements within %.3g of the image path's (diagonal %.3g)" %
          (name, percentile, error, diagonal))
    bptest.check(error <= share * diagonal, "%s: positions differ by %g" % (name, error))


abc = updated(AnalyticFlow(Flow="ABC", Resolution=[20, 18, 16], Bounds=[0, 2, 0, 1.8, 0, 1.6]))
# Absolute step and size: grids of other cell sizes trace with the same ones.
settings = dict(ElementShape="Cross", NumberOfElements=300, Seed=3, Duration=0.5,
                NumberOfTimeSteps=6, StepSizeUnit="Time", StepSize=0.02, ElementSize=0.1,
                EmitterCenter=[1.0, 0.9, 0.8], EmitterSize=[1.6, 1.4, 1.2])
image = traced(abc, 0.5, **settings)
no_messages("image", image)

# Tetrahedra: every grid point of the image's size is a mesh point, so the
# resampled field is the image's.
tets = updated(Tetrahedralize(Input=abc))
same = traced(tets, 0.5, ResampleDimensions=[20, 18, 16], **settings)
no_messages("tets", same)
bptest.check(field(same["output"], "ResampledDimensions") == [20, 18, 16],
             "tets: the grid asked for, %s" % field(same["output"], "ResampledDimensions"))
check_close("tets on the image's grid", same, image, 1e-5)
automatic = traced(tets, 0.5, **settings)
no_messages("tets, automatic grid", automatic)
dims = field(automatic["output"], "ResampledDimensions")
cells = tets.GetDataInformation().GetNumberOfCells()
bptest.check(dims is not None and 0.8 < numpy.prod(dims) / cells < 1.25,
             "tets: about as many grid points as cells (%s for %d)" % (dims, cells))
spacing = field(automatic["output"], "ResampledSpacing")
bptest.check(spacing is not None and max(spacing) / min(spacing) < 1.1,
             "tets: cells close to cubes, spacing %s" % spacing)
check_close("tets on the automatic grid", automatic, image, 0.01, percentile=80)

# Two curvilinear zones sharing the face x = 1, cut from one image: their
# points are the image's.
fine = updated(AnalyticFlow(Flow="ABC", Resolution=[21, 18, 16], Bounds=[0, 2, 0, 1.8, 0, 1.6]))
zones = updated(GroupDatasets(Input=[
    ImageDatatoPointSet(Input=ExtractSubset(Input=fine, VOI=[0, 10, 0, 17, 0, 15])),
    ImageDatatoPointSet(Input=ExtractSubset(Input=fine, VOI=[10, 20, 0, 17, 0, 15]))]))
joined = traced(zones, 0.5, ResampleDimensions=[21, 18, 16], **settings)
no_messages("zones", joined)
on_fine = traced(fine, 0.5, **settings)
check_close("zones", joined, on_fine, 1e-5)

# A curved annulus, r in [1, 2], in solid-body rotation (the interpolation
# of a linear field is exact in any hexahedron): elements circle at the
# rate and stay out of the hole.
annulus = ProgrammableSource(OutputDataSetType="vtkStructuredGrid")
annulus.Script = """
import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
nr, nt, nz = 9, 73, 5
r, t, z = numpy.meshgrid(numpy.linspace(1, 2, nr), numpy.linspace(0, 2 * numpy.pi, nt),
                         numpy.linspace(0, 0.5, nz), indexing="ij")
xyz = numpy.stack([r * numpy.cos(t), r * numpy.sin(t), z], -1).transpose(2, 1, 0, 3).reshape(-1, 3)
out = self.GetOutput()
out.SetDimensions(nr, nt, nz)
points = vtkPoints(); points.SetData(numpy_to_vtk(xyz.copy(), deep=1)); out.SetPoints(points)
v = numpy_to_vtk(numpy.stack([-xyz[:, 1], xyz[:, 0], 0 * xyz[:, 2]], -1).copy(), deep=1)
v.SetName("velocity"); out.GetPointData().AddArray(v)
"""
annulus.ScriptRequestInformation = """
from paraview import util
util.SetOutputWholeExtent(self, [0, 8, 0, 72, 0, 4])
"""
updated(annulus)
turn = 0.6
circle = traced(annulus, turn, ElementShape="Square", NumberOfElements=400, Seed=5,
               Duration=turn, NumberOfTimeSteps=7, Integrator="Runge-Kutta 4",
               LifetimeRange=[100, 100], EmitterCenter=[1.5, 0, 0.25],
               EmitterSize=[0.6, 0.6, 0.4], MinimumReleaseSpeed=0)
start = traced(annulus, 0.0, ElementShape="Square", NumberOfElements=400, Seed=5,
              Duration=turn, NumberOfTimeSteps=7, Integrator="Runge-Kutta 4",
              LifetimeRange=[100, 100], EmitterCenter=[1.5, 0, 0.25],
              EmitterSize=[0.6, 0.6, 0.4], MinimumReleaseSpeed=0)
no_messages("curvilinear", circle)
if len(circle["xyz"]) and len(start["xyz"]):
    before, after = start["xyz"].mean(1), circle["xyz"].mean(1)
    angle = numpy.arctan2(after[:, 1], after[:, 0]) - numpy.arctan2(before[:, 1], before[:, 0])
    angle = (angle + math.pi) % (2 * math.pi) - math.pi
    radius = numpy.hypot(after[:, 0], after[:, 1])
    print("curvilinear: turned %.4f rad (expected %.4f), radius %.3f..%.3f" %
          (numpy.median(angle), turn, radius.min(), radius.max()))
    bptest.check(abs(numpy.median(angle) - turn) < 0.01 * turn,
                 "curvilinear: elements turn at the rotation rate (%g)" % numpy.median(angle))
    bptest.check(radius.min() > 1.0, "curvilinear: an element centre in the hole (r = %g)" %
                 radius.min())
else:
    bptest.check(False, "curvilinear: no output")
# Releases never in the hole, on the grid of a real CFD user (automatic).
released = traced(annulus, 0.05, ElementShape="Point", NumberOfElements=3000, Seed=2,
                 Duration=turn, NumberOfTimeSteps=7)
radius = numpy.hypot(released["xyz"][:, :, 0], released["xyz"][:, :, 1]).ravel()
bptest.check(len(radius) and radius.min() > 0.95,
             "curvilinear: releases in the hole (r = %g)" % (radius.min() if len(radius) else 0))

# Cell-only vectors, no Cell Data to Point Data: the cell's value where a
# grid point lies (as ParaView's resamplers take cell data).
cell_only = updated(PointDatatoCellData(Input=tets))
cell_only.PassPointData = 0
updated(cell_only)
cell_trace = traced(cell_only, 0.5, vectors=("CELLS", "velocity"), **settings)
no_messages("cells", cell_trace)
speed = vtk_to_numpy(cell_trace["output"].GetPointData().GetArray("Speed"))
bptest.check((speed > 0.05).mean() > 0.9, "cells: elements move (%.2f)" % (speed > 0.05).mean())
check_close("cells", cell_trace, image, 0.01, percentile=50)

# A flat triangulated mesh at z = 0.5: a one-layer grid, elements in its plane.
plane = Plane(Origin=[-1, -1, 0.5], Point1=[1, -1, 0.5], Point2=[-1, 1, 0.5], XResolution=40,
              YResolution=40)
vortex = Calculator(Input=Triangulate(Input=plane), ResultArrayName="velocity",
                    Function="-coordsY*iHat + coordsX*jHat")
flat = traced(updated(vortex), ElementShape="Strip8", NumberOfElements=200, Seed=1,
             Duration=1.0, NumberOfTimeSteps=11)
no_messages("flat", flat)
dims = field(flat["output"], "ResampledDimensions")
bptest.check(dims is not None and dims[2] == 1, "flat: a one-layer grid (%s)" % dims)
z = flat["xyz"][:, :, 2] if len(flat["xyz"]) else numpy.array([0.0])
bptest.check(len(flat["xyz"]) and abs(z - 0.5).max() < 1e-6,
             "flat: elements leave the plane by %g" % abs(z - 0.5).max())

# An unsteady mesh: the double gyre's steps on tetrahedra, only the vectors
# change. The same time line and trace as on the image.
gyre = updated(AnalyticFlow(Flow="Double Gyre", Resolution=[33, 17, 2],
                            Bounds=[0, 2, 0, 1, 0, 0.05], NumberOfTimeSteps=5))
moving = updated(Tetrahedralize(Input=gyre))
unsteady_settings = dict(ElementShape="Point", NumberOfElements=500, Seed=7)
on_image = traced(gyre, **unsteady_settings)
on_mesh = traced(moving, ResampleDimensions=[33, 17, 2], **unsteady_settings)
no_messages("unsteady", on_mesh)
bptest.check(on_mesh["times"] == on_image["times"],
             "unsteady: the image's time line (%d values, %d)" %
             (len(on_mesh["times"]), len(on_image["times"])))
check_close("unsteady", on_mesh, on_image, 1e-5)

# The GPU engine in the Bound Particles display steps on the resampled grid
# as on an image: the same picture of the same elements.
def gpu_picture(source, name, **properties):
    tracer = BoundParticleTracer(Input=source, Vectors=["POINTS", "velocity"], Engine="GPU",
                                 **properties)
    view = bptest.element_view([300, 300])
    view.ViewTime = 0.5
    shown = Show(tracer, view)
    shown.SetRepresentationType("Bound Particles")
    bptest.colour_display(shown, None, None)
    # Show resets the camera of a new view only when it already knows the
    # data's bounds: one camera for both pictures.
    view.CameraPosition = [4.2, 3.2, 5.4]
    view.CameraFocalPoint = [1.0, 0.9, 0.8]
    with bptest.CapturedMessages() as log:
        Render(view)
    path = bptest.save_picture(view, tempfile.gettempdir(), name)
    Delete(tracer)
    return path, log.messages


on_grid, grid_messages = gpu_picture(abc, "bp-mesh-gpu-image", ResampleDimensions=[20, 18, 16],
                                     **settings)
on_tets, tets_messages = gpu_picture(tets, "bp-mesh-gpu-tets", ResampleDimensions=[20, 18, 16],
                                     **settings)
bptest.check(not tets_messages, "GPU on tets: messages %s" % tets_messages)
covered = bptest.covered_fraction(on_tets)
mean, pixels = bptest.image_difference(on_grid, on_tets)
print("GPU on tets: %.3f of the picture covered; against the image's: mean %.3f, pixels %.4f" %
      (covered, mean, pixels))
bptest.check(covered > 0.01, "GPU on tets: nothing drawn (%.4f)" % covered)
bptest.check(mean <= 1.0 and pixels <= 0.005, "GPU on tets: not the image's picture")

bptest.finish()
