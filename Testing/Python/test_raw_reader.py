"""The Raw Vector Volume Series reader through File > Open's path (OpenDataFile):
the .bpvol extension picks it, the animation sees its time steps, both layouts
and byte orders give the values written, z_coordinates give a rectilinear grid,
broken files give an error naming them, and the tracer runs on it."""
import json
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import numpy  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())

folder = tempfile.mkdtemp(prefix="bp-raw-reader-")
dims = (8, 6, 5)
times = [0.0, 0.5, 1.5, 2.0]


def field(step):
    """(nz, ny, nx, 3) values, x fastest: a flow along +x that varies in space and time."""
    z, y, x = numpy.meshgrid(numpy.arange(dims[2]), numpy.arange(dims[1]),
                             numpy.arange(dims[0]), indexing="ij")
    v = numpy.empty(z.shape + (3,))
    v[..., 0] = 0.5 + 0.1 * step + 0.01 * x
    v[..., 1] = 0.02 * y - 0.05
    v[..., 2] = 0.01 * z * step
    return v


def write_series(name, three_files, byte_order, dtype, extra=None):
    code = "<" if byte_order == "little" else ">"
    files = []
    for k in range(len(times)):
        v = field(k).astype(code + dtype)
        if three_files:
            names = ["%s_%d_%s.raw" % (name, k, c) for c in "uvw"]
            for c in range(3):
                numpy.ascontiguousarray(v[..., c]).tofile(os.path.join(folder, names[c]))
            files.append(names)
        else:
            names = "%s_%d.raw" % (name, k)
            v.tofile(os.path.join(folder, names))
            files.append(names)
    descriptor = {"dimensions": list(dims), "origin": [0, 0, 0], "spacing": [0.5, 0.5, 0.5],
                  "scalar_type": {"f4": "float32", "f8": "float64"}[dtype],
                  "byte_order": byte_order, "times": times, "files": files}
    descriptor.update(extra or {})
    path = os.path.join(folder, name + ".bpvol")
    with open(path, "w") as f:
        json.dump(descriptor, f, indent=1)
    return path


def vectors(proxy, t):
    proxy.UpdatePipeline(t)
    data = servermanager.Fetch(proxy)
    array = data.GetPointData().GetVectors()
    return data, (None if array is None else vtk_to_numpy(array).copy())


try:
    interleaved = write_series("a", False, "little", "f4")
    components = write_series("b", True, "big", "f8")

    reader = OpenDataFile(interleaved)
    bptest.check(reader is not None and reader.GetXMLName() == "RawVectorVolumeSeriesReader",
                 "OpenDataFile picks the Raw Vector Volume Series reader for .bpvol")
    bptest.check(reader.GetClientSideObject().GetClassName() == "vtkRawVectorVolumeSeriesReader",
                 "the reader's class is %s" % reader.GetClientSideObject().GetClassName())
    bptest.check(list(reader.TimestepValues) == times, "TimestepValues %s" % reader.TimestepValues)
    bptest.check(reader.ReadAhead == 1, "ReadAhead defaults to on")
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    bptest.check(list(GetTimeKeeper().TimestepValues) == times,
                 "the animation sees %s" % list(GetTimeKeeper().TimestepValues))

    other = OpenDataFile(components)
    for k, t in enumerate(times):
        data, a = vectors(reader, t)
        expected = field(k).reshape(-1, 3).astype(numpy.float32)
        bptest.check(data.GetClassName() == "vtkImageData", "image output, not %s"
                     % data.GetClassName())
        bptest.check(a is not None and a.shape == expected.shape and (a == expected).all(),
                     "interleaved little-endian float32 step %d" % k)
        bptest.check(data.GetPointData().GetVectors().GetName() == "velocity", "array name")
        _, b = vectors(other, t + 0.25)  # between steps: the step before
        bptest.check(b is not None and (b == expected).all(),
                     "three big-endian float64 files step %d" % k)
    bptest.check(data.GetSpacing() == (0.5, 0.5, 0.5) and data.GetDimensions() == dims,
                 "grid %s %s" % (data.GetSpacing(), data.GetDimensions()))
    # Played forward, every step after the first came from the read-ahead (the counters are
    # not wrapped for Python; PrintSelf shows them).
    printed = str(reader.GetClientSideObject())
    bptest.check("NumberOfStepsRead: 4" in printed and "NumberOfReadAheadHits: 3" in printed,
                 "read-ahead while playing: %s" % [l.strip() for l in printed.splitlines()
                                                   if "Number" in l])

    # Non-uniform layers: a rectilinear grid.
    z = [0.0, 0.2, 0.5, 1.0, 2.0]
    layered = OpenDataFile(write_series("c", False, "big", "f4",
                                        {"z_coordinates": z, "array_name": "wind"}))
    layered.UpdatePipeline(1.5)
    # servermanager.Fetch garbles a rectilinear grid's coordinates in ParaView 5.11 (a .vtr
    # from ParaView's own reader too), so look at the reader's output in this builtin session.
    data = layered.GetClientSideObject().GetOutputDataObject(0)
    a = vtk_to_numpy(data.GetPointData().GetVectors())
    bptest.check(data.GetClassName() == "vtkRectilinearGrid", "z_coordinates give %s"
                 % data.GetClassName())
    bptest.check(layered.GetDataInformation().DataInformation.GetDataSetTypeAsString()
                 == "vtkRectilinearGrid", "the data information says rectilinear")
    if data.GetClassName() == "vtkRectilinearGrid":
        bptest.check(list(vtk_to_numpy(data.GetZCoordinates())) == z, "z coordinates")
        bptest.check(data.GetPointData().GetVectors().GetName() == "wind", "array_name")
        bptest.check((a == field(2).reshape(-1, 3).astype(numpy.float32)).all(), "layered values")

    # The tracer plays over the series.
    # Vectors named: the active source (the layered reader) has 'wind'.
    tracer = BoundParticleTracer(Input=reader, Vectors=["POINTS", "velocity"],
                                 NumberOfElements=30, ElementShape="Cross",
                                 EmitterCenter=[1.0, 1.2, 1.0], EmitterSize=[0.4, 0.4, 0.4])
    with bptest.CapturedMessages() as log:
        for t in times:
            tracer.UpdatePipeline(t)
    bptest.check(not log.messages, "tracing over the series: %s" % log.messages)
    bptest.check(tracer.GetDataInformation().GetNumberOfPoints() > 0, "the tracer has output")

    # A truncated step: an error naming the file, and an empty output.
    broken_file = os.path.join(folder, "a_2.raw")
    with open(broken_file, "r+b") as f:
        f.truncate(100)
    broken = OpenDataFile(interleaved)
    with bptest.CapturedMessages() as log:
        broken.UpdatePipeline(1.5)
    bptest.check(log.mentions(broken_file) and log.mentions("truncated"),
                 "truncated file error: %s" % log.messages)
    bptest.check(broken.GetDataInformation().GetNumberOfPoints() == 0, "no output for it")
    broken.UpdatePipeline(0.5)
    bptest.check(broken.GetDataInformation().GetNumberOfPoints() == 8 * 6 * 5,
                 "the other steps still read")

    # A broken descriptor.
    bad = os.path.join(folder, "bad.bpvol")
    with open(bad, "w") as f:
        f.write('{"dimensions": [8, 6, 5], "scalar_type": "float", "files": ["a_0.raw"]}')
    with bptest.CapturedMessages() as log:
        bad_reader = OpenDataFile(bad)
        bad_reader.UpdatePipeline()
    bptest.check(log.mentions(bad) and log.mentions("scalar_type"),
                 "bad descriptor error: %s" % log.messages)
    bptest.check(bad_reader.GetDataInformation().GetNumberOfPoints() == 0, "no output for it")
finally:
    shutil.rmtree(folder, ignore_errors=True)

bptest.finish()
