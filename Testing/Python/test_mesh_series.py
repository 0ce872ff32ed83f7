"""Meshes that change from one time step to the next, and meshes of an odd
shape, through the tracer's automatic resampled grid (hostile cases of
issues 38 and 46), each written here as a .pvd series of .vtu files:

- adapting: the same box cut finer at every step (another point count,
  other cells): it traces to the last step with one grid, whichever time is
  asked first, with no message (issue 46: "do not share one grid" once step
  2 was read);
- topology: hexahedra, then tetrahedra, then a mix, points renumbered,
  vectors on points or cells, played forward, back and forward again (issue
  38: a SIGSEGV once; run under valgrind's memcheck with `--cases
  topology` it reports nothing in the plugin, only ld.so's strncmp);
- moving: the mesh shifts out of the first step's bounds: it traces on the
  first step's grid and says that the part beyond is left out;
- slab: 40,000 hexahedra over 1 x 1 x 1e-5 (issue 38: 1587 x 1587 x 8 =
  20.1 M points and 6 GB, no word): at most 8 times the cells, and a warning
  that says what the grid is and why.

    with-display.sh pvpython test_mesh_series.py --plugin BoundParticles.so [--cases a,b]
"""
import os
import shutil
import sys
import tempfile

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import (numpy_to_vtk, numpy_to_vtkIdTypeArray,  # noqa: E402
                                           vtk_to_numpy)
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_TETRA, vtkCellArray,  # noqa: E402
                                           vtkUnstructuredGrid)
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter  # noqa: E402

args = bptest.arguments("--cases")
LoadPlugin(args.plugin, ns=globals())
cases = args.cases.split(",") if args.cases else ["adapting", "topology", "moving", "slab"]
folder = tempfile.mkdtemp(prefix="bp-mesh-series-")


def swirl(xyz, t=0.0):
    """A steady swirl about the box's centre line along z, slowly turning."""
    v = numpy.zeros_like(xyz)
    v[:, 0] = -(xyz[:, 1] - 0.5) * (1.0 + 0.1 * t)
    v[:, 1] = xyz[:, 0] - 0.5
    v[:, 2] = 0.05
    return v


def lattice(n, extent=(1.0, 1.0, 1.0), shift=(0.0, 0.0, 0.0)):
    """Points of an n[0] x n[1] x n[2] lattice over `extent` (x fastest), and
    the corners of its hexahedra (C x 8, VTK's order)."""
    axes = [numpy.linspace(s, s + e, m) for s, e, m in zip(shift, extent, n)]
    z, y, x = numpy.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    xyz = numpy.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    k, j, i = numpy.meshgrid(*(numpy.arange(m - 1) for m in n[::-1]), indexing="ij")
    base = (i + n[0] * (j + n[1] * k)).ravel()
    dx, dy, dz = 1, n[0], n[0] * n[1]
    hexes = numpy.stack([base, base + dx, base + dx + dy, base + dy, base + dz, base + dx + dz,
                         base + dx + dy + dz, base + dy + dz], axis=1)
    return xyz, hexes


def tetrahedra(hexes):
    """Each hexahedron (VTK order) cut into five tetrahedra, positive volume
    for a right-handed lattice."""
    h = hexes
    return numpy.concatenate([h[:, [0, 1, 3, 4]], h[:, [1, 2, 3, 6]], h[:, [1, 4, 5, 6]],
                              h[:, [3, 6, 7, 4]], h[:, [1, 3, 4, 6]]])


def grid(xyz, cells, types, vectors, on_cells=False):
    mesh = vtkUnstructuredGrid()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(numpy.ascontiguousarray(xyz, dtype=numpy.float64), deep=True))
    mesh.SetPoints(points)
    sizes = numpy.array([len(c) for c in cells])
    offsets = numpy.concatenate([[0], numpy.cumsum(sizes)]).astype(numpy.int64)
    connectivity = numpy.concatenate(cells).astype(numpy.int64)
    array = vtkCellArray()
    array.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(connectivity, deep=True))
    mesh.SetCells(numpy_to_vtk(numpy.array(types, dtype=numpy.uint8), deep=True), array)
    velocity = numpy_to_vtk(numpy.ascontiguousarray(vectors, dtype=numpy.float32), deep=True)
    velocity.SetName("velocity")
    (mesh.GetCellData() if on_cells else mesh.GetPointData()).AddArray(velocity)
    return mesh


def series(name, meshes, times=None):
    """Writes the meshes as one .vtu each and a .pvd; its reader."""
    entries = []
    for s, mesh in enumerate(meshes):
        path = "%s_%d.vtu" % (name, s)
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputData(mesh)
        writer.SetFileName(os.path.join(folder, path))
        writer.Write()
        entries.append('    <DataSet timestep="%r" file="%s"/>' %
                       (float(times[s] if times else s), path))
    pvd = os.path.join(folder, name + ".pvd")
    with open(pvd, "w") as out:
        out.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                  '  <Collection>\n%s\n  </Collection>\n</VTKFile>\n' % "\n".join(entries))
    return PVDReader(FileName=pvd)


def field(output, name):
    array = output.GetFieldData().GetArray(name)
    return None if array is None else [array.GetValue(i) for i in range(array.GetNumberOfValues())]


def trace(reader, times, vectors=("POINTS", "velocity"), **properties):
    """A tracer updated at each of `times` in turn: per time (particles,
    ResampledDimensions, messages)."""
    # The reader runs first, as a user's script would: ParaView 6.1 gives a
    # tracer on a source that never ran a zero-size emitter box.
    reader.UpdatePipeline()
    tracer = BoundParticleTracer(Input=reader, Vectors=list(vectors), ElementShape="Point",
                                 NumberOfElements=200, Seed=3, FramesPerInputStep=2,
                                 **properties)
    offered = list(tracer.TimestepValues)
    seen = []
    for t in times:
        with bptest.CapturedMessages() as log:
            tracer.UpdatePipeline(offered[t] if isinstance(t, int) else t)
        output = servermanager.Fetch(tracer)
        xyz = vtk_to_numpy(output.GetPoints().GetData()) if output.GetNumberOfPoints() else None
        finite = xyz is None or bool(numpy.isfinite(xyz).all())
        seen.append(dict(particles=output.GetNumberOfPoints(), finite=finite,
                         dims=field(output, "ResampledDimensions"), messages=log.messages))
    Delete(tracer)
    return seen


def adapting():
    """The box cut finer at each step: 5, 7 then 9 points a side."""
    meshes = []
    for s, n in enumerate((5, 7, 9)):
        xyz, hexes = lattice((n, n, n))
        tets = tetrahedra(hexes)
        meshes.append(grid(xyz, list(tets), [VTK_TETRA] * len(tets), swirl(xyz, s)))
    reader = series("adapting", meshes)
    for name, times in (("forward", [0, 1, 2, 3, 4]), ("to the end", [4]), ("back", [4, 0, 2])):
        steps = trace(reader, times)
        for t, step in zip(times, steps):
            bptest.check(step["particles"] > 0 and step["finite"],
                         "adapting, %s, time %s: %d particles" % (name, t, step["particles"]))
            bptest.check(not step["messages"],
                         "adapting, %s, time %s: messages %s" % (name, t, step["messages"]))
        dims = set(tuple(step["dims"] or ()) for step in steps)
        bptest.check(len(dims) == 1, "adapting, %s: one grid for every step (%s)" % (name, dims))
        print("adapting, %s: grid %s, %s particles" % (name, dims, [s["particles"] for s in steps]))


def topology():
    """Hexahedra, tetrahedra, then both: other point numbering at each step."""
    rng = numpy.random.default_rng(5)
    meshes = []
    for s, n in enumerate((6, 8, 7)):
        xyz, hexes = lattice((n, n, n))
        order = rng.permutation(len(xyz))  # the points renumbered
        renumber = numpy.empty_like(order)
        renumber[order] = numpy.arange(len(order))
        xyz, hexes = xyz[order], renumber[hexes]
        if s == 0:
            cells, types = list(hexes), [VTK_HEXAHEDRON] * len(hexes)
        elif s == 1:
            tets = tetrahedra(hexes)
            cells, types = list(tets), [VTK_TETRA] * len(tets)
        else:
            half = len(hexes) // 2
            tets = tetrahedra(hexes[half:])
            cells = list(hexes[:half]) + list(tets)
            types = [VTK_HEXAHEDRON] * half + [VTK_TETRA] * len(tets)
        meshes.append(grid(xyz, cells, types, swirl(xyz, s)))
    points = series("topology", meshes)
    cell_meshes = []
    for mesh in meshes:
        xyz = vtk_to_numpy(mesh.GetPoints().GetData())
        offsets = vtk_to_numpy(mesh.GetCells().GetOffsetsArray())
        connectivity = vtk_to_numpy(mesh.GetCells().GetConnectivityArray())
        middle = numpy.array([xyz[connectivity[a:b]].mean(axis=0)
                              for a, b in zip(offsets[:-1], offsets[1:])])
        cells = [connectivity[a:b] for a, b in zip(offsets[:-1], offsets[1:])]
        types = vtk_to_numpy(mesh.GetCellTypesArray())
        cell_meshes.append(grid(xyz, cells, types, swirl(middle), on_cells=True))
    on_cells = series("topology-cells", cell_meshes)
    for name, reader, vectors in (("point vectors", points, ("POINTS", "velocity")),
                                  ("cell vectors", on_cells, ("CELLS", "velocity"))):
        times = [0, 1, 2, 3, 4, 0, 4, 2]
        steps = trace(reader, times, vectors)
        for t, step in zip(times, steps):
            bptest.check(step["particles"] > 0 and step["finite"],
                         "topology, %s, time %s: %d particles" % (name, t, step["particles"]))
            bptest.check(not step["messages"],
                         "topology, %s, time %s: messages %s" % (name, t, step["messages"]))
        print("topology, %s: %s particles" % (name, [s["particles"] for s in steps]))


def moving():
    """The mesh slides along x by a quarter of its size each step."""
    meshes = []
    for s in range(3):
        xyz, hexes = lattice((6, 6, 6), shift=(0.25 * s, 0.0, 0.0))
        meshes.append(grid(xyz, list(hexes), [VTK_HEXAHEDRON] * len(hexes), swirl(xyz, s)))
    reader = series("moving", meshes)
    steps = trace(reader, [0, 2, 4])
    for t, step in zip([0, 2, 4], steps):
        bptest.check(step["particles"] > 0 and step["finite"],
                     "moving, time %s: %d particles" % (t, step["particles"]))
    messages = [m for step in steps for m in step["messages"]]
    bptest.check(any("beyond the resampled grid" in m for m in messages),
                 "moving: the part beyond the first grid is said to be left out (%s)" % messages)
    bptest.check(not any("share one grid" in m for m in messages),
                 "moving: refused (%s)" % messages)


def slab():
    """200 x 200 x 1 hexahedra over 1 x 1 x 1e-5."""
    xyz, hexes = lattice((201, 201, 2), extent=(1.0, 1.0, 1e-5))
    reader = series("slab", [grid(xyz, list(hexes), [VTK_HEXAHEDRON] * len(hexes), swirl(xyz))],
                    [0.0])
    steps = trace(reader, [0.5], Duration=1.0, NumberOfTimeSteps=3)
    step = steps[0]
    dims = step["dims"] or [0, 0, 0]
    points = dims[0] * dims[1] * dims[2]
    print("slab: grid %s = %d points for %d cells; %s" % (dims, points, len(hexes),
                                                           step["messages"]))
    bptest.check(0 < points <= 8 * len(hexes),
                 "slab: %s = %d points, more than 8 times the %d cells" % (dims, points, len(hexes)))
    bptest.check(dims[0] >= 190 and dims[1] >= 190, "slab: the plane keeps its 200 x 200 (%s)" % dims)
    bptest.check(step["particles"] > 0 and step["finite"], "slab: %d particles" % step["particles"])
    said = [m for m in step["messages"] if "thin along Z" in m]
    bptest.check(len(said) == 1, "slab: one warning says the grid and why (%s)" % step["messages"])


try:
    for case in cases:
        globals()[case]()
finally:
    shutil.rmtree(folder, ignore_errors=True)
bptest.finish()
