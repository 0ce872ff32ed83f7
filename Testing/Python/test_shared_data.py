"""Every shared real data set traces without an error or a NaN: steady 3D
volumes, and unsteady single-layer (2D) series."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments("--data")
LoadPlugin(args.plugin, ns=globals())

for name in ["combustor.vti", "office.vti", "carotid.vti", "nek_eddy.pvd", "gfs_wind10m.pvd"]:
    reader = OpenDataFile(os.path.join(args.data, name))
    reader.UpdatePipeline()
    tracer = BoundParticleTracer(Input=reader, ElementShape="Strip8", NumberOfElements=500,
                                 Vectors=["POINTS", "velocity"])
    times = list(tracer.TimestepValues)
    middle = times[len(times) // 2]
    with bptest.CapturedMessages() as log:
        tracer.UpdatePipeline(middle)
    bptest.check(not log.messages, "%s: messages %s" % (name, log.messages))
    data = servermanager.Fetch(tracer)
    bptest.check(data.GetNumberOfPoints() == 4000, "%s: %d points" % (name, data.GetNumberOfPoints()))
    xyz = vtk_to_numpy(data.GetPoints().GetData())
    bptest.check((xyz == xyz).all(), "%s: positions are finite" % name)
    moved = vtk_to_numpy(data.GetPointData().GetArray("Speed")).max()
    bptest.check(moved > 0, "%s: elements sit in a moving flow" % name)
    print("%s: %d time values, traced to t = %g" % (name, len(times), middle))
    Delete(tracer)
    Delete(reader)
bptest.finish()
