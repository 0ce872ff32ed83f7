"""Every shared real data set traces without an error or a NaN: steady 3D
volumes, and unsteady single-layer (2D) series. gfs_wind10m's `velocity`
(m/s on a grid in degrees, time in hours) is said to be out of scale with
its grid; its `velocity_deg_per_hour` is not, and is the Vectors default
though `velocity` is the active vectors, with a note of why (issue 53 item
10); `velocity` chosen in Vectors is traced, with the units warning."""
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

# gfs_wind10m with the defaults: not its active vectors, whose units fail the
# time line's check, but the array whose units fit; the note says why, and
# nothing warns of the units of an array not traced.
reader = OpenDataFile(os.path.join(args.data, "gfs_wind10m.pvd"))
reader.UpdatePipeline()
with bptest.CapturedMessages(texts=True) as log:
    tracer = BoundParticleTracer(Input=reader)
    chosen = list(tracer.Vectors)
    tracer.UpdatePipeline(tracer.TimestepValues[1])
bptest.check(chosen == ["POINTS", "velocity_deg_per_hour"],
             "gfs_wind10m: the default Vectors is the array whose units fit: %s" % chosen)
notes = [m for m in log.messages if "traces 'velocity_deg_per_hour'" in m]
bptest.check(len(notes) == 1 and "its units fit the grid and the time steps" in notes[0] and
             "those of 'velocity', the input's active vectors, do not" in notes[0] and
             "an element crosses 19% of the field" in notes[0],
             "gfs_wind10m: Output Messages says once why: %s" % log.messages)
bptest.check(not [m for m in log.messages if UNITS in m],
             "gfs_wind10m: no units warning of the array not traced: %s" % log.messages)
# Chosen in Vectors, `velocity` is traced, and its units are warned of once.
with bptest.CapturedMessages(texts=True) as log:
    tracer.Vectors = ["POINTS", "velocity"]
    tracer.UpdatePipeline(tracer.TimestepValues[1])
    tracer.UpdatePipeline(tracer.TimestepValues[2])
bptest.check(list(tracer.Vectors) == ["POINTS", "velocity"],
             "gfs_wind10m: velocity set in Vectors is kept: %s" % list(tracer.Vectors))
said = [m for m in log.messages if UNITS in m]
bptest.check(len(said) == 1 and "between two input time steps" in said[0] and
             log.messages and any("traces 'velocity' (the input's active vectors)" in m
                                  for m in log.messages),
             "gfs_wind10m velocity: traced, its units warned of once: %s" % log.messages)
Delete(tracer)
Delete(reader)
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
