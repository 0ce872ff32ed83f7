"""Every shared real data set traces without an error or a NaN: steady 3D
volumes, and unsteady single-layer (2D) series. gfs_wind10m's `velocity`
(m/s on a grid in degrees, time in hours) is said to be out of scale with
its grid; its `velocity_deg_per_hour` is not."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments("--data")
LoadPlugin(args.plugin, ns=globals())

UNITS = "the velocity's units may not match the grid's"
for name, vectors in [("combustor.vti", "velocity"), ("office.vti", "velocity"),
                      ("carotid.vti", "velocity"), ("nek_eddy.pvd", "velocity"),
                      ("gfs_wind10m.pvd", "velocity_deg_per_hour"),
                      ("gfs_wind10m.pvd", "velocity")]:
    reader = OpenDataFile(os.path.join(args.data, name))
    reader.UpdatePipeline()
    with bptest.CapturedMessages() as log:
        tracer = BoundParticleTracer(Input=reader, ElementShape="Strip8", NumberOfElements=500,
                                     Vectors=["POINTS", vectors])
        times = list(tracer.TimestepValues)
        middle = times[len(times) // 2]
        tracer.UpdatePipeline(middle)
    if name == "gfs_wind10m.pvd" and vectors == "velocity":
        said = [m for m in log.messages if UNITS in m]
        bptest.check(len(said) == 1 and "between two input time steps" in said[0] and
                     "Calculator" in said[0],
                     "%s %s: the units are said to be out of scale once: %s" %
                     (name, vectors, log.messages))
    else:
        bptest.check(not log.messages, "%s %s: messages %s" % (name, vectors, log.messages))
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
