"""The tracer's output arrays, checked against references computed the slow way.

The output is built fast (ranges handed over with the arrays, Velocity and
Vorticity from one cell, array memory reused between frames); this checks
that nothing a user colours by changed for it:
- every array's values against numpy: Velocity and Vorticity from the field's
  grid points (trilinear, and the curl of the cell's trilinear interpolant,
  blended between time steps), Speed from Velocity, Normals from the
  triangles of the output's strips;
- every range ParaView reads (per component, finite, magnitude) against numpy,
  with trails too (their points follow the elements'), and a Surface display
  coloured by each array rescales to that range;
- an earlier frame held by someone else is never overwritten;
- Output Arrays: only the arrays asked for, the same values, the same trace.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()


def field_at(flow, t):
    """The flow's grid (origin, spacing, dims) and its vectors at time t, blended
    between the two time steps around t as the tracer blends them."""
    times = list(flow.TimestepValues or [])
    if len(times) < 2:  # steady
        times = [t, t + 1.0]
    k = max(0, min(len(times) - 2, int(np.searchsorted(times, t, side="right")) - 1))
    slices = []
    for time in (times[k], times[k + 1]):
        flow.UpdatePipeline(time)
        data = flow.GetClientSideObject().GetOutputDataObject(0)
        dims = data.GetDimensions()
        values = vtk_to_numpy(data.GetPointData().GetVectors()).astype(np.float64)
        slices.append(values.reshape(dims[2], dims[1], dims[0], 3))
    w = 0.0 if t <= times[k] else min(1.0, (t - times[k]) / (times[k + 1] - times[k]))
    return (np.array(data.GetOrigin()), np.array(data.GetSpacing()), np.array(dims),
            slices[0] + w * (slices[1] - slices[0]))


def reference_samples(grid, positions):
    """Trilinear velocity and |curl| of the cell's interpolant at each position."""
    origin, spacing, dims, v = grid
    g = np.clip((positions - origin) / spacing, 0, dims - 1)
    cell = np.minimum(np.floor(g), np.maximum(dims - 2, 0)).astype(int)
    f = g - cell
    nxt = np.minimum(cell + 1, dims - 1)
    velocity = np.zeros((len(positions), 3))
    d = np.zeros((len(positions), 3, 3))  # d[:, a, k] = d v_k / d x_a
    for cx in (0, 1):
        for cy in (0, 1):
            for cz in (0, 1):
                corner = v[(nxt if cz else cell)[:, 2], (nxt if cy else cell)[:, 1],
                           (nxt if cx else cell)[:, 0]]
                wx = f[:, 0] if cx else 1 - f[:, 0]
                wy = f[:, 1] if cy else 1 - f[:, 1]
                wz = f[:, 2] if cz else 1 - f[:, 2]
                velocity += (wx * wy * wz)[:, None] * corner
                for a, (w0, w1, c) in enumerate(((wy, wz, cx), (wx, wz, cy), (wx, wy, cz))):
                    sign = 1.0 if c else -1.0
                    flat = dims[a] <= 1
                    d[:, a, :] += 0.0 if flat else (sign * w0 * w1 / spacing[a])[:, None] * corner
    curl = np.stack([d[:, 1, 2] - d[:, 2, 1], d[:, 2, 0] - d[:, 0, 2], d[:, 0, 1] - d[:, 1, 0]], 1)
    return velocity, np.linalg.norm(curl, axis=1)


def numpy_ranges(values):
    """What VTK's GetRange reports: per component, and the magnitude of tuples
    (the squared sum in the array's own type)."""
    columns = values.reshape(len(values), -1)
    per_component = [(columns[:, c].min(), columns[:, c].max()) for c in range(columns.shape[1])]
    squared = (columns * columns).sum(axis=1, dtype=columns.dtype)
    magnitude = (np.sqrt(squared.min().astype(np.float64)), np.sqrt(squared.max().astype(np.float64)))
    return per_component, magnitude


def check_ranges(name, array, values):
    per_component, magnitude = numpy_ranges(values)
    for c, expected in enumerate(per_component):
        got, finite = array.GetRange(c), array.GetFiniteRange(c)
        bptest.check(got == tuple(float(x) for x in expected) and finite == got,
                     "%s component %d: range %s, finite %s, numpy %s" % (name, c, got, finite, expected))
    if array.GetNumberOfComponents() > 1:
        got = array.GetRange(-1)
        bptest.check(np.allclose(got, magnitude, rtol=1e-7, atol=0),
                     "%s magnitude: range %s, numpy %s" % (name, got, magnitude))


def reference_normals(out):
    """Each particle's normal the slow way: the mean of the unit normals of
    the triangles of its element's strip (VTK's strip order), normalised."""
    points = vtk_to_numpy(out.GetPoints().GetData()).astype(np.float64)
    strips = out.GetStrips()
    offsets = vtk_to_numpy(strips.GetOffsetsArray())
    ids = vtk_to_numpy(strips.GetConnectivityArray())
    sums = np.zeros_like(points)
    for c in range(len(offsets) - 1):
        strip = ids[offsets[c]:offsets[c + 1]]
        for j in range(len(strip) - 2):
            a, b, d = strip[j], strip[j + 1], strip[j + 2]
            if j % 2:
                a, b = b, a
            normal = np.cross(points[b] - points[a], points[d] - points[a])
            length = np.linalg.norm(normal)
            if length > 0:
                sums[[a, b, d]] += normal / length
    lengths = np.linalg.norm(sums, axis=1)
    normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))
    used = lengths > 0
    normals[used] = sums[used] / lengths[used, None]
    return normals


def check_frame(label, tracer, flow, t):
    tracer.UpdatePipeline(t)
    out = tracer.GetClientSideObject().GetOutputDataObject(0)
    pd = out.GetPointData()
    positions = vtk_to_numpy(out.GetPoints().GetData()).astype(np.float64)
    velocity, vorticity = reference_samples(field_at(flow, t), positions)
    scale = np.abs(velocity).max()
    got_velocity = vtk_to_numpy(pd.GetArray("Velocity")).astype(np.float64)
    bptest.check(np.abs(got_velocity - velocity).max() <= 1e-5 * scale,
                 "%s: Velocity off by %.3g" % (label, np.abs(got_velocity - velocity).max()))
    got_vorticity = vtk_to_numpy(pd.GetArray("Vorticity")).astype(np.float64)
    worst = np.abs(got_vorticity - vorticity).max()
    bptest.check(worst <= 1e-4 * max(1.0, vorticity.max()),
                 "%s: Vorticity off by %.3g (largest %.3g)" % (label, worst, vorticity.max()))
    speed = vtk_to_numpy(pd.GetArray("Speed")).astype(np.float64)
    bptest.check(np.allclose(speed, np.linalg.norm(got_velocity, axis=1), rtol=1e-6, atol=1e-7),
                 "%s: Speed is |Velocity|" % label)
    normals = vtk_to_numpy(pd.GetArray("Normals")).astype(np.float64)
    worst = np.abs(normals - reference_normals(out)).max()
    bptest.check(worst <= 1e-5, "%s: Normals off by %.3g" % (label, worst))
    check_ranges("%s Points" % label, out.GetPoints().GetData(), vtk_to_numpy(out.GetPoints().GetData()))
    for i in range(pd.GetNumberOfArrays()):
        array = pd.GetArray(i)
        check_ranges("%s %s" % (label, array.GetName()), array, vtk_to_numpy(array))
    return out


for flow_name in ("Shear Layer", "Double Gyre"):
    flow = AnalyticFlow(Flow=flow_name, Resolution=[24, 20, 12])
    flow.UpdatePipeline()  # the emitter box then spans its bounds (ParaView 6: not before)
    tracer = BoundParticleTracer(Input=flow, ElementShape="Strip16", NumberOfElements=300,
                                 Seed=4, Engine="CPU")
    times = list(tracer.TimestepValues)
    held = []
    for k in (1, 2, 3, 7):
        out = check_frame("%s t=%.3g" % (flow_name, times[k]), tracer, flow, times[k])
        copy = vtkPolyData()
        copy.ShallowCopy(out)  # a consumer that keeps this frame
        held.append((copy, vtk_to_numpy(copy.GetPoints().GetData()).copy(),
                     vtk_to_numpy(copy.GetPointData().GetArray("Force")).copy()))
    for copy, points, force in held:
        bptest.check(np.array_equal(vtk_to_numpy(copy.GetPoints().GetData()), points) and
                     np.array_equal(vtk_to_numpy(copy.GetPointData().GetArray("Force")), force),
                     "%s: a frame someone holds is never written over" % flow_name)

    # Coloured by each array, a display rescales to the array's range.
    view = CreateRenderView(ViewSize=[200, 150])
    shown = Show(tracer, view)
    view.ViewTime = times[4]
    tracer.UpdatePipeline(times[4])  # the source's data information, which rescaling reads
    Render(view)
    data = tracer.GetClientSideObject().GetOutputDataObject(0)
    for name in ("Velocity", "Speed", "Force", "Lifetime", "ElementId", "ParticleIndex",
                 "Vorticity", "Layer", "Radius"):
        ColorBy(shown, ("POINTS", name))
        shown.RescaleTransferFunctionToDataRange(False, True)
        lut_range = GetColorTransferFunction(name).RGBPoints[0::4]
        values = vtk_to_numpy(data.GetPointData().GetArray(name))
        per_component, magnitude = numpy_ranges(values)
        expected = magnitude if values.ndim > 1 else per_component[0]
        bptest.check(np.allclose([lut_range[0], lut_range[-1]], expected, rtol=1e-6, atol=1e-12),
                     "%s: coloured by %s the map spans %s, the data %s"
                     % (flow_name, name, (lut_range[0], lut_range[-1]), expected))
    Delete(shown)
    Delete(view)
    Delete(tracer)
    Delete(flow)

# With trails, the ranges cover the trail poses' points as well as the elements'.
flow = AnalyticFlow(Flow="Shear Layer", Resolution=[24, 20, 12])
flow.UpdatePipeline()  # the emitter box then spans its bounds (ParaView 6: not before)
tracer = BoundParticleTracer(Input=flow, ElementShape="Strip16", NumberOfElements=300, Seed=4,
                             Engine="CPU", Trails=1, TrailLength=4, TrailSpacing=1)
tracer.UpdatePipeline(list(tracer.TimestepValues)[6])
out = tracer.GetClientSideObject().GetOutputDataObject(0)
bptest.check(out.GetNumberOfPoints() > 300 * 16, "trails add points (%d)" % out.GetNumberOfPoints())
check_ranges("trails Points", out.GetPoints().GetData(), vtk_to_numpy(out.GetPoints().GetData()))
for i in range(out.GetPointData().GetNumberOfArrays()):
    array = out.GetPointData().GetArray(i)
    check_ranges("trails %s" % array.GetName(), array, vtk_to_numpy(array))
Delete(tracer)
Delete(flow)

# Output Arrays: only the arrays asked for, each as in the full output; the
# trace itself is the same whatever is asked for.
flow = AnalyticFlow(Flow="Double Gyre", Resolution=[24, 20, 12])
flow.UpdatePipeline()  # the emitter box then spans its bounds (ParaView 6: not before)
full = BoundParticleTracer(Input=flow, ElementShape="Strip16", NumberOfElements=300, Seed=4)
narrow = BoundParticleTracer(Input=flow, ElementShape="Strip16", NumberOfElements=300, Seed=4,
                             OutputArrays=["Force", "Speed"])
t = list(full.TimestepValues)[5]
for tracer in (full, narrow):
    tracer.UpdatePipeline(t)
whole = full.GetClientSideObject().GetOutputDataObject(0)
part = narrow.GetClientSideObject().GetOutputDataObject(0)
names = sorted(part.GetPointData().GetArrayName(i) for i in range(part.GetPointData().GetNumberOfArrays()))
bptest.check(names == ["Force", "Speed"], "Output Arrays Force, Speed: the output has %s" % names)
bptest.check(np.array_equal(vtk_to_numpy(part.GetPoints().GetData()),
                            vtk_to_numpy(whole.GetPoints().GetData())),
             "the trace does not depend on the output arrays")
for name in ("Force", "Speed"):
    bptest.check(np.array_equal(vtk_to_numpy(part.GetPointData().GetArray(name)),
                                vtk_to_numpy(whole.GetPointData().GetArray(name))),
                 "%s is the same with Velocity left out" % name)
narrow.OutputArrays = ["Vorticity"]
narrow.UpdatePipeline(t)
part = narrow.GetClientSideObject().GetOutputDataObject(0)
bptest.check(np.array_equal(vtk_to_numpy(part.GetPointData().GetArray("Vorticity")),
                             vtk_to_numpy(whole.GetPointData().GetArray("Vorticity"))),
             "Vorticity is the same with Velocity left out")
narrow.ComputeVorticity = 0
narrow.UpdatePipeline(t)
part = narrow.GetClientSideObject().GetOutputDataObject(0)
bptest.check(part.GetPointData().GetArray("Vorticity") is None,
             "Compute Vorticity off leaves Vorticity out even when ticked")

bptest.finish()
