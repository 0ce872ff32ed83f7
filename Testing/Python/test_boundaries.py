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
- Stick, Slip and Bounce (the grid's sides as a wall): in the same shear
  layer every element stays shown and is never released again (its lifetime
  left is the first release's), every particle is finite and in the field,
  and the walled elements pile up at the outflow side x = 1; Restitution
  outside [0, 1] is refused by name; a wall with Linking is refused.
- On a real grid (a Wavelet image, a uniform flow (1, 0.5, 0) put on it by
  a Calculator) strips driven into the side x = 10 with Slip lie on it and
  slide along it (+y) at the flow's tangential speed; with Stick they stop.
- Periodic along x on the same Wavelet (period 20) in the flow (1, 0, 0):
  every strip is back where it was after one period, whole, its centre
  inside the period, with no message; a flow whose last plane differs from its
  first is traced with a warning; with Trails the trails break at the seam
  (no pose a period from its strip, a strip that has not crossed keeps every
  pose), and the GPU engine's Bound Particles display draws the same picture
  as the CPU engine's; Periodic with Linking, and along a flat axis, is refused by name.
"""
import os
import shutil
import sys
import tempfile

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
bptest.check(terminate.GetProperty("Boundary").Available ==
             ["Release Again", "Terminate", "Stick", "Slip", "Bounce"],
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

# The grid's sides as a wall: nothing leaves, nothing is released again.
for wall in ("Stick", "Slip", "Bounce"):
    walled = tracer(wall)
    walled.Restitution = 0.5
    data = bptest.fetch(walled, 1.8)
    kept, points = shown(data)
    left = bptest.point_array(data, "Lifetime")[::N]
    every = vtk_to_numpy(data.GetPoints().GetData())
    print("%s at t = 1.8: %d shown, %d points, x up to %.4f, lifetimes left %.3f to %.3f"
          % (wall, len(kept), len(every), every[:, 0].max(), left.min(), left.max()))
    bptest.check(len(kept) == COUNT, "%s shows every element: %d" % (wall, len(kept)))
    bptest.check(np.all(np.isfinite(every)), "%s: every point finite" % wall)
    bptest.check(np.abs(every).max() <= 1.0 + 1e-6, "%s: every particle in the field: %.6f"
                 % (wall, np.abs(every).max()))
    bptest.check(np.allclose(left, 0.2, atol=1e-3), "%s: none released again: lifetimes left "
                 "%.3f to %.3f" % (wall, left.min(), left.max()))
    atWall = np.mean(points[:, :, 0].max(axis=1) > 1.0 - 0.05)
    bptest.check(atWall > 0.3, "%s: the elements carried out pile up at x = 1: %.2f of them"
                 % (wall, atWall))
    walled.Restitution = 1.5
    with bptest.CapturedMessages() as said:
        refused = bptest.fetch(walled, 0.5)
    bptest.check(said.mentions("Restitution must be between 0 and 1"),
                 "%s: Restitution 1.5 is refused by name: %s" % (wall, said.messages))
    bptest.check(refused.GetNumberOfPoints() == 0, "%s: no output when refused" % wall)
    walled.Restitution = 1.0
    walled.Linking = "Chain"
    with bptest.CapturedMessages() as said:
        bptest.fetch(walled, 0.5)
    bptest.check(said.mentions("Boundary = %s" % wall) and said.mentions("Linking"),
                 "%s with Linking is refused: %s" % (wall, said.messages))
    Delete(walled)

# A strip sliding along a wall of a real grid: a Wavelet image ([-10, 10]^3,
# spacing 1) with the uniform flow (1, 0.5, 0); the strips start at x = 6,
# reach the side x = 10 after about 4 and slide along it in +y.
wavelet = Wavelet()
uniform = Calculator(Input=wavelet, ResultArrayName="wind", Function="iHat + 0.5*jHat")
uniform.UpdatePipeline()


def sliding(boundary):
    return BoundParticleTracer(Input=uniform, Vectors=["POINTS", "wind"],
                               ElementShape="Strip4", NumberOfElements=20, ElementSize=1.0,
                               EmitterCenter=[6, -6, 0], EmitterSize=[1, 1, 8],
                               StepSizeUnit="Time", StepSize=0.05, Duration=10,
                               LifetimeRange=[20, 20], Seed=5, Boundary=boundary)


for wall in ("Slip", "Stick"):
    strips = sliding(wall)
    first = vtk_to_numpy(bptest.fetch(strips, 6.0).GetPoints().GetData()).reshape(-1, N, 3)
    later = vtk_to_numpy(bptest.fetch(strips, 8.0).GetPoints().GetData()).reshape(-1, N, 3)
    onWall = np.mean(np.abs(later[:, :, 0] - 10.0) < 1e-3)
    climb = (later[:, :, 1] - first[:, :, 1]).mean()
    print("%s on the Wavelet: %.2f of the particles on x = 10 at t = 8, mean y moved %.3f from "
          "t = 6" % (wall, onWall, climb))
    bptest.check(np.all(np.isfinite(later)) and later[:, :, 0].max() <= 10.0,
                 "%s: every particle finite and inside x = 10" % wall)
    if wall == "Slip":
        bptest.check(onWall > 0.95, "Slip: the strips lie on the wall: %.2f of the particles"
                     % onWall)
        bptest.check(abs(climb - 1.0) < 0.05, "Slip: they slide at the flow's 0.5 along the "
                     "wall: %.3f in 2" % climb)
    else:
        bptest.check(climb < 0.2, "Stick: they stop on the wall: %.3f in 2" % climb)
    Delete(strips)

# Periodic along x on the Wavelet (period 20, its extent) in the uniform flow
# (1, 0, 0): every strip crosses the seam at x = 10 and is back where it was
# after one period, t = 1 to t = 21, whole (never released again), its centre
# always inside [-10, 10] along x.
along = Calculator(Input=wavelet, ResultArrayName="wind", Function="iHat")
periodic = BoundParticleTracer(Input=along, Vectors=["POINTS", "wind"], ElementShape="Strip4",
                               NumberOfElements=20, ElementSize=1.0, EmitterCenter=[0, 0, 0],
                               EmitterSize=[16, 16, 16], StepSizeUnit="Time", StepSize=0.05,
                               Duration=22, LifetimeRange=[100, 100], Seed=5, Periodic=[1, 0, 0])
with bptest.CapturedMessages() as said:
    start = vtk_to_numpy(bptest.fetch(periodic, 1.0).GetPoints().GetData()).reshape(-1, N, 3)
bptest.check(not said.messages, "Periodic on a flow whose planes repeat: no message: %s"
             % said.messages[:2])
middle = vtk_to_numpy(bptest.fetch(periodic, 9.0).GetPoints().GetData()).reshape(-1, N, 3)
back = vtk_to_numpy(bptest.fetch(periodic, 21.0).GetPoints().GetData()).reshape(-1, N, 3)
moved = np.abs(back - start).max()
centres = middle.mean(axis=1)
print("Periodic x on the Wavelet: back within %.2g after one period; centres at t = 9 in x "
      "%.3f to %.3f" % (moved, centres[:, 0].min(), centres[:, 0].max()))
bptest.check(moved < 1e-3, "Periodic: every strip back where it was after one period: %.2g"
             % moved)
bptest.check(centres[:, 0].min() >= -10.0 and centres[:, 0].max() <= 10.0,
             "Periodic: the centres stay in the period: %.3f to %.3f"
             % (centres[:, 0].min(), centres[:, 0].max()))
spread = np.abs(middle[:, :, 0] - middle[:, :1, 0]).max()
bptest.check(spread < 5.0, "Periodic: no strip torn across the seam: %.3f" % spread)
# With Trails (8 poses, 0.2 apart) the trails break at the jump: no pose
# lies a period from its strip, and a strip that has not crossed the seam
# over the trail's span (its centre 1.6 + 1 past x = -10) keeps all 8.
periodic.Trails = 1
with bptest.CapturedMessages() as said:
    trailed = bptest.fetch(periodic, 9.0)
bptest.check(not said.messages, "Periodic with Trails: no message: %s" % said.messages[:2])
xs = vtk_to_numpy(trailed.GetPoints().GetData())[:, 0].reshape(-1, N)
ids = vtk_to_numpy(trailed.GetPointData().GetArray("ElementId"))[::N]
ages = vtk_to_numpy(trailed.GetPointData().GetArray("Age"))[::N]
now = {int(i): x.mean() for i, x, a in zip(ids, xs, ages) if a == 0.0}
poses = [(int(i), x.mean()) for i, x, a in zip(ids, xs, ages) if a > 0.0]
away = max(abs(x - now[i]) for i, x in poses) if poses else float("nan")
settled = [i for i, c in now.items() if c > -10.0 + 1.6 + 1.0]
kept = min(sum(1 for j, _ in poses if j == i) for i in settled) if settled else 0
print("Periodic x with Trails: %d poses of %d strips, at most %.3f from their strip in x; "
      "%d strips past the seam's reach, each with %d poses or more"
      % (len(poses), len(now), away, len(settled), kept))
bptest.check(len(now) == 20 and len(poses) > 0, "Periodic with Trails: strips and their trails")
bptest.check(away < 2.0, "Periodic with Trails: no pose across the seam (%.3f from its strip)"
             % away)
bptest.check(len(settled) > 10 and kept == 8,
             "Periodic with Trails: a strip that has not crossed keeps its 8 poses (%d)" % kept)
bptest.check(len(poses) < 8 * 20, "Periodic with Trails: strips that crossed lost their older "
             "poses (%d of 160 shown)" % len(poses))


def periodic_trails_picture(path, engine):
    """The strips and their trails at t = 9 from +z in the Bound Particles
    display, traced by `engine`."""
    periodic.Engine = engine
    view = CreateRenderView()
    view.ViewSize = [600, 400]
    view.ViewTime = 9.0
    view.OrientationAxesVisibility = 0
    shown = Show(periodic, view)
    shown.SetRepresentationType("Bound Particles")
    ColorBy(shown, None)
    view.CameraPosition = [0, 0, 60]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 12
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[600, 400])
    Delete(shown)
    Delete(view)


# The GPU display breaks its trails as the CPU output does: with either
# engine the same picture (measured: mean 0.002, no pixel; the GPU display
# without the break, drawing two poses across the seam: mean 0.04, 5.7e-4
# of the pixels).
engine_before = periodic.Engine
pictures = tempfile.mkdtemp(prefix="bp_periodic_trails_")
cpu_picture = os.path.join(pictures, "cpu.png")
gpu_picture = os.path.join(pictures, "gpu.png")
periodic_trails_picture(cpu_picture, "CPU")
periodic_trails_picture(gpu_picture, "GPU")
mean, pixels = bptest.image_difference(cpu_picture, gpu_picture)
print("Periodic x with Trails, Bound Particles display, GPU against CPU: mean %.4f, pixels %.5f"
      % (mean, pixels))
bptest.check(mean < 0.03 and pixels < 2e-4, "Periodic with Trails: the GPU display breaks the "
             "trails as the CPU does: mean %.4f, pixels %.5f" % (mean, pixels))
shutil.rmtree(pictures, ignore_errors=True)
periodic.Engine = engine_before
periodic.Trails = 0
periodic.Linking = "Chain"
with bptest.CapturedMessages() as said:
    refused = bptest.fetch(periodic, 2.0)
bptest.check(said.mentions("cannot be used with Linking"),
             "Periodic with Linking is refused: %s" % said.messages)
bptest.check(refused.GetNumberOfPoints() == 0, "Periodic with Linking: no output")
periodic.Linking = "None"
# A flow whose last x plane is not a copy of its first (u = x / 10 + 1, 0
# at x = -10 and 2 at x = 10) is traced, with a warning that names the axis.
along.Function = "(coordsX / 10 + 1) * iHat"
with bptest.CapturedMessages() as said:
    traced = bptest.fetch(periodic, 2.0)
bptest.check(said.mentions("Periodic along x: the grid's last plane along x is not a copy"),
             "Periodic on planes that differ: a warning by name: %s" % said.messages)
bptest.check(traced.GetNumberOfPoints() > 0, "Periodic on planes that differ: still traced")
Delete(periodic)
flat = Wavelet(WholeExtent=[-10, 10, -10, 10, 0, 0])
flatWind = Calculator(Input=flat, ResultArrayName="wind", Function="iHat")
onPlane = BoundParticleTracer(Input=flatWind, Vectors=["POINTS", "wind"], ElementShape="Strip4",
                              NumberOfElements=5, ElementSize=1.0, StepSizeUnit="Time",
                              StepSize=0.05, Duration=1, Periodic=[0, 0, 1])
with bptest.CapturedMessages() as said:
    refused = bptest.fetch(onPlane, 0.5)
bptest.check(said.mentions("Periodic along z needs the grid to have more than one point"),
             "Periodic along a flat axis is refused by name: %s" % said.messages)
bptest.check(refused.GetNumberOfPoints() == 0, "Periodic along a flat axis: no output")
# The boundary of a mesh as a wall (issue 58): an annulus r in [1, 2] (a
# curvilinear mesh, resampled inside the tracer; its hole is cells outside
# the flow) in solid-body rotation with an inward drift of 1, so every strip
# reaches the hole's side within 0.8. With Slip the strips lie down on the
# hole's staircase of cell faces and slide around it: no particle in the
# hole, the elements keep turning, none released again (their centres keep
# turning from where they started).
annulus = ProgrammableSource(OutputDataSetType="vtkStructuredGrid")
annulus.Script = """
import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
nr, nt, nz = 9, 73, 5
r, t, z = numpy.meshgrid(numpy.linspace(1, 2, nr), numpy.linspace(0, 2 * numpy.pi, nt),
                         numpy.linspace(0, 0.5, nz), indexing="ij")
xyz = numpy.stack([r * numpy.cos(t), r * numpy.sin(t), z], -1).transpose(2, 1, 0, 3).reshape(-1, 3)
out = self.GetOutput()
out.SetDimensions(nr, nt, nz)
points = vtkPoints(); points.SetData(numpy_to_vtk(xyz.copy(), deep=1)); out.SetPoints(points)
radius = numpy.hypot(xyz[:, 0], xyz[:, 1])
v = numpy.stack([-xyz[:, 1] - xyz[:, 0] / radius, xyz[:, 0] - xyz[:, 1] / radius, 0 * radius], -1)
v = numpy_to_vtk(v.copy(), deep=1)
v.SetName("velocity"); out.GetPointData().AddArray(v)
"""
annulus.ScriptRequestInformation = """
from paraview import util
util.SetOutputWholeExtent(self, [0, 8, 0, 72, 0, 4])
"""
annulus.UpdatePipeline()
for wall in ("Slip", "Release Again"):
    ring = BoundParticleTracer(Input=annulus, Vectors=["POINTS", "velocity"],
                               ElementShape="Strip4", NumberOfElements=40, ElementSize=0.15,
                               EmitterCenter=[1.6, 0, 0.25], EmitterSize=[0.3, 0.3, 0.3],
                               StepSizeUnit="Time", StepSize=0.01, Duration=1.5,
                               NumberOfTimeSteps=4, LifetimeRange=[100, 100],
                               MinimumReleaseSpeed=0, Seed=5, Boundary=wall)
    start = vtk_to_numpy(bptest.fetch(ring, 0.0).GetPoints().GetData()).reshape(-1, N, 3)
    end = vtk_to_numpy(bptest.fetch(ring, 1.5).GetPoints().GetData()).reshape(-1, N, 3)
    radius = np.hypot(end[:, :, 0], end[:, :, 1])
    before, after = start.mean(1), end.mean(1)
    angle = np.arctan2(after[:, 1], after[:, 0]) - np.arctan2(before[:, 1], before[:, 0])
    angle = (angle + np.pi) % (2 * np.pi) - np.pi
    print("%s on the annulus: particles at r %.4f..%.4f at t = 1.5, %.2f of them within 0.15 "
          "of the hole, elements turned %.3f (median; 1.5 without the wall)"
          % (wall, radius.min(), radius.max(), np.mean(radius < 1.15), np.median(angle)))
    if wall == "Slip":
        bptest.check(np.all(np.isfinite(end)) and radius.min() > 0.99,
                     "Slip: no particle in the annulus' hole (r = %.4f)" % radius.min())
        bptest.check(np.mean(radius < 1.15) > 0.9,
                     "Slip: the strips lie on the hole's side: %.2f" % np.mean(radius < 1.15))
        bptest.check(np.median(angle) > 0.8,
                     "Slip: they slide around it: turned %.3f" % np.median(angle))
    else:
        bptest.check(np.mean(radius < 1.15) < 0.5,
                     "Release Again: strips that reach the hole are released again: %.2f on "
                     "its side" % np.mean(radius < 1.15))
    Delete(ring)

bptest.finish()
