"""Save and resume as a pvpython user does it: SaveData on the tracer's State
output (OutputPort(tracer, 2)), as .vtp and as .pvtp with the writers'
defaults, then a new tracer with InitialStateFile goes on from it: its points
and every point array equal a trace that never stopped (numpy.array_equal),
it steps only from the state on, and a state from another setting, or from
before the trace's start, is said with an empty output.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
folder = bptest.scratch("bp-save-resume-")

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[32, 16, 2], NumberOfTimeSteps=21)


def tracer_on(**extra):
    settings = dict(Input=flow, Vectors=["POINTS", "velocity"], Engine="CPU",
                    NumberOfElements=300, Seed=3, ElementShape="Cross",
                    LifetimeRange=[1.0, 3.0], Trails=1, TrailLength=4)
    settings.update(extra)
    return BoundParticleTracer(**settings)


def arrays(data):
    """The points and every point array, as numpy."""
    out = {"points": vtk_to_numpy(data.GetPoints().GetData()).copy()}
    for k in range(data.GetPointData().GetNumberOfArrays()):
        a = data.GetPointData().GetArray(k)
        if a is not None:
            out[a.GetName()] = vtk_to_numpy(a).copy()
    return out


def same(a, b):
    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)


SAVE_AT, LATER = 3.0, 7.5
saver = tracer_on()
saver.UpdatePipeline(SAVE_AT)


def steps_to(tracer, t):
    """The steps the update to t took (read before a fetch updates again)."""
    tracer.UpdatePipeline(t)
    tracer.UpdatePropertyInformation()
    return tracer.GetPropertyValue("StepsInLastUpdate")


straight = tracer_on()
straight_steps = steps_to(straight, LATER)
expected = arrays(bptest.fetch(straight, LATER))

for name in ("state.vtp", "state.pvtp"):
    path = os.path.join(folder, name)
    SaveData(path, proxy=OutputPort(saver, 2))
    bptest.check(os.path.exists(path), "SaveData wrote %s" % name)
    resumed = tracer_on(InitialStateFile=path)
    with bptest.CapturedMessages() as messages:
        steps = steps_to(resumed, LATER)
        got = arrays(bptest.fetch(resumed, LATER))
    # ParaView 6.1's XML piece reader (VTK 9.6) says it cannot read back the
    # L2_NORM_RANGE information key its own writer stored with an array whose
    # norm range ParaView had computed; the arrays themselves read whole (the
    # check below), so that message alone is not the tracer's.
    said = [m for m in messages.messages if "L2_NORM_RANGE" not in m]
    bptest.check(not said, "%s: no messages: %s" % (name, said[:2]))
    bptest.check(same(got, expected),
                 "%s: resumed at %s, every array equals the trace that never stopped" % (name, LATER))
    bptest.check(0 < steps < straight_steps,
                 "%s: %d steps from the state, %d from the start" % (name, steps, straight_steps))
    Delete(resumed)

# The saved state opens as data: one poly-vertex per element.
reader = XMLPolyDataReader(FileName=[os.path.join(folder, "state.vtp")])
reader.UpdatePipeline()
info = reader.GetDataInformation()
bptest.check(info.GetNumberOfCells() == 300 and info.GetNumberOfPoints() == 300 * 12,
             "the state file holds 300 crosses of 12 particles (%d cells, %d points)"
             % (info.GetNumberOfCells(), info.GetNumberOfPoints()))

# Another setting: said by name, nothing shown; cleared, the trace starts over.
other = tracer_on(NumberOfElements=200, InitialStateFile=os.path.join(folder, "state.vtp"))
with bptest.CapturedMessages() as messages:
    data = bptest.fetch(other, LATER)
bptest.check(data.GetNumberOfPoints() == 0, "a state of another setting shows nothing")
bptest.check(any("numberOfElements: the state's 300, this trace's 200" in m
                 for m in messages.messages), "said by name: %s" % messages.messages[:1])
other.InitialStateFile = ""
bptest.check(bptest.fetch(other, LATER).GetNumberOfPoints() > 0, "cleared, the trace starts over")

# A state from before this trace's start (the same flow, its times shifted
# later): saved by another trace, said, nothing shown; never silently unused.
shifted = TemporalShiftScale(Input=flow, PreShift=SAVE_AT + 1.0)
late = tracer_on(Input=shifted, InitialStateFile=os.path.join(folder, "state.vtp"))
with bptest.CapturedMessages() as messages:
    data = bptest.fetch(late, SAVE_AT + 5.0)
bptest.check(data.GetNumberOfPoints() == 0 and messages.mentions("lies before this trace's start"),
             "a state before the trace's start is said (%d points): %s"
             % (data.GetNumberOfPoints(), messages.messages[:1]))

bptest.finish()
