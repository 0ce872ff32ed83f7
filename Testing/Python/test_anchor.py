"""Anchor = Centre through the tracer, as pvpython users meet it.

- Anchored paddlewheels in the shear layer keep their centres where they were
  released (every element, by ElementId, over the whole trace) while a free
  tracer on the same input carries its elements downstream: the two shown
  together are two tracers on one input.
- They still turn: ElementSpin is non-zero where the vorticity is, about y at
  half the local vorticity (-z), as the free ones' is; Orientation is a unit
  quaternion, the same on every particle of an element.
- Anchor with a super set (Linking) is refused with a message that says so,
  and the output is empty.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()
N = 8  # particles of a paddlewheel


def elements(data):
    """Per element, in ElementId order: centre, spin, orientation."""
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))[::N]
    order = np.argsort(ids)
    points = vtk_to_numpy(data.GetPoints().GetData()).reshape(-1, N, 3)
    spin = vtk_to_numpy(data.GetPointData().GetArray("ElementSpin")).reshape(-1, N, 3)
    q = vtk_to_numpy(data.GetPointData().GetArray("Orientation")).reshape(-1, N, 4)
    return points.mean(axis=1)[order], spin[order], q[order]


flow = AnalyticFlow(Flow="Shear Layer", Resolution=[32, 32, 32])
flow.UpdatePipeline()


def tracer(anchor):
    return BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                               ElementShape="Paddlewheel", NumberOfElements=120,
                               ElementSize=0.15, EmitterCenter=[0, 0, 0],
                               EmitterSize=[1.0, 1.0, 1.4], Integrator="Runge-Kutta 4",
                               Restoration="Shape Matching", StepSizeUnit="Time",
                               StepSize=0.02, Duration=1.0, LifetimeRange=[100, 100], Seed=5,
                               Anchor=anchor,
                               OutputArrays=["ElementId", "ElementSpin", "Orientation"])


anchored, free = tracer("Centre"), tracer("None")
bptest.check(anchored.Anchor == "Centre" and free.Anchor == "None", "Anchor is set by name")
start, _, _ = elements(bptest.fetch(anchored, 0.0))
freeStart, _, _ = elements(bptest.fetch(free, 0.0))
bptest.check(np.allclose(start, freeStart, atol=1e-6), "both tracers release at the same places")
worst = 0.0
for time in (0.3, 0.6, 1.0):
    centres, spin, q = elements(bptest.fetch(anchored, time))
    worst = max(worst, float(np.abs(centres - start).max()))
print("anchored centres within %.2e of their release centres" % worst)
bptest.check(worst < 1e-5, "anchored centres stay: off by up to %.2e" % worst)
# Free ones drift downstream (not yet out of the field at x = 1).
freeCentres, freeSpin, _ = elements(bptest.fetch(free, 0.3))
drift = freeCentres[:, 0] - freeStart[:, 0]
expected = 0.3 * (1.25 - start[:, 2] ** 2)  # u(z) = 1.25 - z^2
bptest.check(np.all(drift > 0.8 * expected),
             "free elements drift downstream: least drift / u %.3f" % (drift / expected).min())

# Spins: non-zero where the vorticity (0, -2z, 0) is, about y at half of it.
bptest.check(np.allclose(np.linalg.norm(q, axis=2), 1.0, atol=1e-5), "unit quaternions")
bptest.check(np.all(spin == spin[:, :1]) and np.all(q == q[:, :1]),
             "ElementSpin and Orientation are the same on every particle")
s, z = spin[:, 0], start[:, 2]
strong = np.abs(z) > 0.3
err = np.abs(s[strong, 1] + z[strong]) / np.abs(z[strong])
print("anchored spins about y: median relative error %.3f to half the vorticity, over %d "
      "elements" % (np.median(err), strong.sum()))
bptest.check(strong.sum() > 20, "enough elements where the vorticity is strong")
bptest.check(np.all(np.abs(s[strong, 1]) > 0.15), "ElementSpin is non-zero where vorticity is")
bptest.check(np.median(err) < 0.1, "spin about y is half the vorticity: median error %.3f" %
             np.median(err))
bptest.check(np.all(np.sign(s[strong, 1]) == -np.sign(z[strong])), "spin sign follows height")
freeS = freeSpin[:, 0]
freeErr = np.abs(freeS[strong, 1] + freeCentres[strong, 2]) / np.abs(freeCentres[strong, 2])
bptest.check(np.median(freeErr) < 0.1, "free ones spin alike: median error %.3f" %
             np.median(freeErr))

# A super set cannot be anchored: said, and nothing output.
anchored.Linking = "Sheet"
with bptest.CapturedMessages() as said:
    data = bptest.fetch(anchored, 0.5)
bptest.check(said.mentions("cannot be anchored"), "Linking with Anchor is refused with a "
             "message: %s" % said.messages)
bptest.check(data.GetNumberOfPoints() == 0, "no output when refused")
anchored.Linking = "None"
bptest.check(elements(bptest.fetch(anchored, 0.5))[0].shape == start.shape, "traces again after")
bptest.finish()
