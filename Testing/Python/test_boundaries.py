"""Boundary through the tracer, as pvpython users meet it.

- In the shear layer (u(z) = 1.25 - z^2 along x) elements released in the
  field's left half are carried out through x = 1. With Boundary = Terminate
  those that left are hidden (no cells) until their lifetime runs out, so at
  t = 1.8 fewer elements are shown than with Release Again, which releases
  them again at once; every particle shown with Terminate (Reset When = Any
  Particle Leaves) lies in the field.
- After their lifetime (2) the terminated ones come back as their next
  generation: at t = 2.1 every element is shown again.
- Terminate with a super set (Linking) is refused with a message that says
  so, and the output is empty.
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
N = 4  # particles of a Strip4
COUNT = 150

flow = AnalyticFlow(Flow="Shear Layer", Resolution=[24, 24, 24])
flow.UpdatePipeline()


def tracer(boundary):
    return BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                               ElementShape="Strip4", NumberOfElements=COUNT,
                               ElementSize=0.1, EmitterCenter=[-0.5, 0, 0],
                               EmitterSize=[0.8, 1.8, 1.8], StepSizeUnit="Time",
                               StepSize=0.02, Duration=2.4, LifetimeRange=[2, 2], Seed=3,
                               ResetWhen="Any Particle Leaves", Boundary=boundary,
                               OutputArrays=["ElementId", "Lifetime"])


def shown(data):
    """The elements with cells, and every point of theirs."""
    elements = {data.GetCell(c).GetPointId(0) // N for c in range(data.GetNumberOfCells())}
    points = vtk_to_numpy(data.GetPoints().GetData()).reshape(-1, N, 3)
    return elements, points[sorted(elements)]


terminate, again = tracer("Terminate"), tracer("Release Again")
bptest.check(terminate.Boundary == "Terminate" and again.Boundary == "Release Again",
             "Boundary is set by name")
bptest.check(terminate.GetProperty("Boundary").Available == ["Release Again", "Terminate"],
             "Boundary offers %s" % terminate.GetProperty("Boundary").Available)
late, lateAgain = bptest.fetch(terminate, 1.8), bptest.fetch(again, 1.8)
kept, keptPoints = shown(late)
keptAgain, _ = shown(lateAgain)
print("at t = 1.8: %d elements shown with Terminate, %d with Release Again"
      % (len(kept), len(keptAgain)))
bptest.check(len(keptAgain) == COUNT, "Release Again shows every element: %d" % len(keptAgain))
bptest.check(len(kept) < COUNT - 20, "Terminate shows fewer elements: %d" % len(kept))
bptest.check(late.GetNumberOfPoints() == COUNT * N, "terminated elements keep their points")
outside = np.abs(keptPoints).max() if len(kept) else 0.0
bptest.check(outside <= 1.0 + 1e-6, "no particle shown outside the field: %.4f" % outside)
# Lifetime is what is left of it: 0.2 for every element of the first release.
left = bptest.point_array(late, "Lifetime")[::N]
bptest.check(np.allclose(left, 0.2, atol=1e-3), "the terminated are not released again before "
             "their lifetime ends: lifetimes left %.3f to %.3f" % (left.min(), left.max()))
leftAgain = bptest.point_array(lateAgain, "Lifetime")[::N]
bptest.check(leftAgain.max() > 0.3, "Release Again released some again: most left %.3f"
             % leftAgain.max())

back = bptest.fetch(terminate, 2.1)
returned, _ = shown(back)
left = bptest.point_array(back, "Lifetime")[::N]
print("at t = 2.1: %d shown, lifetimes left %.3f to %.3f" % (len(returned), left.min(), left.max()))
bptest.check(len(returned) == COUNT, "after their lifetime every element is shown again: %d"
             % len(returned))
bptest.check(np.all(left > 1.8), "as its next generation: least left %.3f" % left.min())

# A super set lives out its lifetime whole: Terminate is refused.
terminate.Linking = "Chain"
with bptest.CapturedMessages() as said:
    data = bptest.fetch(terminate, 0.5)
bptest.check(said.mentions("Boundary = Terminate"), "Linking with Terminate is refused with a "
             "message: %s" % said.messages)
bptest.check(data.GetNumberOfPoints() == 0, "no output when refused")
terminate.Linking = "None"
bptest.check(len(shown(bptest.fetch(terminate, 0.5))[0]) > 0, "traces again after")
bptest.finish()
