"""The tracer with its defaults, straight on the output of ParaView's mesh readers.

Each case is written by this script into a temporary folder (nothing is
downloaded, nothing is written into the repository), opened with ParaView's
own reader, and traced by a Bound Particle Tracer whose only property set is
Vectors, to the middle of the offered time range (tracer.TimestepValues):
- plot3d: the real combustor (combxyz.bin, combq.bin), PLOT3D reader, a
  multiblock of one curvilinear (structured) grid;
- nek5000: the real Nek5000 eddy series (11 steps) on its own spectral-element
  mesh of quads, as a .pvd of .vtu (this ParaView has no Nek5000 reader, so the
  script reads the Nek5000 files itself);
- ensight: the same eddy series, triangulated, as an EnSight Gold case (2D
  unstructured, 11 steps), EnSight reader;
- exodus: the real office flow cut into tetrahedra, written by
  vtkExodusIIWriter, opened with the reader OpenDataFile picks;
- openfoam: a hexahedral annulus (a 3D Taylor-Couette-like flow; 41% of a
  box around it, the hole and the corners, is outside the mesh) with `U` as
  cell data in three time folders, OpenFOAM reader with its defaults
  (cell-to-point on), point `U`;
- openfoam-cells: the same case with the reader's cell-to-point off, cell `U`.
Prints one row per case:
- the reader OpenDataFile picked, its output type, cells, time steps, and the
  vectors traced (P: point, C: cell data);
- resampled: the tracer's output field data ResampledDimensions;
- inside: the share of particles inside the original mesh at that time (a 2D
  mesh's particles are put onto its plane first);
- moving: the share of elements whose particles' mean speed is at least 1% of
  the top speed of the input vectors at that time;
- time traced, top speed, and the messages the tracer printed.
Targets (the issue's "done when"): inside >= 90%, moving >= 80%, and an output
at all; with --check a miss fails the run. With --pictures DIR it also writes
one picture per case there.

    with-display.sh pvpython bench/mesh_data.py --plugin BoundParticles.so --data ../shared/data
"""
import argparse
import os
import shutil
import sys
import tempfile
import time

import numpy
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_QUAD, vtkCellArray, vtkPolyData,
                                           vtkUnstructuredGrid)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from messages import CapturedMessages  # noqa: E402
INSIDE_TARGET, MOVING_TARGET = 0.90, 0.80


# ---------------------------------------------------------------- generators
# Each make_* writes its case under `folder` and returns
# (reader proxy, Vectors for the tracer).

def make_plot3d(data, folder):
    """The real combustor through the PLOT3D reader, velocity computed from Q."""
    orig = os.path.join(data, "orig", "vtk-data")
    reader = PLOT3DReader(FileName=os.path.join(orig, "combxyz.bin"),
                          QFileName=[os.path.join(orig, "combq.bin")],
                          Functions=["Vector - Velocity"])
    return reader, ["POINTS", "Velocity"]


def read_nek5000(path):
    """The series of a .nek5000 file as [(time, points N x 3, quads M x 4, velocity N x 3)].

    Nek5000 binary field files: a 132-byte ASCII header, the float 6.54321 as
    an endianness tag, the element map, then per field (X, U, P ...) and per
    element the components one after the other, nx*ny*nz values each.
    The spectral elements' points are merged where elements meet, so the
    quads form one conforming mesh (as a Nek5000 reader would give).
    """
    meta = dict(line.split(":", 1) for line in open(path) if ":" in line)
    template = meta["filetemplate"].strip()
    first, count = int(meta["firsttimestep"]), int(meta["numtimesteps"])
    folder = os.path.dirname(path)
    steps, coordinates = [], None
    for step in range(first, first + count):
        raw = open(os.path.join(folder, template % (0, step)), "rb").read()
        header = raw[:132].decode().split()
        word, nx, ny, nz, elements = (int(v) for v in header[1:6])
        when, fields = float(header[7]), header[11]
        endian = "<" if abs(numpy.frombuffer(raw[132:136], "<f4")[0] - 6.54321) < 1e-4 else ">"
        real = numpy.dtype(endian + ("f4" if word == 4 else "f8"))
        dims = 2 if nz == 1 else 3
        offset = 136 + 4 * elements  # past the tag and the element map
        per_element = nx * ny * nz
        values = {}
        for field in fields:
            components = dims if field in "XU" else 1
            size = elements * components * per_element
            values[field] = numpy.frombuffer(raw, real, size, offset).reshape(
                elements, components, per_element)
            offset += size * real.itemsize
        if "X" in values:
            coordinates = values["X"]
        xyz = numpy.zeros((elements * per_element, 3))
        xyz[:, :dims] = coordinates.transpose(0, 2, 1).reshape(-1, dims)
        velocity = numpy.zeros_like(xyz)
        velocity[:, :dims] = values["U"].transpose(0, 2, 1).reshape(-1, dims)
        steps.append((when, xyz, velocity))
    # One element's quads (points i fastest), repeated for every element.
    i, j = numpy.meshgrid(numpy.arange(nx - 1), numpy.arange(ny - 1))
    corner = (i + nx * j).ravel()
    quad = numpy.stack([corner, corner + 1, corner + 1 + nx, corner + nx], axis=1)
    quads = (quad[None] + per_element * numpy.arange(elements)[:, None, None]).reshape(-1, 4)
    # Merge points shared by elements (identical coordinates up to rounding).
    scale = numpy.abs(steps[0][1]).max()
    _, keep, merged = numpy.unique(numpy.round(steps[0][1] / scale, 9), axis=0,
                                   return_index=True, return_inverse=True)
    merged = merged.ravel()
    return [(when, xyz[keep], merged[quads], velocity[keep]) for when, xyz, velocity in steps]


def unstructured(points, cells, cell_type, arrays):
    """A vtkUnstructuredGrid of one cell type with the given point arrays."""
    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points, dtype=float), deep=True))
    grid.SetPoints(vtk_points)
    connectivity = vtkCellArray()
    connectivity.SetData(cells.shape[1], numpy_to_vtkIdTypeArray(
        numpy.ascontiguousarray(cells.ravel(), dtype=numpy.int64), deep=True))
    grid.SetCells(cell_type, connectivity)
    for name, values in arrays.items():
        array = numpy_to_vtk(numpy.ascontiguousarray(values), deep=True)
        array.SetName(name)
        grid.GetPointData().AddArray(array)
    return grid


def make_nek5000(data, folder):
    """The Nek5000 eddy series on its own quad mesh, as a .pvd of .vtu files."""
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    series = read_nek5000(os.path.join(data, "orig", "vtk-data", "nek5000", "eddy_uv.nek5000"))
    entries = []
    for index, (when, xyz, quads, velocity) in enumerate(series):
        name = "eddy_%02d.vtu" % index
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputData(unstructured(xyz, quads, VTK_QUAD, {"velocity": velocity}))
        writer.SetFileName(os.path.join(folder, name))
        writer.Write()
        entries.append('    <DataSet timestep="%.17g" file="%s"/>' % (when, name))
    path = os.path.join(folder, "eddy.pvd")
    with open(path, "w") as pvd:
        pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                  '  <Collection>\n%s\n  </Collection>\n</VTKFile>\n' % "\n".join(entries))
    return OpenDataFile(path), ["POINTS", "velocity"]


def make_ensight(data, folder):
    """The Nek5000 eddy series cut into triangles, as an EnSight Gold ASCII case."""
    series = read_nek5000(os.path.join(data, "orig", "vtk-data", "nek5000", "eddy_uv.nek5000"))
    _, xyz, quads, _ = series[0]
    triangles = numpy.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])

    def column(values, fmt="%12.5e"):
        return "\n".join(fmt % v for v in values) + "\n"

    with open(os.path.join(folder, "eddy.geo"), "w") as geo:
        geo.write("Nek5000 eddy_uv\ntriangulated spectral-element mesh\n"
                  "node id off\nelement id off\npart\n%10d\nfluid\ncoordinates\n%10d\n"
                  % (1, len(xyz)))
        for axis in range(3):
            geo.write(column(xyz[:, axis]))
        geo.write("tria3\n%10d\n" % len(triangles))
        numpy.savetxt(geo, triangles + 1, fmt="%10d", delimiter="")
    for index, (_, _, _, velocity) in enumerate(series):
        with open(os.path.join(folder, "eddy.vel%04d" % index), "w") as var:
            var.write("velocity\npart\n%10d\ncoordinates\n" % 1)
            for axis in range(3):
                var.write(column(velocity[:, axis]))
    path = os.path.join(folder, "eddy.case")
    with open(path, "w") as case:
        case.write("FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: eddy.geo\n\n"
                   "VARIABLE\nvector per node: 1 velocity eddy.vel****\n\n"
                   "TIME\ntime set: 1\nnumber of steps: %d\nfilename start number: 0\n"
                   "filename increment: 1\ntime values:\n%s"
                   % (len(series), column([s[0] for s in series], "%.9g")))
    return OpenDataFile(path), ["POINTS", "velocity"]


def make_exodus(data, folder):
    """The office flow (a structured grid) cut into tetrahedra, written as Exodus II."""
    from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
    from vtkmodules.vtkIOExodus import vtkExodusIIWriter
    from vtkmodules.vtkIOLegacy import vtkDataSetReader
    office = vtkDataSetReader()
    office.SetFileName(os.path.join(data, "orig", "vtk-data", "office.binary.vtk"))
    office.Update()
    office.GetOutput().GetPointData().GetArray("vectors").SetName("velocity")
    tetrahedra = vtkDataSetTriangleFilter()
    tetrahedra.SetInputConnection(office.GetOutputPort())
    path = os.path.join(folder, "office.exo")
    writer = vtkExodusIIWriter()
    writer.SetInputConnection(tetrahedra.GetOutputPort())
    writer.SetFileName(path)
    writer.WriteAllTimeStepsOff()
    writer.Write()
    reader = OpenDataFile(path)
    # The ExodusII reader loads no nodal variable unless asked to (IOSS loads all).
    for name in ("PointVariables", "NodeBlockFields"):
        if name in reader.ListProperties():
            reader.SetPropertyWithName(name, reader.GetProperty(name).Available)
    return reader, ["POINTS", "velocity"]


def hexahedral_annulus(inner=1.0, outer=2.0, height=1.0, radial=12, around=96, layers=12):
    """Points (N x 3) and hexahedra (C x 8, VTK order) filling an annulus around z."""
    r = numpy.linspace(inner, outer, radial + 1)
    angle = numpy.linspace(0, 2 * numpy.pi, around, endpoint=False)
    z = numpy.linspace(0, height, layers + 1)
    R, A, Z = numpy.meshgrid(r, angle, z, indexing="ij")
    points = numpy.stack([R * numpy.cos(A), R * numpy.sin(A), Z], axis=-1).reshape(-1, 3)

    def index(i, j, k):
        return (i * around + j % around) * (layers + 1) + k  # j wraps around the circle

    i, j, k = (a.ravel() for a in numpy.meshgrid(numpy.arange(radial), numpy.arange(around),
                                                   numpy.arange(layers), indexing="ij"))
    hexahedra = numpy.stack([index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k),
                             index(i, j + 1, k), index(i, j, k + 1), index(i + 1, j, k + 1),
                             index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)], axis=1)
    return points, hexahedra


def poly_mesh(points, hexahedra, patch_of):
    """OpenFOAM's face-based description of a hexahedral mesh.

    Returns (faces F x 4, owner, neighbour, [(patch, count)]): internal faces
    first in upper-triangular order (by owner, then neighbour), then the
    boundary faces patch by patch; every face's normal points out of its owner.
    `patch_of(centres)` names the patch of each boundary face.
    """
    sides = numpy.array([[0, 4, 7, 3], [1, 2, 6, 5], [0, 1, 5, 4],
                         [3, 7, 6, 2], [0, 3, 2, 1], [4, 5, 6, 7]])
    faces = hexahedra[:, sides].reshape(-1, 4)
    cells = numpy.repeat(numpy.arange(len(hexahedra)), 6)
    # Orient each copy outward from its cell, whatever the hexahedra's handedness.
    corners = points[faces]
    normal = numpy.cross(corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 1])
    outward = corners.mean(axis=1) - points[hexahedra].mean(axis=1)[cells]
    flip = (normal * outward).sum(axis=1) < 0
    faces[flip] = faces[flip][:, ::-1]
    _, which, counts = numpy.unique(numpy.sort(faces, axis=1), axis=0,
                                    return_inverse=True, return_counts=True)
    which = which.ravel()
    # The copies of a face sort next to each other; the first is the lower cell's.
    order = numpy.lexsort((cells, which))
    shared = counts[which[order]] == 2
    first = order[shared][0::2]
    second = order[shared][1::2]
    internal = numpy.lexsort((cells[second], cells[first]))
    owner, neighbour = cells[first][internal], cells[second][internal]
    boundary = order[~shared]
    names = patch_of(points[faces[boundary]].mean(axis=1))
    patches = sorted(set(names))
    boundary = numpy.concatenate([boundary[names == name] for name in patches])
    return (numpy.concatenate([faces[first][internal], faces[boundary]]),
            numpy.concatenate([owner, cells[boundary]]), neighbour,
            [(name, int((names == name).sum())) for name in patches])


def foam_file(path, cls, body, location=""):
    """Writes an OpenFOAM ASCII dictionary/list file with its FoamFile header."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n%s"
                "    object %s;\n}\n\n%s" % (cls, '    location "%s";\n' % location
                                           if location else "", os.path.basename(path), body))


def foam_list(rows, fmt):
    return "%d\n(\n%s\n)\n" % (len(rows), "\n".join(fmt % tuple(row) for row in rows))


def couette_flow(centres, when):
    """A Taylor-Couette-like flow in the annulus 1 <= r <= 2, 0 <= z <= 1.

    A swirl that grows with time, plus a vortex in the r-z plane (stream
    function sin(pi s) sin(pi z), s = r - 1) that pulses; every component
    normal to a wall vanishes on it, so the flow stays in the annulus.
    """
    x, y, z = centres.T
    r = numpy.hypot(x, y)
    s = r - 1.0
    swirl = (1.0 + 0.5 * when) * r * numpy.sin(numpy.pi * s)
    pulse = 0.4 * (1.0 + 0.5 * numpy.sin(when))
    ur = pulse * numpy.sin(numpy.pi * s) * numpy.cos(numpy.pi * z)
    uz = -pulse * numpy.cos(numpy.pi * s) * numpy.sin(numpy.pi * z)
    return numpy.stack([ur * x / r - swirl * y / r, ur * y / r + swirl * x / r, uz], axis=1)


def make_openfoam(data, folder, times=(0, 1, 2, 3)):
    """The annulus as an OpenFOAM case, `U` as cell data in each time folder.

    The reader skips the 0 folder by default (its Skip Zero Time), so four
    folders give three time steps.
    """
    points, hexahedra = hexahedral_annulus()

    def patch_of(centres):
        r = numpy.hypot(centres[:, 0], centres[:, 1])
        return numpy.where(centres[:, 2] < 1e-6, "bottom", numpy.where(
            centres[:, 2] > 1 - 1e-6, "top", numpy.where(r < 1.5, "inner", "outer")))

    faces, owner, neighbour, patches = poly_mesh(points, hexahedra, patch_of)
    mesh = os.path.join(folder, "constant", "polyMesh")
    foam_file(os.path.join(mesh, "points"), "vectorField",
              foam_list(points, "(%.9g %.9g %.9g)"), "constant/polyMesh")
    foam_file(os.path.join(mesh, "faces"), "faceList",
              foam_list(faces, "4(%d %d %d %d)"), "constant/polyMesh")
    foam_file(os.path.join(mesh, "owner"), "labelList",
              foam_list(owner[:, None], "%d"), "constant/polyMesh")
    foam_file(os.path.join(mesh, "neighbour"), "labelList",
              foam_list(neighbour[:, None], "%d"), "constant/polyMesh")
    start, entries = len(neighbour), []
    for name, count in patches:
        entries.append("    %s\n    {\n        type wall;\n        nFaces %d;\n"
                       "        startFace %d;\n    }" % (name, count, start))
        start += count
    foam_file(os.path.join(mesh, "boundary"), "polyBoundaryMesh",
              "%d\n(\n%s\n)\n" % (len(patches), "\n".join(entries)), "constant/polyMesh")
    foam_file(os.path.join(folder, "system", "controlDict"), "dictionary",
              "application icoFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
              "endTime %g;\ndeltaT 0.01;\nwriteControl runTime;\nwriteInterval 1;\n"
              % times[-1], "system")
    centres = points[hexahedra].mean(axis=1)
    walls = "".join("    %s\n    {\n        type fixedValue;\n        value uniform (0 0 0);\n"
                    "    }\n" % name for name, _ in patches)
    for when in times:
        foam_file(os.path.join(folder, "%g" % when, "U"), "volVectorField",
                  "dimensions [0 1 -1 0 0 0 0];\n\ninternalField nonuniform List<vector>\n%s;\n\n"
                  "boundaryField\n{\n%s}\n" % (foam_list(couette_flow(centres, when),
                                                         "(%.7g %.7g %.7g)"), walls), "%g" % when)
    path = os.path.join(folder, "case.foam")
    open(path, "w").close()
    return OpenDataFile(path), ["POINTS", "U"]


def make_openfoam_cells(data, folder):
    """The OpenFOAM case read with cell-to-point off: `U` exists only on cells."""
    reader, _ = make_openfoam(data, folder)
    reader.Createcelltopointfiltereddata = 0
    return reader, ["CELLS", "U"]


CASES = [("plot3d", make_plot3d), ("nek5000", make_nek5000), ("ensight", make_ensight),
         ("exodus", make_exodus), ("openfoam", make_openfoam),
         ("openfoam-cells", make_openfoam_cells)]


# ---------------------------------------------------------------- measures

def original_mesh(reader, time):
    """The reader's output at `time` merged into one vtkUnstructuredGrid."""
    merge = MergeBlocks(Input=reader)
    merge.UpdatePipeline(time)
    mesh = servermanager.Fetch(merge)
    Delete(merge)
    return mesh


def describe(reader):
    """The reader's name, output type (short), cells and time steps."""
    info = reader.GetDataInformation()
    kind = info.GetDataSetTypeAsString().replace("vtk", "").replace("DataSetCollection", "DSC")
    return (type(reader).__name__, kind.replace("DataSet", ""), info.GetNumberOfCells(),
            len(reader.TimestepValues))


def top_speed(mesh, vectors):
    """The largest magnitude of the traced vectors on the original mesh."""
    data = mesh.GetPointData() if vectors[0] == "POINTS" else mesh.GetCellData()
    velocity = vtk_to_numpy(data.GetArray(vectors[1])).astype(float)
    speed = numpy.linalg.norm(velocity, axis=1)
    return speed[numpy.isfinite(speed)].max()


def inside_share(mesh, xyz):
    """The share of positions inside a cell of `mesh` (vtkProbeFilter's mask).

    A mesh with no z extent (2D) gets its positions put onto its plane first:
    the elements' own extent takes some of their particles off it.
    """
    from vtkmodules.vtkFiltersCore import vtkProbeFilter
    xyz = numpy.array(xyz, dtype=float).reshape(-1, 3)
    bounds = mesh.GetBounds()
    if bounds[5] - bounds[4] <= 1e-12 * max(bounds[1] - bounds[0], bounds[3] - bounds[2]):
        xyz[:, 2] = bounds[4]
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    positions = vtkPolyData()
    positions.SetPoints(points)
    probe = vtkProbeFilter()
    probe.SetInputData(positions)
    probe.SetSourceData(mesh)
    probe.Update()
    mask = probe.GetOutput().GetPointData().GetArray(probe.GetValidPointMaskArrayName())
    return vtk_to_numpy(mask).mean()


def field_values(data, name):
    """A field data array's values as a tuple (whatever its tuples x components), or None."""
    array = data.GetFieldData().GetArray(name)
    return None if array is None else tuple(vtk_to_numpy(array).ravel().tolist())


def measure(name, make, data, folder, pictures):
    started = time.time()
    reader, vectors = make(data, folder)
    reader.UpdatePipeline()
    tracer = BoundParticleTracer(Input=reader, Vectors=vectors)
    times = list(tracer.TimestepValues) or [0.0]
    middle = times[len(times) // 2]
    messages = []
    with CapturedMessages(messages):
        tracer.UpdatePipeline(middle)
    output = servermanager.Fetch(tracer)
    mesh = original_mesh(reader, middle)
    row = dict(name=name, input=describe(reader), vectors=vectors, time=middle,
               top=top_speed(mesh, vectors), messages=messages, inside=float("nan"),
               moving=float("nan"), resampled=None, particles=output.GetNumberOfPoints())
    if row["particles"]:
        elements = tracer.NumberOfElements
        xyz = vtk_to_numpy(output.GetPoints().GetData()).astype(float).reshape(elements, -1, 3)
        speed = vtk_to_numpy(output.GetPointData().GetArray("Speed")).reshape(elements, -1)
        row["inside"] = inside_share(mesh, xyz)
        row["moving"] = (speed.mean(axis=1) >= 0.01 * row["top"]).mean()
        row["resampled"] = field_values(output, "ResampledDimensions")
    if pictures:
        picture(reader, tracer, middle, os.path.join(pictures, name + ".png"))
    Delete(tracer)
    Delete(reader)
    row["seconds"] = time.time() - started
    return row


def picture(reader, tracer, time, path):
    """The input as a translucent surface, the elements coloured by Speed."""
    view = CreateRenderView()
    view.ViewSize = [800, 600]
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    mesh = Show(reader, view, Representation="Surface")
    mesh.ColorArrayName = ["POINTS", ""]  # plain grey: the colours are the tracer's
    mesh.Opacity = 0.15
    display = Show(tracer, view)
    ColorBy(display, ("POINTS", "Speed"))
    display.RescaleTransferFunctionToDataRange(True, False)
    bounds = reader.GetDataInformation().GetBounds()
    if bounds[5] > bounds[4]:  # a volume: look from the side and above, z up
        view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [0, -1, 0], [0, 0, 0], \
            [0, 0, 1]
        view.ResetCamera()
        view.GetActiveCamera().Elevation(30)
        view.GetActiveCamera().Azimuth(30)
    view.ResetCamera()
    Render(view)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    SaveScreenshot(path, view)
    Delete(view)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "shared", "data"))
    parser.add_argument("--pictures", help="write <case>.png here")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 when a case misses a target")
    parser.add_argument("--cases", nargs="+", choices=[name for name, _ in CASES],
                        help="only these cases")
    args = parser.parse_args()
    LoadPlugin(args.plugin, ns=globals())
    scratch = tempfile.mkdtemp(prefix="mesh_data_")
    try:
        rows = []
        for name, make in CASES:
            if args.cases and name not in args.cases:
                continue
            folder = os.path.join(scratch, name)
            os.makedirs(folder)
            rows.append(measure(name, make, args.data, folder, args.pictures))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    header = ("case", "reader", "output", "cells", "steps", "vectors", "resampled", "time",
              "inside", "moving", "top speed", "sec")
    print("%-15s %-22s %-16s %6s %5s %-10s %-11s %7s %7s %7s %9s %5s" % header)
    for r in rows:
        print("%-15s %-22s %-16s %6d %5d %-10s %-11s %7.4g %6.1f%% %6.1f%% %9.4g %5.1f" % (
            (r["name"],) + r["input"] + (
                "%s:%s" % (r["vectors"][0][0], r["vectors"][1]),
                "x".join("%d" % d for d in r["resampled"]) if r["resampled"] else "-",
                r["time"], 100 * r["inside"], 100 * r["moving"], r["top"], r["seconds"])))
        for message in r["messages"]:
            print("    %s" % message[:300])
    print("targets: inside >= %d%%, moving >= %d%%" % (100 * INSIDE_TARGET, 100 * MOVING_TARGET))
    missed = [r["name"] for r in rows
              if not (r["inside"] >= INSIDE_TARGET and r["moving"] >= MOVING_TARGET)]
    if args.check and missed:
        print("FAILED: targets missed on %s" % ", ".join(missed))
        raise SystemExit(1)


if __name__ == "__main__":
    main()
