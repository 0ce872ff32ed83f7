"""The Bound Particle Tracer on an unstructured mesh: what the resample onto a
uniform grid costs on the first frame, and what Play costs after it, beside
an image of the same size and ParaView's own Particle Tracer on the mesh.

The data, generated here and written to a temporary folder as one file per
time step with a .pvd (so both tracers read it as a user's would, a reader
re-reading a step it does not hold):
- mesh: the box [0,2] x [0,1] x [0,1], 2n x n x n hexahedra of 6 tetrahedra
  each (--cells, about 1 M by default; --cut 5 for five), interior points
  jittered by up to a tenth of a cell (--jitter) so that no cell lines up
  with the axes; the same points and cells at every time step, only the
  vectors change (--moving: the points jittered anew at every step);
- image: a uniform grid with the same points per axis (so the same number of
  points) over the same box;
- flow: the unsteady double gyre (the plugin's Analytic Flow), with a weak
  swirl in z that vanishes on the z faces, so nothing leaves the box; --steps
  time steps, 0.5 apart.
Each tracer releases one-particle elements from the same --seeds random
points (Seed Source), RK4 with two sub-steps per data interval, no
vorticity, lifetimes beyond the run; the Bound Particle Tracer offers one
frame per input time step (Frames Per Input Step 1; --frames-per-step N
offers N, of which N - 1 use the time steps held) and resamples the mesh
automatically (Resample Dimensions 0 0 0; --resample to set them).
Timed, in a fresh tracer each repeat (interleaved, medians of --repeats):
- first frame: UpdatePipeline at the first time, the reader holding another
  step (so a read, and for the mesh the resample, are included);
- following: UpdatePipeline at each later offered time in order, as Play
  does (the median frame).
Rows: the Bound Particle Tracer on the mesh, on the image of the same size,
ParaView's Particle Tracer (Mesh Over Time: Static) on the mesh, and the
Bound Particle Tracer on an image of the dimensions it resampled the mesh to
(the grid it steps on after the resample). Prints those dimensions (the
output field array ResampledDimensions, from an untimed first frame), then
the table: first frame, following frames, mesh/image per frame and Particle
Tracer/Bound on the mesh (first frame | following). Then where a following
frame's time goes: own, the tracer's own executions (between its Start and
End events, so the reader's work left out); reader, the reader's executions;
the slowest frame; how many times the reader executed on the first frame
and per following frame; and a replay in the same tracer (back to the first
time, then Play again: the kept interpolation weights and cached steps at
work). Last, how far the final positions lie from the mesh's (the same job).

    with-display.sh pvpython bench/unstructured.py --plugin BoundParticles.so [--cells 100000]
"""
import argparse
import itertools
import os
import shutil
import statistics
import sys
import tempfile
import time

import numpy
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_TETRA, vtkCellArray, vtkImageData, vtkPolyData,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLUnstructuredGridWriter

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", required=True)
parser.add_argument("--cells", type=float, default=1e6, help="tetrahedra in the mesh (about)")
parser.add_argument("--steps", type=int, default=11, help="data time steps")
parser.add_argument("--seeds", type=int, default=10000, help="elements (one particle each)")
parser.add_argument("--repeats", type=int, default=3)
parser.add_argument("--resample", type=int, nargs=3, metavar=("NX", "NY", "NZ"),
                    help="the tracer's Resample Dimensions (default automatic)")
parser.add_argument("--frames-per-step", type=int, default=1,
                    help="the Bound Particle Tracer's Frames Per Input Step: 1 (default) makes "
                         "every frame need a new time step; more plays frames from the steps "
                         "held (ParaView's tracer offers the input's times either way)")
parser.add_argument("--keep", metavar="DIR",
                    help="write the data here and keep it (default: a temporary folder)")
parser.add_argument("--cut", type=int, choices=(5, 6), default=6,
                    help="tetrahedra per hexahedron: 6 (default, along the main diagonal) or 5 "
                         "(a middle one and four corners, mirrored between neighbours)")
parser.add_argument("--jitter", type=float, default=0.1,
                    help="how far inner points move, in cells (default 0.1; 0: a regular lattice)")
parser.add_argument("--moving", action="store_true",
                    help="the inner points jittered anew at every time step (a moving mesh: "
                         "each step is searched again; ParaView's tracer with Mesh Over Time: "
                         "Different); by default the mesh is static and only the vectors change")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

DT = 0.5  # between data time steps, as the plugin's Analytic Flow
JITTER = args.jitter  # of a cell, per axis, interior points only (0.1 keeps every tetrahedron valid)


def gyre(xyz, t):
    """The double gyre on [0,2] x [0,1] (as Core/Field/AnalyticFlows.cpp) with a
    weak swirl in z that is 0 on z = 0 and z = 1; float32, N x 3."""
    x, y, z = xyz[:, 0], xyz[:, 1], xyz[:, 2]
    A, eps, omega = 0.1, 0.25, 2 * numpy.pi / 10.0
    a = eps * numpy.sin(omega * t)
    b = 1.0 - 2.0 * a
    f = a * x * x + b * x
    dfdx = 2.0 * a * x + b
    v = numpy.empty(xyz.shape, dtype=numpy.float32)
    v[:, 0] = -numpy.pi * A * numpy.sin(numpy.pi * f) * numpy.cos(numpy.pi * y)
    v[:, 1] = numpy.pi * A * numpy.cos(numpy.pi * f) * numpy.sin(numpy.pi * y) * dfdx
    v[:, 2] = 0.25 * numpy.pi * A * numpy.sin(numpy.pi * z) * numpy.cos(numpy.pi * f)
    return v


def grid_points(dims, spacing):
    """The points of a uniform grid at the origin, x fastest, N x 3."""
    k, j, i = numpy.meshgrid(*(numpy.arange(d) for d in dims[::-1]), indexing="ij")
    return numpy.stack([i.ravel() * spacing[0], j.ravel() * spacing[1], k.ravel() * spacing[2]],
                       axis=1)


def tetrahedra(dims):
    """6 tetrahedra per hexahedron (Kuhn: along each order of the three axes
    from the hexahedron's first corner to its last), or 5 (--cut 5: the
    corners of one parity around a middle one, mirrored between neighbours
    so that faces match), point ids, C x 4."""
    nx, ny, nz = dims
    k, j, i = numpy.meshgrid(numpy.arange(nz - 1), numpy.arange(ny - 1), numpy.arange(nx - 1),
                             indexing="ij")
    corner = (i + nx * (j + ny * k)).ravel().astype(numpy.int64)
    step = [1, nx, nx * ny]
    if args.cut == 5:
        # Corner c of a hexahedron: bit 0 along x, bit 1 along y, bit 2 along z.
        at = numpy.stack([corner + (c & 1) * step[0] + (c >> 1 & 1) * step[1] +
                          (c >> 2 & 1) * step[2] for c in range(8)], axis=1)
        even = [[0, 1, 2, 4], [1, 3, 2, 7], [1, 4, 5, 7], [2, 7, 6, 4], [1, 2, 4, 7]]
        odd = [[1, 3, 0, 5], [0, 2, 3, 6], [0, 5, 4, 6], [3, 6, 7, 5], [0, 3, 5, 6]]
        parity = ((i + j + k).ravel() % 2)[:, None, None]
        return numpy.where(parity == 0, at[:, even], at[:, odd]).reshape(-1, 4)
    tets = numpy.empty((corner.size, 6, 4), dtype=numpy.int64)
    for n, (a, b, c) in enumerate(itertools.permutations(range(3))):
        tets[:, n, 0] = corner
        tets[:, n, 1] = corner + step[a]
        tets[:, n, 2] = corner + step[a] + step[b]
        tets[:, n, 3] = corner + step[a] + step[b] + step[c]
    return tets.reshape(-1, 4)


def orient(tets, xyz):
    """Swaps two points of each tetrahedron of negative volume (VTK's order)."""
    p = [xyz[tets[:, m]] for m in range(4)]
    volume = numpy.einsum("ij,ij->i", numpy.cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0])
    flip = volume < 0
    tets[flip, 1], tets[flip, 2] = tets[flip, 2].copy(), tets[flip, 1].copy()
    return float(numpy.abs(volume).min())


def write_pvd(path, files):
    with open(path, "w") as out:
        out.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                  '  <Collection>\n')
        for t, name in files:
            out.write('    <DataSet timestep="%r" part="0" file="%s"/>\n' % (t, name))
        out.write("  </Collection>\n</VTKFile>\n")


def raw_writer(writer, data, path):
    writer.SetInputData(data)
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    writer.SetCompressorTypeToNone()
    writer.SetHeaderTypeToUInt64()
    writer.SetFileName(path)
    writer.Write()


def write_series(data, xyz, name, move=None):
    """Writes `data` with the flow at `xyz` at every time step, and a .pvd of
    them, into the folder; the .pvd's path. `move(s)`, if given, gives step
    s's points (set as the data's)."""
    writer = vtkXMLImageDataWriter() if data.IsA("vtkImageData") else vtkXMLUnstructuredGridWriter()
    files = []
    for s in range(args.steps):
        if move:
            xyz = move(s)
            data.GetPoints().SetData(numpy_to_vtk(xyz.astype(numpy.float32), deep=True))
        velocity = numpy_to_vtk(gyre(xyz, DT * s), deep=True)
        velocity.SetName("velocity")
        data.GetPointData().SetVectors(velocity)
        files.append((DT * s, "%s_%03d.%s" % (name, s, writer.GetDefaultFileExtension())))
        raw_writer(writer, data, os.path.join(folder, files[-1][1]))
    write_pvd(os.path.join(folder, name + ".pvd"), files)
    return os.path.join(folder, name + ".pvd")


def image_over_box(dims, name):
    """An image of `dims` points over the box, with the flow: its .pvd."""
    spacing = [(e / (d - 1) if d > 1 else 1.0) for e, d in zip((2.0, 1.0, 1.0), dims)]
    image = vtkImageData()
    image.SetDimensions(dims)
    image.SetSpacing(spacing)
    image.SetOrigin(0, 0, 0)
    return write_series(image, grid_points(dims, spacing), name)


def make_mesh():
    """Writes the mesh's steps: its .pvd, cell count, point count and the
    dimensions of the grid it was made from."""
    n = max(2, int(round((args.cells / (2.0 * args.cut)) ** (1.0 / 3.0))))
    dims = (2 * n + 1, n + 1, n + 1)
    spacing = (2.0 / (dims[0] - 1), 1.0 / (dims[1] - 1), 1.0 / (dims[2] - 1))
    regular = grid_points(dims, spacing)
    index = [numpy.rint(regular[:, a] / spacing[a]).astype(int) for a in range(3)]

    def jittered(seed):
        rng = numpy.random.default_rng(seed)
        moved = regular.copy()
        for a in range(3):
            interior = (index[a] > 0) & (index[a] < dims[a] - 1)
            moved[interior, a] += rng.uniform(-JITTER, JITTER, interior.sum()) * spacing[a]
        return moved

    xyz = jittered(1)
    tets = tetrahedra(dims)
    assert orient(tets, xyz) > 0, "a flat tetrahedron"
    mesh = vtkUnstructuredGrid()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz.astype(numpy.float32), deep=True))
    mesh.SetPoints(points)
    cells = vtkCellArray()
    offsets = numpy.arange(0, 4 * len(tets) + 1, 4, dtype=numpy.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(tets.ravel(), deep=True))
    mesh.SetCells(VTK_TETRA, cells)
    move = (lambda s: jittered(1 + s)) if args.moving else None
    return write_series(mesh, xyz, "mesh", move), len(tets), len(xyz), dims


def make_seeds():
    """--seeds random points inside the box, away from its faces."""
    rng = numpy.random.default_rng(2)
    xyz = rng.uniform([0.05, 0.05, 0.05], [1.95, 0.95, 0.95], (args.seeds, 3))
    seeds = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz.astype(numpy.float32), deep=True))
    seeds.SetPoints(points)
    verts = vtkCellArray()
    ids = numpy.arange(args.seeds + 1, dtype=numpy.int64)
    verts.SetData(numpy_to_vtkIdTypeArray(ids, deep=True),
                  numpy_to_vtkIdTypeArray(ids[:-1].copy(), deep=True))
    seeds.SetVerts(verts)
    proxy = TrivialProducer(registrationName="seeds")
    proxy.GetClientSideObject().SetOutput(seeds)
    return proxy


class Stopwatch:
    """The seconds an algorithm spends in its own executions (between its
    Start and End events, so without its upstream's), and how many."""

    def __init__(self, proxy):
        self.seconds, self.count, self.started = 0.0, 0, None
        algorithm = proxy.GetClientSideObject()
        algorithm.AddObserver("StartEvent", self.start)
        algorithm.AddObserver("EndEvent", self.end)

    def start(self, *unused):
        self.started = time.perf_counter()

    def end(self, *unused):
        if self.started is not None:
            self.seconds += time.perf_counter() - self.started
            self.count += 1
            self.started = None

    def lap(self):
        """The seconds and executions since the last lap."""
        lap = (self.seconds, self.count)
        self.seconds, self.count = 0.0, 0
        return lap


class Reader:
    """A .pvd reader, timed."""

    def __init__(self, path):
        self.proxy = PVDReader(FileName=path)
        self.proxy.UpdatePipeline(0.0)
        self.times = list(self.proxy.TimestepValues)
        self.watch = Stopwatch(self.proxy)


def bound(reader):
    tracer = BoundParticleTracer(Input=reader.proxy, SeedSource=seeds,
                                 Vectors=["POINTS", "velocity"], ElementShape="Point",
                                 NumberOfElements=args.seeds, Integrator="Runge-Kutta 4",
                                 StepSizeUnit="Time", StepSize=DT / 2,
                                 FramesPerInputStep=args.frames_per_step,
                                 LifetimeRange=[1e9, 1e9], Seed=1, ComputeVorticity=0)
    if args.resample:
        tracer.ResampleDimensions = args.resample
    return tracer


def particle_tracer(reader):
    tracer = ParticleTracer(Input=reader.proxy, SeedSource=seeds)
    tracer.SelectInputVectors = ["POINTS", "velocity"]
    tracer.StaticSeeds = 1
    tracer.MeshOverTime = "Different" if args.moving else "Static"
    tracer.ComputeVorticity = 0
    tracer.ForceReinjectionEveryNSteps = 0
    return tracer


def play(tracer, times, own, reader):
    """UpdatePipeline at the first time, then at each later one: the first
    frame's seconds and reader executions; each following frame's seconds
    (all, the tracer's own, the reader's) and the reader's executions per
    following frame."""
    own.lap()
    reader.watch.lap()
    start = time.perf_counter()
    tracer.UpdatePipeline(times[0])
    first = time.perf_counter() - start
    own.lap()
    first_reads = reader.watch.lap()[1]
    frames, frames_own, frames_read, reads = [], [], [], 0
    for t in times[1:]:
        start = time.perf_counter()
        tracer.UpdatePipeline(t)
        frames.append(time.perf_counter() - start)
        frames_own.append(own.lap()[0])
        seconds, count = reader.watch.lap()
        frames_read.append(seconds)
        reads += count
    return dict(first=first, first_reads=first_reads, frames=frames, frames_own=frames_own,
                frames_read=frames_read, frame_reads=reads / max(1, len(frames)))


def timed(make, reader):
    """A fresh tracer played through the offered times twice (the second time
    a replay: back to the first time, then forward again); the two plays, the
    offered times, the particles at the end of the first play, their
    positions by seed and the resampled dimensions (or None)."""
    reader.proxy.UpdatePipeline(reader.times[-1])  # the reader holds another step
    tracer = make(reader)
    times = list(tracer.TimestepValues)
    own = Stopwatch(tracer)
    first_play = play(tracer, times, own, reader)
    output = servermanager.Fetch(tracer)
    dims = output.GetFieldData().GetArray("ResampledDimensions")
    dims = None if dims is None else [int(v) for v in vtk_to_numpy(dims).ravel()]
    particles = output.GetNumberOfPoints()
    xyz = vtk_to_numpy(output.GetPoints().GetData()).astype(float) if particles else None
    ids = output.GetPointData().GetArray("ParticleId")  # ParaView's tracer: which seed
    if xyz is not None and ids is not None:
        xyz = dict(zip(vtk_to_numpy(ids).astype(int).tolist(), xyz))
    elif xyz is not None:
        xyz = dict(enumerate(xyz))  # one-particle elements in seed order
    replay = play(tracer, times, own, reader)
    Delete(tracer)
    return dict(play=first_play, replay=replay, particles=particles, dims=dims,
                offered=len(times), xyz=xyz)


def summary(runs):
    """Medians over the repeats (of each repeat's median frame)."""
    def middle(values):
        values = list(values)
        return statistics.median(values) if values else float("nan")

    def median(key, of="play", reduce=middle):
        return middle(reduce(r[of][key]) if reduce else r[of][key] for r in runs)
    return dict(first=median("first", reduce=None), frame=median("frames"),
                own=median("frames_own"), read=median("frames_read"),
                slowest=median("frames", reduce=lambda v: max(v, default=float("nan"))),
                first_reads=median("first_reads", reduce=None),
                frame_reads=median("frame_reads", reduce=None),
                replay_first=median("first", "replay", None), replay=median("frames", "replay"),
                replay_reads=median("frame_reads", "replay", None),
                particles=runs[-1]["particles"], offered=runs[-1]["offered"],
                xyz=runs[-1]["xyz"])


folder = args.keep or tempfile.mkdtemp(prefix="bp-unstructured-")
os.makedirs(folder, exist_ok=True)
began = time.perf_counter()
try:
    mesh_path, cell_count, point_count, dims = make_mesh()
    image_path = image_over_box(dims, "image")
    made = time.perf_counter() - began
    seeds = make_seeds()
    mesh, image = Reader(mesh_path), Reader(image_path)
    print("mesh: %d tetrahedra, %d points (%d x %d x %d hexahedra of %d, jittered by %g of a "
          "cell); image: %d x %d x %d points; %s; written in %.1f s to %s"
          % (cell_count, point_count, dims[0] - 1, dims[1] - 1, dims[2] - 1, args.cut, JITTER,
             dims[0], dims[1], dims[2],
             "%d time steps 0.5 apart, %s" % (len(mesh.times), "the points moved at each"
                                              if args.moving else "the same points and cells"),
             made, folder))
    print("job: %d one-particle elements from the same seed points, RK4, 2 sub-steps per "
          "interval, %d repeats (medians, interleaved)" % (args.seeds, args.repeats))

    # An untimed first frame on the mesh: the dimensions the tracer resamples
    # it to, for one more row (an image of that size: the grid the tracer
    # steps on once the resample is done).
    probe = bound(mesh)
    probe.UpdatePipeline(mesh.times[0])
    probed = servermanager.Fetch(probe).GetFieldData().GetArray("ResampledDimensions")
    Delete(probe)
    resampled = None if probed is None else [int(v) for v in vtk_to_numpy(probed).ravel()]
    if resampled:
        print("resampled dimensions (%s): %s = %d points, for %d cells"
              % ("set" if args.resample else "automatic", " x ".join(map(str, resampled)),
                 numpy.prod(resampled), cell_count))
    else:
        print("resampled dimensions: no ResampledDimensions array in the output")
    sys.stdout.flush()

    ROWS = [("mesh (Bound)", bound, mesh), ("image same size (Bound)", bound, image),
            ("mesh (ParaView Particle Tracer)", particle_tracer, mesh)]
    if resampled:
        ROWS.append(("image of resampled size (Bound)", bound,
                     Reader(image_over_box(resampled, "resampled"))))
    runs = {name: [] for name, _, _ in ROWS}
    for _ in range(args.repeats):
        for name, make, reader in ROWS:
            runs[name].append(timed(make, reader))
    rows = [(name, summary(runs[name])) for name, _, _ in ROWS]
    mesh_row, image_row, pt_row = (r for _, r in rows[:3])

    print()
    head = "%-32s %8s %10s %11s %11s"
    print(head % ("", "first", "following", "mesh/image", "PT/Bound"))
    print(head % ("", "frame s", "ms/frame", "per frame", "first|frame"))
    for name, r in rows:
        ratio = "%.2fx" % (r["frame"] / image_row["frame"]) if r is mesh_row else "-"
        versus = ("%.1fx|%.1fx" % (r["first"] / mesh_row["first"], r["frame"] / mesh_row["frame"])
                  if r is pt_row else "-")
        print("%-32s %8.3f %10.1f %11s %11s" % (name, r["first"], 1e3 * r["frame"], ratio, versus))
    print()
    print("where a following frame's time goes, and a replay (back to the first time, then "
          "Play again):")
    head = "%-32s %9s %9s %9s %7s %7s %9s %9s %7s"
    print(head % ("", "own", "reader", "slowest", "reads", "reads", "replay", "replay",
                  "replay"))
    print(head % ("", "ms/frame", "ms/frame", "ms/frame", "first", "/frame", "first s",
                  "ms/frame", "reads"))
    for name, r in rows:
        print("%-32s %9.1f %9.1f %9.1f %7d %7.2f %9.3f %9.1f %7.2f" % (
            name, 1e3 * r["own"], 1e3 * r["read"], 1e3 * r["slowest"], r["first_reads"],
            r["frame_reads"], r["replay_first"], 1e3 * r["replay"], r["replay_reads"]))
    print("own: the tracer's own executions in a frame, the reader's left out; reader: the "
          "reader's executions in it; slowest: the slowest following frame; reads: the reader's "
          "executions on the first frame and per following frame; %d offered times each; "
          "mesh/image own: %.2fx" % (rows[0][1]["offered"], mesh_row["own"] / image_row["own"]))
    print("particles at the end: %s" % ", ".join("%s %d" % (name, r["particles"])
                                                  for name, r in rows))
    for name, r in rows[1:]:
        if mesh_row["xyz"] and r["xyz"]:
            common = [i for i in mesh_row["xyz"] if i in r["xyz"]]
            far = [numpy.linalg.norm(mesh_row["xyz"][i] - r["xyz"][i]) for i in common]
            if far:
                print("final positions, mesh (Bound) against %s: %d particles in both, "
                      "distance median %.2e, max %.2e (box 2 x 1 x 1)"
                      % (name, len(far), statistics.median(far), max(far)))
    print("total %.0f s" % (time.perf_counter() - began))
    sys.stdout.flush()
finally:
    if not args.keep:
        shutil.rmtree(folder, ignore_errors=True)
