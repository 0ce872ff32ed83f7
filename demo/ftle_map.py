"""The double gyre's FTLE map from elements, next to one computed independently.

Spring-free crosses (Restoration Iterations 0) released on a lattice over the
gyres and traced to T = 10 (one period) carry ElementFTLE, ln(largest
stretch) / age; put back at the lattice points they were released from,
they are the tracer's second output, the FTLE map. The picture shows it on
the left and, on the right, the FTLE of the same lattice computed here in
numpy: the flow map integrated with RK4 through the same sampled field
(bilinear in space, linear in time, as the tracer samples it), finite
differences over +-delta, the largest eigenvalue of the Cauchy-Green tensor.

    pvpython demo/ftle_map.py --plugin BoundParticles.so --output docs

It also writes ftle-forward-backward.png: the same map traced forward beside
the one traced backward (Time Direction = Backward: released at T, traced
back to 0), whose ridges are the gyre's attracting structures.
"""
import os
import sys

import numpy as np

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import apply_preset, dark_view, look_down, picture_arguments  # noqa: E402

T = 10.0          # one period of the gyre
STEP = 0.02       # the tracer's step and the reference's, in time units
SIZE = 0.01       # element size: small against the gyres
COUNTS = (120, 60)  # the lattice over [0, 2] x [0, 1]: Lattice's own counts for 7,200


def lattice_points(counts=COUNTS, box=(0.0, 2.0, 0.0, 1.0)):
    """Cell centres of counts[0] x counts[1] cells over `box`, x fastest
    (as Core/Release/ReleaseLattice places Release Pattern = Lattice)."""
    sx = (box[1] - box[0]) / counts[0]
    sy = (box[3] - box[2]) / counts[1]
    x = box[0] + (np.arange(counts[0]) + 0.5) * sx
    y = box[2] + (np.arange(counts[1]) + 0.5) * sy
    X, Y = np.meshgrid(x, y)
    return np.column_stack([X.ravel(), Y.ravel()])


def gyre_scene(engine="CPU", counts=COUNTS, lattice=True):
    """The double gyre (one z layer's thickness) and a tracer of spring-free
    crosses on the lattice: Release Pattern = Lattice, or (`lattice` False)
    seed points at the lattice's points, which place element e at point e
    alike."""
    flow = AnalyticFlow(Flow="Double Gyre", Resolution=[129, 65, 2],
                        Bounds=[0.0, 2.0, 0.0, 1.0, -0.01, 0.01],
                        NumberOfTimeSteps=int(round(T / 0.5)) + 1)
    flow.UpdatePipeline(0.0)
    n = counts[0] * counts[1]
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                 ElementShape="Cross", RestorationIterations=0,
                                 NumberOfElements=n, ElementSize=SIZE,
                                 ReleaseOrientation="Fixed", Integrator="Runge-Kutta 4",
                                 StepSizeUnit="Time", StepSize=STEP, FramesPerInputStep=1,
                                 LifetimeRange=[2 * T, 2 * T], MinimumReleaseSpeed=0.0,
                                 Engine=engine)
    tracer.OutputArrays = ["ElementFTLE", "ElementStretch", "ElementId", "ParticleIndex"]
    if lattice:
        tracer.ReleasePattern = "Lattice"
        tracer.EmitterCenter = [1.0, 0.5, 0.0]
        tracer.EmitterSize = [2.0, 1.0, 0.0]
    else:
        p = lattice_points(counts)
        seeds = PolyLineSource(Points=list(np.column_stack([p, np.zeros(len(p))]).ravel()))
        tracer.SeedSource = seeds
    return flow, tracer


def sampled_field(flow, times):
    """The flow's grid (origin, spacing, dims) and its (x, y) vectors at each
    of `times`, as arrays [time, y, x, 2] of the first z layer."""
    values = []
    for t in times:
        flow.UpdatePipeline(t)
        data = flow.GetClientSideObject().GetOutputDataObject(0)
        dims = data.GetDimensions()
        v = vtk_to_numpy(data.GetPointData().GetArray("velocity")).astype(np.float64)
        values.append(v.reshape(dims[2], dims[1], dims[0], 3)[0, :, :, :2])
    return np.array(data.GetOrigin()), np.array(data.GetSpacing()), dims, np.array(values)


def velocity(field, times, t, p):
    """The field at points p (n x 2) at time t: bilinear between the grid's
    points, linear between its time steps (the tracer's sampling)."""
    origin, spacing, dims, v = field
    k = int(np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(times) - 2))
    w = np.clip((t - times[k]) / (times[k + 1] - times[k]), 0.0, 1.0)
    g = np.clip((p - origin[:2]) / spacing[:2], 0.0, [dims[0] - 1, dims[1] - 1])
    i = np.minimum(np.floor(g).astype(int), [dims[0] - 2, dims[1] - 2])
    f = g - i
    out = np.zeros_like(p)
    for s in (0, 1):
        slab = v[k + s]
        ws = w if s else 1.0 - w
        out += ws * ((1 - f[:, :1]) * (1 - f[:, 1:]) * slab[i[:, 1], i[:, 0]] +
                     f[:, :1] * (1 - f[:, 1:]) * slab[i[:, 1], i[:, 0] + 1] +
                     (1 - f[:, :1]) * f[:, 1:] * slab[i[:, 1] + 1, i[:, 0]] +
                     f[:, :1] * f[:, 1:] * slab[i[:, 1] + 1, i[:, 0] + 1])
    return out


def analytic_velocity(field, times, t, p):
    """The double gyre's formula itself (Shadden et al. 2005: A = 0.1,
    epsilon = 0.25, omega = 2 pi / 10) on [0, 2] x [0, 1], not its samples."""
    A, eps, omega = 0.1, 0.25, 2 * np.pi / 10.0
    a = eps * np.sin(omega * t)
    b = 1.0 - 2.0 * a
    x, y = p[:, 0], p[:, 1]
    f = a * x * x + b * x
    return np.column_stack([-np.pi * A * np.sin(np.pi * f) * np.cos(np.pi * y),
                            np.pi * A * np.cos(np.pi * f) * np.sin(np.pi * y) * (2 * a * x + b)])


def flow_map(field, times, p, t_end, h=STEP, sample=velocity, t_start=0.0):
    """Classic RK4 from t_start to t_end (backward where t_end < t_start)."""
    p = p.copy()
    steps = int(round(abs(t_end - t_start) / h))
    h = h if t_end >= t_start else -h
    for s in range(steps):
        t = t_start + s * h
        k1 = sample(field, times, t, p)
        k2 = sample(field, times, t + h / 2, p + h / 2 * k1)
        k3 = sample(field, times, t + h / 2, p + h / 2 * k2)
        k4 = sample(field, times, t + h, p + h * k3)
        p += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return p


def reference_ftle(field, times, points, t_end, delta, sample=velocity, t_start=0.0):
    """FTLE of each point: central differences of the flow map from t_start
    to t_end over +-delta along x and y, the Cauchy-Green tensor C = F^T F,
    ln(sqrt(max eig C)) / |t_end - t_start| (backward: attracting structures)."""
    n = len(points)
    offsets = np.array([[delta, 0], [-delta, 0], [0, delta], [0, -delta]])
    moved = flow_map(field, times, np.concatenate([points + o for o in offsets]), t_end,
                     sample=sample, t_start=t_start)
    xp, xm, yp, ym = (moved[k * n:(k + 1) * n] for k in range(4))
    F = np.stack([(xp - xm) / (2 * delta), (yp - ym) / (2 * delta)], axis=2)  # n x 2 x 2
    C = np.einsum("nki,nkj->nij", F, F)
    largest = np.linalg.eigvalsh(C)[:, -1]
    return np.log(np.sqrt(largest)) / abs(t_end - t_start)


def element_ftle(tracer, n):
    """ElementFTLE of elements 0..n-1 from the tracer's elements (port 0),
    and whether each was found."""
    data = servermanager.Fetch(tracer)
    pd = data.GetPointData()
    ids = vtk_to_numpy(pd.GetArray("ElementId"))
    first = vtk_to_numpy(pd.GetArray("ParticleIndex")) == 0
    ftle = np.zeros(n)
    found = np.zeros(n, dtype=bool)
    keep = first & (ids < n)
    ftle[ids[keep]] = vtk_to_numpy(pd.GetArray("ElementFTLE"))[keep]
    found[ids[keep]] = True
    return ftle, found


def ftle_image(tracer):
    """The tracer's FTLE map (port 1): its points (n x 2), FTLE and mask."""
    image = servermanager.Fetch(tracer, 0, None, 1)  # process 0's: the whole map
    dims = image.GetDimensions()
    n = dims[0] * dims[1] * dims[2]
    points = np.array([image.GetPoint(k)[:2] for k in range(n)])
    pd = image.GetPointData()
    return (image, points, vtk_to_numpy(pd.GetArray("FTLE")).astype(np.float64),
            vtk_to_numpy(pd.GetArray("vtkValidPointMask")) > 0)


def compare(elements, reference, valid):
    """How alike two FTLE maps are over the valid points: their correlation,
    the overlap of their ridges (the share of the reference's top 10% that is
    in the elements' top 10%), and the median relative difference where the
    reference is above a third of its largest value."""
    a, b = elements[valid], reference[valid]
    correlation = float(np.corrcoef(a, b)[0, 1])
    top = max(1, len(b) // 10)
    ridge_b = set(np.argsort(b)[-top:])
    ridge_a = set(np.argsort(a)[-top:])
    overlap = len(ridge_a & ridge_b) / float(top)
    strong = b > b.max() / 3.0
    median = float(np.median(np.abs(a[strong] - b[strong]) / b[strong]))
    return {"correlation": correlation, "ridge_overlap": overlap,
            "median_relative_error": median, "points": int(valid.sum()),
            "strong": int(strong.sum())}


def both_maps(flow, tracer, counts=COUNTS):
    """The elements' map and the reference at the lattice points (n x 2)."""
    tracer.UpdatePipeline(T)
    times = np.arange(0.0, T + 0.25, 0.5)
    field = sampled_field(flow, times)
    if tracer.ReleasePattern == "Lattice":
        _, points, elements, valid = ftle_image(tracer)
    else:
        points = lattice_points(counts)
        elements, valid = element_ftle(tracer, len(points))
    reference = reference_ftle(field, times, points, T, SIZE / 2)
    return points, elements, reference, valid, (field, times)


def image_of(values, counts, origin):
    """A vtkImageData of the lattice's values, its first point at `origin`."""
    image = vtkImageData()
    image.SetDimensions(counts[0], counts[1], 1)
    image.SetOrigin(origin[0], origin[1], 0.0)
    image.SetSpacing(2.0 / counts[0], 1.0 / counts[1], 1.0)
    array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float32), deep=1)
    array.SetName("FTLE")
    image.GetPointData().SetScalars(array)
    return image


def main():
    args = picture_arguments(__doc__)
    LoadPlugin(args.plugin, ns=globals())
    flow, tracer = gyre_scene()
    points, elements, reference, valid, _ = both_maps(flow, tracer)
    stats = compare(elements, reference, valid)
    print("FTLE map from elements against numpy: " + ", ".join(
        "%s %.3g" % (k, v) for k, v in sorted(stats.items())))
    # The tracer's map as it is (FTLE 0 where a point is not valid), and
    # numpy's beside it.
    first = points[0]
    numpy_map = TrivialProducer()
    numpy_map.GetClientSideObject().SetOutput(
        image_of(reference, COUNTS, (first[0] + 2.15, first[1])))
    save_two_maps(args, (OutputPort(tracer, 1), numpy_map),
                  (("elements (ElementFTLE)", 0.19), ("numpy (flow map)", 0.68)),
                  np.percentile(reference, 99.5), "ftle-map.png")
    forward_and_backward(args, flow, tracer, points, reference)


def forward_and_backward(args, flow, tracer, points, forward_reference):
    """The picture of Time Direction: the forward map (repelling structures,
    released at 0 and traced to T) beside the backward one (attracting
    structures, released at T and traced back to 0), both from elements."""
    _, backward = gyre_scene()
    backward.TimeDirection = "Backward"
    backward.UpdatePipeline(0.0)
    image, _, values, found = ftle_image(backward)
    times = np.arange(0.0, T + 0.25, 0.5)
    field = sampled_field(flow, times)
    reference = reference_ftle(field, times, points, 0.0, SIZE / 2, t_start=T)
    stats = compare(values, reference, found)
    print("backward FTLE map from elements against numpy: " + ", ".join(
        "%s %.3g" % (k, v) for k, v in sorted(stats.items())))
    # The backward map as it was at time 0, beside the forward one at T.
    shifted = vtkImageData()
    shifted.DeepCopy(image)
    origin = image.GetOrigin()
    shifted.SetOrigin(origin[0] + 2.15, origin[1], origin[2])
    backward_map = TrivialProducer()
    backward_map.GetClientSideObject().SetOutput(shifted)
    top = max(np.percentile(forward_reference, 99.5), np.percentile(reference, 99.5))
    save_two_maps(args, (OutputPort(tracer, 1), backward_map),
                  (("forward, 0 to 10: repelling", 0.15), ("backward, 10 to 0: attracting", 0.63)),
                  top, "ftle-forward-backward.png")


def save_two_maps(args, ports, labels, top, name):
    """Two FTLE maps side by side at time T, each with its label (text, x),
    coloured 0 to `top`, saved as `name` in the output folder."""
    view = dark_view(T, size=(1600, 620))
    view.EnableRenderOnInteraction = 0
    lut = GetColorTransferFunction("FTLE")
    apply_preset(lut, "Inferno (matplotlib)")
    lut.RescaleTransferFunction(0.0, float(top))
    for port in ports:
        display = Show(port, view)
        display.SetRepresentationType("Slice")
        ColorBy(display, ("POINTS", "FTLE"))
        display.LookupTable = lut
    for text, x in labels:
        label = Text(Text=text)
        shown = Show(label, view)
        shown.WindowLocation = "Any Location"
        shown.Position = [x, 0.83]
        shown.FontSize = 14
    look_down(view, 2.075, 0.5, 0.85)
    path = os.path.join(args.output, name)
    SaveScreenshot(path, view, ImageResolution=[1600, 620])
    print("wrote " + path)
    Delete(view)

if __name__ == "__main__":
    main()
