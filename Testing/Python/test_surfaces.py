"""The Surfaces input (gates, outlets and walls) as pvpython users meet it.

Solid-body rotation (unit angular velocity about z, period 2 pi), 8 squares
released on the circle of radius 0.5 at angles (j + 1/2) 2 pi / 8:
- a Plane on the half-plane y = 0, x > 0 as a Gate: the Interactions port
  has each element once per turn (two turns traced), Passed, at the
  analytic time 2 pi k - a within a step, on the plane, with its normal
  and cell; the elements output is the same as without the Surfaces;
- the whole plane y = 0 in two cells with a cell array Kind (1: Outlet for
  x < 0, 0: Gate for x > 0): an element ends where it crosses the outlet
  (Terminated, at pi - a, or 3 pi - a after one passage of the gate) and is
  hidden from then on; a Bound Particles display with the GPU engine ends
  them at the outlet itself (no fallback to the CPU engine) and draws what
  the CPU engine's Surface display shows;
- a wall (Kind 2) with Slip keeps every particle on its side, with Slid
  events where they reach it, on a Bound Particles display with the GPU
  engine too (no fallback), drawn as the CPU engine's; with Stick the
  particles that reach it stay;
- bad input: Surfaces with no cells, outside the field, with NaN points or
  with values of Kind that name no interaction warn and lose nothing; a
  Kind with NaN, with no value that names an interaction, of 3 components
  or of strings is said as it is, once;
- SurfaceId is 6 + the block, null and empty blocks counted;
- with Linking, Anchor = Centre or Restitution 2 the update fails with one
  message per update, and again after a change.
"""
import builtins
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()

COUNT = 8
ANGLES = [2 * math.pi * (j + 0.5) / COUNT for j in range(COUNT)]
STEP = 0.01
END = 4 * math.pi + 0.1  # two turns

flow = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[17, 17, 17])
seeds = ProgrammableSource(OutputDataSetType="vtkPolyData")
seeds.Script = (
    "import math\n"
    "from vtkmodules.vtkCommonCore import vtkPoints\n"
    "p = vtkPoints()\n"
    "for a in %r: p.InsertNextPoint(0.5 * math.cos(a), 0.5 * math.sin(a), 0.0)\n"
    "self.GetOutput().SetPoints(p)\n" % (ANGLES,))


def plane_with_kinds(kinds, nan=False):
    """The plane y = 0 over x in [-1, 1], one cell per value of `kinds` along x
    (cell array Kind), normal -y; with `nan`, one point made NaN."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "from vtkmodules.vtkFiltersSources import vtkPlaneSource\n"
        "from vtkmodules.vtkCommonCore import vtkDoubleArray\n"
        "p = vtkPlaneSource(); p.SetOrigin(-1, 0, -1); p.SetPoint1(1, 0, -1)\n"
        "p.SetPoint2(-1, 0, 1); p.SetXResolution(%d); p.Update()\n"
        "out = self.GetOutput(); out.ShallowCopy(p.GetOutput())\n"
        "k = vtkDoubleArray(); k.SetName('Kind')\n"
        "for v in %r: k.InsertNextValue(v)\n"
        "out.GetCellData().AddArray(k)\n"
        "if %r: out.GetPoints().SetPoint(0, float('nan'), 0, 0)\n" % (len(kinds), kinds, nan))
    return source


def tracer(**extra):
    settings = dict(Input=flow, Vectors=["POINTS", "velocity"], SeedSource=seeds,
                    NumberOfElements=COUNT, ElementShape="Square", ElementSize=0.1,
                    ReleaseOrientation="Fixed", MinimumReleaseSpeed=0.0,
                    Integrator="Runge-Kutta 4", StepSizeUnit="Time", StepSize=STEP,
                    Duration=END, NumberOfTimeSteps=3, LifetimeRange=[100, 100],
                    OutputArrays=["ElementId"])
    settings.update(extra)
    return BoundParticleTracer(**settings)


def events(proxy, time=END):
    proxy.UpdatePipeline(time)
    data = servermanager.Fetch(proxy, None, None, 3)
    names = ("ElementId", "Time", "Interaction", "SurfaceId", "SurfaceCell", "Normal",
             "ElementVelocity")
    arrays = {n: bptest.point_array(data, n) for n in names}
    points = np.array([data.GetPoint(k) for k in range(data.GetNumberOfPoints())]).reshape(-1, 3)
    return arrays, points


def elements(proxy, time=END):
    data = bptest.fetch(proxy, time)
    return np.array([data.GetPoint(k) for k in range(data.GetNumberOfPoints())]), \
        data.GetNumberOfCells()


PASSED, TERMINATED = 5, 1

# A gate on the half-plane y = 0, x > 0.
gate = Plane(Origin=[0, 0, -1], Point1=[1, 0, -1], Point2=[0, 0, 1])
gated = tracer(Surfaces=gate)
a, points = events(gated)
bptest.check(a["Time"] is not None and len(a["Time"]) == 2 * COUNT,
             "two passages per element over two turns: %s" %
             (None if a["Time"] is None else len(a["Time"])))
worst = 0.0
for e in range(COUNT):
    mine = sorted(a["Time"][a["ElementId"] == e].tolist())
    expected = [2 * math.pi * k - ANGLES[e] for k in (1, 2)]
    bptest.check(len(mine) == 2, "element %d passes twice: %s" % (e, mine))
    if len(mine) == 2:
        worst = float(np.max(np.abs(np.array(mine + [worst]) - np.array(expected + [0.0]))))
print("worst passage time error %.3g (step %g)" % (worst, STEP))
bptest.check(worst < STEP, "each passage at the analytic time within a step: %.3g" % worst)
bptest.check(set(a["Interaction"].tolist()) == {PASSED}, "every event is Passed")
bptest.check(set(a["SurfaceId"].tolist()) == {6}, "the Surfaces' block 0 is SurfaceId 6")
bptest.check(set(a["SurfaceCell"].tolist()) == {0}, "the plane's one cell")
bptest.check(np.allclose(a["Normal"], [0, -1, 0], atol=1e-6), "the plane's normal, -y")
bptest.check(np.all(a["ElementVelocity"][:, 1] > 0.4), "the elements pass going +y")
bptest.check(np.all(np.abs(points[:, 1]) < 1e-5) and np.all(points[:, 0] > 0.45),
             "each passage on the plane, at the circle")
plain = tracer()
mine, cells = elements(gated)
theirs, plain_cells = elements(plain)
bptest.check(mine.shape == theirs.shape and np.array_equal(mine, theirs) and cells == plain_cells,
             "a gate changes nothing in the elements output")

# An outlet (x < 0) and a gate (x > 0) by the cell array Kind.
both = tracer(Surfaces=plane_with_kinds([1.0, 0.0]),
              SurfaceInteractionArray="Kind")
a, points = events(both)
rows = sorted(zip(a["ElementId"].tolist(), a["Time"].tolist(), a["Interaction"].tolist(),
                  a["SurfaceCell"].tolist()))
expected = []
for e, angle in enumerate(ANGLES):
    if angle > math.pi:
        expected.append((e, 2 * math.pi - angle, PASSED, 1))
        expected.append((e, 3 * math.pi - angle, TERMINATED, 0))
    else:
        expected.append((e, math.pi - angle, TERMINATED, 0))
bptest.check(len(rows) == len(expected) and builtins.all(
    r[0] == x[0] and abs(r[1] - x[1]) < STEP and r[2:] == x[2:] for r, x in zip(rows, expected)),
    "an outlet ends each element where it crosses, after the gate where it passes it: %s"
    % rows)
_, cells = elements(both)
bptest.check(cells == 0, "every element ended at the outlet is hidden: %d cells" % cells)

# A wall (x < 0, Kind 2) and a gate (x > 0) with Boundary = Slip: the
# rotation carries the squares down onto the wall's upper side, where they
# stay (the flow there is normal to it: nothing to slide along); a
# particle records a Slid event when it reaches it (again where the springs
# lifted it off).
walled = tracer(Surfaces=plane_with_kinds([2.0, 0.0]), SurfaceInteractionArray="Kind",
                Boundary="Slip", OutputArrays=["ElementId", "ParticleIndex"])
a, points = events(walled, 5.0)
slid = a["Interaction"] == 3
bptest.check(slid.any() and np.all(a["SurfaceCell"][slid] == 0) and
             np.all(a["SurfaceId"][slid] == 6) and np.all(np.abs(points[slid, 1]) < 1e-5),
             "Slid events on the wall's cell: %d" % int(slid.sum()))
pairs = set(zip(a["ElementId"][slid].tolist(), bptest.point_array(
    servermanager.Fetch(walled, None, None, 3), "ParticleIndex")[slid].tolist()))
print("%d Slid events of %d particles" % (int(slid.sum()), len(pairs)))
bptest.check(len(pairs) >= 4 * 3, "the particles of at least three squares reach the wall")
positions, _ = elements(walled, 5.0)
on_wall_side = positions[positions[:, 0] < -0.05]
bptest.check(len(on_wall_side) > 0 and float(on_wall_side[:, 1].min()) >= -1e-6,
             "no particle passes the wall: lowest y %.3g over x < 0" %
             (float(on_wall_side[:, 1].min()) if len(on_wall_side) else float("nan")))
stuck = tracer(Surfaces=plane_with_kinds([2.0, 0.0]), SurfaceInteractionArray="Kind",
               Boundary="Stick", OutputArrays=["ElementId", "ParticleIndex"])
held_at_4, _ = elements(stuck, 4.0)
held_at_5, _ = elements(stuck, 5.0)
a, _ = events(stuck, 5.0)
on_wall = np.abs(held_at_4[:, 1]) < 1e-4
bptest.check(on_wall.any() and np.array_equal(held_at_4[on_wall], held_at_5[on_wall]),
             "Stick holds the particles on the wall: %d held, unmoved from t = 4 to 5"
             % int(on_wall.sum()))
at_wall = a["SurfaceCell"] == 0
bptest.check(at_wall.any() and np.all(a["Interaction"][at_wall] == 2),
             "their events at the wall (cell 0) are Stuck: %s" % a["Interaction"][at_wall])


# The GPU engine ends the elements at the outlet itself: at t = 2 three of
# the eight have ended (those released at angles a > pi - 2), at the end all.
def rendered(engine, representation, name, view_time, kinds=(1.0, 0.0), **extra):
    """The outlet's trace (or with `kinds` another) on `engine` drawn by
    `representation` at view_time: the picture's file and the messages the
    render gave."""
    t = tracer(Surfaces=plane_with_kinds(list(kinds)), SurfaceInteractionArray="Kind",
               Engine=engine, **extra)
    view = bptest.element_view((240, 180))
    shown = Show(t, view)
    shown.SetRepresentationType(representation)
    bptest.colour_display(shown, None, None)
    view.ViewTime = view_time
    with bptest.CapturedMessages() as said:
        Render(view)
    image = bptest.save_picture(view, pictures, name)
    Delete(t)
    return image, said


pictures = bptest.scratch("bp-surfaces-")  # not "output": a ProgrammableSource deletes it
cpu_image, _ = rendered("CPU", "Surface", "outlet_cpu", 2.0)
gpu_image, said = rendered("GPU", "Bound Particles", "outlet_gpu", 2.0)
mean, pixels = bptest.image_difference(cpu_image, gpu_image)
covered = bptest.covered_fraction(gpu_image)
print("outlet, GPU display against CPU Surface at t = 2: mean %.3f, pixels %.4f; %.4f drawn"
      % (mean, pixels, covered))
bptest.check(not said.messages, "the GPU display runs the outlet without a message: %s"
             % said.messages)
# (An element drawn on one engine only covers about 0.0007 of the picture.)
bptest.check(covered > 0.001 and mean <= 0.5 and pixels <= 0.0003,
             "the GPU display ends the elements at the outlet as the CPU engine does: mean %.3f, "
             "pixels %.4f, %.4f drawn" % (mean, pixels, covered))
end_image, said = rendered("GPU", "Bound Particles", "outlet_gpu_end", END)
bptest.check(bptest.covered_fraction(end_image) == 0.0 and not said.messages,
             "at the end every element has ended at the outlet on the GPU: %.4f drawn; %s"
             % (bptest.covered_fraction(end_image), said.messages))

# The GPU engine keeps the particles off the Slip wall itself (no fallback
# to the CPU engine): the squares resting on it drawn as the CPU engine's.
cpu_image, _ = rendered("CPU", "Surface", "wall_cpu", 3.0, (2.0, 0.0), Boundary="Slip")
gpu_image, said = rendered("GPU", "Bound Particles", "wall_gpu", 3.0, (2.0, 0.0),
                           Boundary="Slip")
mean, pixels = bptest.image_difference(cpu_image, gpu_image)
covered = bptest.covered_fraction(gpu_image)
print("Slip wall, GPU display against CPU Surface at t = 3: mean %.3f, pixels %.4f; %.4f drawn"
      % (mean, pixels, covered))
bptest.check(not said.messages, "the GPU display runs the wall without a message: %s"
             % said.messages)
bptest.check(covered > 0.001 and mean <= 0.5 and pixels <= 0.0003,
             "the GPU display keeps the particles off the wall as the CPU engine does: mean "
             "%.3f, pixels %.4f, %.4f drawn" % (mean, pixels, covered))

# Bad input: a clear warning, and the trace goes on. A Slip wall that reaches
# a periodic side warns too: a particle crossing the seam can pass it.
empty = ProgrammableSource(OutputDataSetType="vtkPolyData")
empty.Script = "pass"
far = Plane(Origin=[10, 10, 10], Point1=[11, 10, 10], Point2=[10, 11, 10])
cases = [("no cells", empty, {}, "no surface to act on"),
         ("outside the field", far, {}, "reaches into the field"),
         ("NaN points", plane_with_kinds([0.0, 0.0], nan=True), {}, "not finite"),
         ("unknown values", plane_with_kinds([1.0, 7.0]),
          {"SurfaceInteractionArray": "Kind"}, "names no interaction"),
         ("a missing array", gate, {"SurfaceInteractionArray": "Absent"},
          "no cell array 'Absent'"),
         ("a Slip wall at a periodic side", plane_with_kinds([2.0, 0.0]),
          {"SurfaceInteractionArray": "Kind", "Boundary": "Slip", "Periodic": [1, 0, 0]},
          "closer than one cell to a periodic side")]
for name, surface, extra, said in cases:
    with bptest.CapturedMessages() as messages:
        bad = tracer(Surfaces=surface, **extra)
        positions, cells = elements(bad, 1.0)
    bptest.check(messages.mentions(said), "%s: warned (%s): %s" % (name, said, messages.messages))
    bptest.check(cells > 0 and np.all(np.isfinite(positions)),
                 "%s: the trace goes on, finite (%d cells)" % (name, cells))
    Delete(bad)


def plane_with_array(cells, code):
    """The plane of plane_with_kinds in `cells` cells, with the cell array
    Kind that `code` makes as `k` (any class, any components)."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "from vtkmodules.vtkFiltersSources import vtkPlaneSource\n"
        "from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray\n"
        "p = vtkPlaneSource(); p.SetOrigin(-1, 0, -1); p.SetPoint1(1, 0, -1)\n"
        "p.SetPoint2(-1, 0, 1); p.SetXResolution(%d); p.Update()\n"
        "out = self.GetOutput(); out.ShallowCopy(p.GetOutput())\n%s\n"
        "out.GetCellData().AddArray(k)\n" % (cells, code))
    return source


# A bad Surface Interaction Array: each fault said as it is.
kinds = [
    ("NaN among unknown values", plane_with_array(4, "k = vtkDoubleArray(); k.SetName('Kind')\n"
     "for v in (3.0, -1.0, float('nan'), 1.0): k.InsertNextValue(v)"),
     ["3 cells", "such as -1 3 NaN)"], ["no surface to act on"]),
    ("no value names an interaction", plane_with_array(2, "k = vtkDoubleArray(); "
     "k.SetName('Kind')\nfor v in (1.5, 0.5): k.InsertNextValue(v)"),
     ["2 cells", "No cell of the Surfaces is left to act on"], ["no polygons"]),
    ("3 components", plane_with_array(2, "k = vtkDoubleArray(); k.SetName('Kind'); "
     "k.SetNumberOfComponents(3)\nk.InsertNextTuple3(1, 5, 5); k.InsertNextTuple3(0, 7, 7)"),
     ["cell array 'Kind' of 3 components: its first component is taken"], []),
    ("a string array", plane_with_array(2, "k = vtkStringArray(); k.SetName('Kind')\n"
     "k.InsertNextValue('1'); k.InsertNextValue('0')"),
     ["cell array 'Kind' that is not numeric (a vtkStringArray"], ["no cell array"])]
for name, surface, said, unsaid in kinds:
    with bptest.CapturedMessages() as messages:
        bad = tracer(Surfaces=surface, SurfaceInteractionArray="Kind")
        a, points = events(bad)
    bptest.check(len(messages.messages) == 1 and builtins.all(messages.mentions(m) for m in said) and
                 not builtins.any(messages.mentions(m) for m in unsaid),
                 "%s: one warning saying %s, not %s: %s" % (name, said, unsaid, messages.messages))
    if name == "3 components":
        # Component 0: cell 0 (x < 0) an Outlet, cell 1 a Gate.
        bptest.check(a["Interaction"] is not None and
                     set(a["Interaction"].tolist()) == {PASSED, TERMINATED},
                     "3 components: the first says Outlet and Gate: %s" % (
                         None if a["Interaction"] is None else set(a["Interaction"].tolist())))
    Delete(bad)

# SurfaceId is 6 + the block: the leaf's number from 0 among all the leaves,
# null and empty blocks included. Blocks [null, empty, null, the gate].
blocks = ProgrammableSource(OutputDataSetType="vtkMultiblockDataSet")
blocks.Script = (
    "from vtkmodules.vtkFiltersSources import vtkPlaneSource\n"
    "from vtkmodules.vtkCommonDataModel import vtkPolyData\n"
    "p = vtkPlaneSource(); p.SetOrigin(0, 0, -1); p.SetPoint1(1, 0, -1)\n"
    "p.SetPoint2(0, 0, 1); p.Update()\n"
    "out = self.GetOutput(); out.SetNumberOfBlocks(4)\n"
    "out.SetBlock(1, vtkPolyData()); out.SetBlock(3, p.GetOutput())\n")
with bptest.CapturedMessages() as messages:
    blocked = tracer(Surfaces=blocks, SurfaceInteractionArray="Absent")
    a, points = events(blocked)
bptest.check(a["SurfaceId"] is not None and len(a["SurfaceId"]) == 2 * COUNT and
             set(a["SurfaceId"].tolist()) == {9},
             "the gate in block 3 after null and empty blocks is SurfaceId 6 + 3: %s" %
             (None if a["SurfaceId"] is None else set(a["SurfaceId"].tolist())))
bptest.check(messages.mentions("(the first: block 3) have no cell array 'Absent'"),
             "the warnings number the blocks alike: %s" % messages.messages)
Delete(blocked)

# A refusal is said once per update (ParaView asks every port), and again
# at the next update after a change.
refusals = [("Linking", dict(Surfaces=gate, Linking="Chain", SeedSource=None),
             "Surfaces (gates, outlets and walls) act on single elements"),
            ("Anchor", dict(Surfaces=gate, Anchor="Centre"),
             "Surfaces (gates, outlets and walls) act on travelling elements"),
            ("Restitution", dict(Boundary="Bounce", Restitution=2.0),
             "Restitution must be between 0 and 1")]
for name, settings, refusal in refusals:
    refused = tracer(**settings)
    for update in ("first", "after a change"):
        with bptest.CapturedMessages() as messages:
            refused.UpdatePipeline(1.0)
            servermanager.Fetch(refused, None, None, 3)
        bptest.check(len(messages.messages) == 1 and messages.mentions(refusal),
                     "%s, %s update: refused once with a message: %s" %
                     (name, update, messages.messages))
        refused.ElementSize = 0.2
    Delete(refused)

# A state saved at a failed update holds no state and says why when it is
# resumed (not an empty state, nor an unrelated reader error).
refused = tracer(Boundary="Bounce", Restitution=2.0)
saved = os.path.join(bptest.scratch("bp-surfaces-"), "failed.vtp")
with bptest.CapturedMessages() as messages:
    refused.UpdatePipeline(1.0)
    SaveData(saved, proxy=OutputPort(refused, 2))
Delete(refused)
resumed = tracer(InitialStateFile=saved)
with bptest.CapturedMessages() as messages:
    resumed.UpdatePipeline(1.0)
bptest.check(messages.mentions("holds no state: the trace failed: ") and
             messages.mentions("Restitution must be between 0 and 1"),
             "a state saved at a failed update says the failure on resume: %s" % messages.messages)
Delete(resumed)
bptest.finish()
