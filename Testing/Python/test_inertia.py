"""Heavy particles (Inertia = Maxey-Riley) through the tracer, as pvpython users meet it.

- The properties' defaults, and Inertia off by default: the trace of a
  tracer with Inertia = Maxey-Riley and Response Time 0 is the massless one,
  point for point.
- Settling in still fluid: SlipVelocity and ParticleVelocity reach the
  terminal velocity Response Time x (1 - beta) x Gravity (within 1%), and the
  particles sink by the distance it gives.
- Solid-body rotation: heavy particles drift outwards, bubbles inwards, at
  tau (1 - beta) omega^2 r (within 5%).
- Bad settings are refused with a message naming the property and an empty
  output; Anchor with inertia is refused; a response time far below the step
  is noted as nearly massless; gravity far out of the data's units is warned
  of. The plugin's double gyre with the tracer's defaults, and the user
  guide's heavy particles on it, say nothing.
- The Bound Particles display with the GPU engine draws what the CPU engine's
  Surface display shows.
- On a flat field (2D data) heavy particles stay in the plane: Gravity's
  component across it is dropped with a warning, on both engines.
- Heavy particles in still fluid and in 1e-12 of noise: the automatic step
  follows their settling, they settle inside the box, and nothing is said.
- A state file brings the settings back; the Python trace records them. Its
  NaN, infinite and text values are said by name: a NaN Response Time is
  refused after reloading as before, Inertia as its entry's text takes it.
"""
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview import servermanager, smtrace  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()
VELOCITY = ["POINTS", "velocity"]


def points(data):
    return vtk_to_numpy(data.GetPoints().GetData()) if data.GetNumberOfPoints() else np.zeros((0, 3))


vortex = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[17, 17, 17])
vortex.UpdatePipeline()
bounds = vortex.GetDataInformation().GetBounds()
centre = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
          0.5 * (bounds[4] + bounds[5])]
still = Calculator(Input=vortex, ResultArrayName="still", Function="velocity*0")
still.UpdatePipeline()


def tracer(flow, vectors, **settings):
    base = dict(Input=flow, Vectors=vectors, ElementShape="Point", NumberOfElements=40,
                EmitterCenter=centre, EmitterSize=[0.2, 0.2, 0.2], LifetimeRange=[100, 100],
                Integrator="Runge-Kutta 4", StepSizeUnit="Time", StepSize=0.005, Duration=1.0,
                Seed=4, OutputArrays=["ElementId", "ParticleVelocity", "SlipVelocity",
                                      "Velocity"])
    base.update(settings)
    return BoundParticleTracer(**base)


massless = tracer(vortex, VELOCITY)
bptest.check(massless.Inertia == "None" and massless.ResponseTime == 0.1 and
             massless.DensityRatio == 1000 and list(massless.Gravity) == [0, 0, 0],
             "defaults: Inertia None, Response Time 0.1, Density Ratio 1000, no gravity")
zero = tracer(vortex, VELOCITY, Inertia="Maxey-Riley", ResponseTime=0.0, Gravity=[0, 0, -9.81])
a, b = bptest.fetch(massless, 1.0), bptest.fetch(zero, 1.0)
bptest.check(np.array_equal(points(a), points(b)) and len(points(a)) == 40,
             "Response Time 0 traces the massless particles, point for point")
bptest.check(not np.any(bptest.point_array(a, "SlipVelocity")) and
             np.array_equal(bptest.point_array(a, "ParticleVelocity"), bptest.point_array(a, "Velocity")),
             "without inertia the slip is 0 and ParticleVelocity is the flow's")

# Settling in still fluid.
tau, ratio, g = 0.05, 2.65, -4.0
beta = 3.0 / (1.0 + 2.0 * ratio)
terminal = tau * (1.0 - beta) * g
settling = tracer(still, ["POINTS", "still"], Inertia="Maxey-Riley", ResponseTime=tau,
                  DensityRatio=ratio, Gravity=[0, 0, g])
start = points(bptest.fetch(settling, 0.0))
data = bptest.fetch(settling, 0.5)
slip = bptest.point_array(data, "SlipVelocity")
expected = terminal * (1.0 - math.exp(-0.5 / tau))
worst = np.abs(slip[:, 2] - expected).max()
print("settling: terminal %.5f, slip within %.2e; sideways %.2e" %
      (terminal, worst, np.abs(slip[:, :2]).max()))
bptest.check(worst < 0.01 * abs(terminal) and not np.any(slip[:, :2]),
             "settles at Response Time x (1 - beta) x Gravity within 1%% (off by %.2e)" % worst)
bptest.check(np.allclose(bptest.point_array(data, "ParticleVelocity"), slip),
             "in still fluid the particle's velocity is its slip")
sunk = points(data)[:, 2] - start[:, 2]
fall = terminal * (0.5 - tau * (1.0 - math.exp(-0.5 / tau)))
bptest.check(np.abs(sunk - fall).max() < 0.01 * abs(fall),
             "sinks by %.4f (expected %.4f)" % (sunk.mean(), fall))


def drift(flow, ratio):
    """Mean log radial growth rate over [0, 1] of particles about the axis."""
    t = tracer(vortex, VELOCITY, Inertia="Maxey-Riley", ResponseTime=0.01, DensityRatio=ratio,
               EmitterSize=[0.6, 0.6, 0.2])
    r = []
    for time in (0.0, 1.0):
        p = points(bptest.fetch(t, time))
        ids = bptest.point_array(servermanager.Fetch(t), "ElementId")
        r.append(np.hypot(p[:, 0] - centre[0], p[:, 1] - centre[1])[np.argsort(ids)])
    Delete(t)
    return np.median(np.log(r[1] / r[0]))


for ratio in (1000.0, 0.001):
    rate = drift(vortex, ratio)
    expected = 0.01 * (1.0 - 3.0 / (1.0 + 2.0 * ratio))
    print("vortex, density ratio %g: radial rate %.5f, expected %.5f" % (ratio, rate, expected))
    bptest.check(abs(rate - expected) < 0.05 * abs(expected),
                 "density ratio %g drifts at tau (1 - beta) omega^2 r: %.5f against %.5f" %
                 (ratio, rate, expected))

# Bad settings: refused by name, with an empty output.
for name, value in (("ResponseTime", -1.0), ("ResponseTime", float("nan")),
                    ("DensityRatio", 0.0), ("Gravity", [0, float("nan"), 0])):
    setattr(settling, name, value)
    with bptest.CapturedMessages() as said:
        out = bptest.fetch(settling, 0.5)
    bptest.check(said.mentions(name) and out.GetNumberOfPoints() == 0,
                 "%s = %s is refused by name: %s" % (name, value, said.messages))
    settling.ResponseTime, settling.DensityRatio, settling.Gravity = tau, ratio, [0, 0, g]
settling.Anchor = "Centre"
with bptest.CapturedMessages() as said:
    out = bptest.fetch(settling, 0.5)
bptest.check(said.mentions("inertia has no meaning") and out.GetNumberOfPoints() == 0,
             "Anchor with inertia is refused: %s" % said.messages)
settling.Anchor = "None"
settling.ResponseTime = 1e-7
with bptest.CapturedMessages() as said:
    out = bptest.fetch(settling, 0.5)
bptest.check(said.mentions("close to massless") and out.GetNumberOfPoints() == 40,
             "a response time far below the step is noted: %s" % said.messages)
settling.ResponseTime = tau

# Gravity far out of the data's units (9.81 m/s^2 given as 1.27e5 km/h^2: the
# particles settle 10^5 times the field over their lifetime) is said once, by
# name; the settling above (8 times the field) is not.
UNITS = "Gravity may not be in the data's units"
with bptest.CapturedMessages() as said:
    bptest.fetch(settling, 0.5)
bptest.check(not said.mentions(UNITS), "sensible gravity is not warned of: %s" % said.messages)
settling.Gravity = [0, 0, -127137.6]
with bptest.CapturedMessages() as said:
    bptest.fetch(settling, 0.5)
gravity = [m for m in said.messages if UNITS in m]
bptest.check(len(gravity) == 1 and "-127138" in gravity[0],
             "gravity out of the data's units is said once: %s" % said.messages)
settling.Gravity = [0, 0, g]

# Heavy particles in still fluid and in noise (issue 53): the automatic step
# follows their settling (a particle falls half a cell a step), so they
# settle inside the box. The noise's own step was 4e10, which threw every
# particle far out of it, with a warning that blamed Gravity's units; the
# still field said that nothing would move.
noise = Calculator(Input=vortex, ResultArrayName="noise", Function="velocity*1e-12")
cell = (bounds[1] - bounds[0]) / 16.0
for name, fluid in (("still", still), ("noise", noise)):
    automatic = BoundParticleTracer(Input=fluid, Vectors=["POINTS", name], ElementShape="Point",
                                    NumberOfElements=40, Seed=4, Inertia="Maxey-Riley",
                                    ResponseTime=tau, DensityRatio=2.65, Gravity=[0, 0, g],
                                    OutputArrays=["SlipVelocity"])
    with bptest.CapturedMessages() as said:
        automatic.UpdatePipelineInformation()
        end = automatic.TimestepValues[-1]
        data = bptest.fetch(automatic, end)
    automatic.UpdatePropertyInformation()
    step = automatic.GetPropertyValue("ResolvedTimeStep")
    settled = points(data)
    inside = len(settled) == 40 and np.all(np.isfinite(settled)) and all(
        bounds[2 * a] - cell <= settled[:, a].min() and
        settled[:, a].max() <= bounds[2 * a + 1] + cell for a in range(3))
    slip = (np.median(bptest.point_array(data, "SlipVelocity")[:, 2]) if len(settled)
            else float("nan"))
    print("%s fluid: step %.4g (falls %.4g cells), end %.4g, median slip %.5f (terminal %.5f); %s"
          % (name, step, step * abs(terminal) / cell, end, slip, terminal, said.messages))
    bptest.check(abs(step * abs(terminal) - 0.5 * cell) < 0.01 * cell,
                 "%s fluid: the automatic step lets a settling particle fall half a cell "
                 "(%.4g cells)" % (name, step * abs(terminal) / cell))
    bptest.check(inside and abs(slip - terminal) < 0.01 * abs(terminal),
                 "%s fluid: the particles settle at the terminal velocity inside the box "
                 "(median slip %.5f; bounds %s)" % (name, slip, data.GetBounds()))
    bptest.check(not said.messages, "%s fluid: nothing said of heavy particles settling: %s" %
                 (name, said.messages))
    Delete(automatic)
Delete(noise)

# The plugin's own double gyre with every tracer default, and the user guide's
# heavy particles over it, say nothing (its flow crossing 13% of the coarse
# default grid, 4 cells, between two time steps is no units mismatch).
with bptest.CapturedMessages() as said:
    default_gyre = AnalyticFlow(Flow="Double Gyre")
    SetActiveSource(default_gyre)  # a tracer takes the active source's arrays
    plain = BoundParticleTracer(Input=default_gyre)
    plain.UpdatePipeline()
    SetActiveSource(default_gyre)
    dust = BoundParticleTracer(Input=default_gyre, ElementShape="Point", NumberOfElements=4000,
                               Inertia="Maxey-Riley", ResponseTime=0.5, DensityRatio=1000,
                               OutputArrays=["SlipVelocity", "Speed"])
    dust.UpdatePipeline(5.0)
bptest.check(not said.messages and servermanager.Fetch(dust).GetNumberOfPoints() == 4000,
             "the default double gyre and the guide's heavy particles say nothing: %s" %
             said.messages)
for proxy in (dust, plain, default_gyre):
    Delete(proxy)

# Every input kind: the vortex as an unstructured mesh (resampled inside the
# tracer) traces the heavy particles the image does.
def heavy_points(flow, vectors):
    t = tracer(flow, vectors, Inertia="Maxey-Riley", ResponseTime=0.05, DensityRatio=20,
               Gravity=[0, 0, -1], ResampleDimensions=[17, 17, 17])
    p = points(bptest.fetch(t, 1.0))
    order = np.argsort(bptest.point_array(servermanager.Fetch(t), "ElementId"))
    Delete(t)
    return p[order]


mesh = CleantoGrid(Input=ImageDatatoPointSet(Input=vortex))
mesh.UpdatePipeline()
on_image, on_mesh = heavy_points(vortex, VELOCITY), heavy_points(mesh, VELOCITY)
apart = np.abs(on_image - on_mesh).max() if on_image.shape == on_mesh.shape else float("inf")
print("heavy particles on the mesh within %.2e of the image's" % apart)
bptest.check(apart < 1e-4, "a mesh input traces the image's heavy particles (%.2e)" % apart)

# Lattice releases and the FTLE map, which is then the heavy particles' FTLE.
gyre = AnalyticFlow(Flow="Double Gyre", Resolution=[64, 32, 2], Bounds=[0, 2, 0, 1, -0.01, 0.01],
                    NumberOfTimeSteps=5)
gyre.UpdatePipeline()


def ftle_map(inertia):
    t = BoundParticleTracer(Input=gyre, Vectors=VELOCITY, ElementShape="Cross",
                            RestorationIterations=0, NumberOfElements=200, ElementSize=0.02,
                            ReleasePattern="Lattice", EmitterCenter=[1.0, 0.5, 0.0],
                            EmitterSize=[2.0, 1.0, 0.0], ReleaseOrientation="Fixed",
                            StepSizeUnit="Time", StepSize=0.05, LifetimeRange=[10, 10],
                            MinimumReleaseSpeed=0.0, Inertia=inertia, ResponseTime=0.3,
                            DensityRatio=1000)
    t.UpdatePipeline(2.0)
    image = servermanager.Fetch(t, 0, None, 1)
    values = image.GetPointData().GetArray("FTLE")
    Delete(t)
    return vtk_to_numpy(values).astype(float) if values is not None else np.zeros(0)


inertial_map, tracer_map = ftle_map("Maxey-Riley"), ftle_map("None")
print("FTLE maps: %d points, heavy mean %.3f, massless mean %.3f" %
      (len(inertial_map), np.nanmean(inertial_map) if len(inertial_map) else 0,
       np.nanmean(tracer_map) if len(tracer_map) else 0))
bptest.check(len(inertial_map) == len(tracer_map) > 0 and np.isfinite(inertial_map).all() and
             np.abs(inertial_map - tracer_map).max() > 1e-3,
             "the FTLE map of a heavy lattice release is its own, finite")

# The GPU display steps heavy particles itself and draws what the CPU
# engine's Surface shows.
def rendered(t, representation, name, view_time, color=None, scalar_range=None):
    """Tracer t drawn by `representation` at view_time, saved as `name`, then
    deleted: the picture's file and the messages the render gave."""
    view = bptest.element_view((240, 180))
    shown = Show(t, view)
    shown.SetRepresentationType(representation)
    bptest.colour_display(shown, color, scalar_range)
    view.ViewTime = view_time
    with bptest.CapturedMessages() as said:
        Render(view)
    image = bptest.save_picture(view, output, name)
    Delete(t)
    return image, said


def picture(engine, representation, name, color=None, scalar_range=None):
    t = tracer(vortex, VELOCITY, ElementShape="Strip8", NumberOfElements=60, ElementSize=0.15,
               EmitterSize=[1.2, 1.2, 1.2], Inertia="Maxey-Riley", ResponseTime=0.05,
               DensityRatio=50, Gravity=[0, 0, -3], Engine=engine,
               OutputArrays=["Normals", "SlipVelocity", "ParticleVelocity"])
    return rendered(t, representation, name, 0.5, color, scalar_range)


output = bptest.scratch("bp-inertia-")
for color, scalar_range in ((None, None), ("SlipVelocity", (0.0, 0.2)),
                            ("ParticleVelocity", (0.0, 1.2))):
    name = "inertia_" + (color or "solid")
    cpu_image, _ = picture("CPU", "Surface", name + "_cpu", color, scalar_range)
    gpu_image, said = picture("GPU", "Bound Particles", name + "_gpu", color, scalar_range)
    mean, pixels = bptest.image_difference(cpu_image, gpu_image)
    covered = bptest.covered_fraction(gpu_image)
    print("GPU display against CPU Surface, %s: mean %.3f, pixels %.4f; %.3f of the picture "
          "drawn" % (color or "solid", mean, pixels, covered))
    bptest.check(covered > 0.01, "the GPU display draws the elements (%.4f covered)" % covered)
    bptest.check(not said.messages, "the GPU display runs heavy particles without a message: %s"
                 % said.messages)
    bptest.check(mean <= 0.5 and pixels <= 0.002,
                 "the GPU display draws the CPU engine's heavy particles, %s: mean %.3f, pixels "
                 "%.4f" % (color or "solid", mean, pixels))

# A flat field (one point thick along Z, as 2D data) keeps heavy particles in
# its plane: Gravity's component across it is dropped, with a warning, for
# both engines; its component in the plane acts as given.
PLANE_Z = 0.25
flat = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[17, 17, 1],
                    Bounds=[-1, 1, -1, 1, PLANE_Z, PLANE_Z])
flat.UpdatePipeline()


def flat_tracer(gravity, **settings):
    base = dict(EmitterCenter=[0, 0, PLANE_Z], EmitterSize=[1.2, 1.2, 0], Inertia="Maxey-Riley",
                ResponseTime=0.05, DensityRatio=50, Gravity=gravity)
    base.update(settings)
    return tracer(flat, VELOCITY, **base)


def flat_trace(gravity):
    t = flat_tracer(gravity)
    with bptest.CapturedMessages() as said:
        data = bptest.fetch(t, 1.0)
    p, slip = points(data), bptest.point_array(data, "SlipVelocity")
    order = np.argsort(bptest.point_array(data, "ElementId"))
    Delete(t)
    return p[order], slip[order], said


sideways, _, _ = flat_trace([0, -2, 0])
for gravity in ([0, -2, -9.81], [0, 0, -9.81]):
    p, slip, said = flat_trace(gravity)
    print("flat field, Gravity %s: z in [%g, %g], slip across %g; %s" %
          (gravity, p[:, 2].min(), p[:, 2].max(), np.abs(slip[:, 2]).max(), said.messages))
    bptest.check(len(p) == 40 and np.all(p[:, 2] == PLANE_Z) and not np.any(slip[:, 2]),
                 "Gravity %s on a flat field: every point stays in the plane z = %g (z in [%g, "
                 "%g])" % (gravity, PLANE_Z, p[:, 2].min(), p[:, 2].max()))
    bptest.check(len(said.messages) == 1 and said.mentions("Gravity crosses its plane") and
                 said.mentions("-9.81 along Z"),
                 "Gravity %s on a flat field: its dropped component is said once: %s" %
                 (gravity, said.messages))
    if gravity[1]:
        bptest.check(p.shape == sideways.shape and np.array_equal(p, sideways),
                     "only the crossing component is dropped: the trace is Gravity 0 -2 0's")
    else:
        bptest.check(said.mentions("do not fall") and np.any(slip[:, :2]),
                     "Gravity wholly across the plane leaves heavy particles lagging the flow "
                     "in it, with a warning and no error: %s" % said.messages)


def flat_picture(engine, representation, name):
    t = flat_tracer([0, 0, -9.81], ElementShape="Strip8", NumberOfElements=60,
                    ElementSize=0.15, Engine=engine, OutputArrays=["Normals"])
    return rendered(t, representation, name, 1.0)


cpu_image, _ = flat_picture("CPU", "Surface", "inertia_flat_cpu")
gpu_image, said = flat_picture("GPU", "Bound Particles", "inertia_flat_gpu")
mean, pixels = bptest.image_difference(cpu_image, gpu_image)
print("flat field, GPU display against CPU Surface: mean %.3f, pixels %.4f; %s" %
      (mean, pixels, said.messages))
bptest.check(said.mentions("Gravity crosses its plane") and mean <= 0.5 and pixels <= 0.002 and
             bptest.covered_fraction(gpu_image) > 0.01,
             "on a flat field the GPU display keeps heavy particles in the plane as the CPU "
             "engine does: mean %.3f, pixels %.4f; %s" % (mean, pixels, said.messages))

# The Python trace records the settings of a tracer made while tracing.
smtrace.start_trace()
traced_tracer = BoundParticleTracer(Input=vortex, Vectors=VELOCITY, Inertia="Maxey-Riley",
                                    ResponseTime=0.25, DensityRatio=3.5, Gravity=[0, -2, 0])
traced = smtrace.stop_trace()
# ParaView 5.11 and 5.13 trace `tracer.Name = value`, 6.1 `tracer.Set(Name=value, ...)`.
for name, value in (("Inertia", "'Maxey-Riley'"), ("ResponseTime", "0.25"),
                    ("DensityRatio", "3.5"), ("Gravity", "[0.0, -2.0, 0.0]")):
    recorded = re.search(r"\b%s ?= ?%s" % (name, re.escape(value)), traced)
    bptest.check(recorded, "the trace records %s = %s:\n%s" % (name, value, traced))

# A state file brings them back.
state = os.path.join(bptest.scratch("bp-inertia-state-"), "inertia.pvsm")
SaveState(state)
ResetSession()
LoadPlugin(args.plugin, ns=globals())
LoadState(state)
loaded = [s for s in GetSources().values() if s.GetXMLName() == "BoundParticleTracer" and
          s.ResponseTime == 0.25]
bptest.check(len(loaded) == 1 and loaded[0].Inertia == "Maxey-Riley" and
             loaded[0].DensityRatio == 3.5 and list(loaded[0].Gravity) == [0, -2, 0],
             "the state file brings the settings back")

# A state file whose values ParaView reads as 0 (issue 53): NaN (as ParaView
# writes a NaN itself), infinity and text. A tracer refused for its NaN
# Response Time stays refused after reloading (it came back as a working
# massless trace), Inertia written as its entry's text takes that entry (it
# came back as None), other text keeps the default; each is said by name.
ResetSession()
LoadPlugin(args.plugin, ns=globals())
small = AnalyticFlow(Flow="Solid Body Rotation", Resolution=[9, 9, 9])
BoundParticleTracer(Input=small, Vectors=VELOCITY, ElementShape="Point", NumberOfElements=20,
                    Inertia="Maxey-Riley", ResponseTime=float("nan"), DensityRatio=3.5)
SaveState(state)
with open(state) as f:
    text = f.read()
bptest.check(re.search(r'name="ResponseTime"[^>]*>\s*<Element index="0" value="nan"', text,
                       re.IGNORECASE), "ParaView writes a NaN Response Time as NaN")


def set_state_value(text, name, value):
    return re.sub(r'(name="%s"[^>]*>\s*<Element index="0" value=")[^"]*(")' % name,
                  r"\g<1>%s\g<2>" % value, text)


for edits, expect in (
        ({"ResponseTime": "NaN"}, "refused"),
        ({"ResponseTime": "nan", "Inertia": "Maxey-Riley"}, "refused"),
        ({"ResponseTime": "Infinity"}, "refused"),
        ({"ResponseTime": "-inf", "NumberOfElements": "many"}, "refused"),
        ({"ResponseTime": "0.25", "Inertia": "Maxey-Riley", "NumberOfElements": "many"},
         "traced")):
    edited = text
    for name, value in edits.items():
        edited = set_state_value(edited, name, value)
    with open(state, "w") as f:
        f.write(edited)
    ResetSession()
    LoadPlugin(args.plugin, ns=globals())
    with bptest.CapturedMessages() as said:
        LoadState(state)
    loaded = [s for s in GetSources().values() if s.GetXMLName() == "BoundParticleTracer"]
    named = all(any("%s the value '%s'" % (name, value) in m for m in said.messages)
                for name, value in edits.items() if value != "0.25")
    with bptest.CapturedMessages() as refused:
        out = bptest.fetch(loaded[0], 0.5) if loaded else None
    count = out.GetNumberOfPoints() if out else -1
    print("state file with %s: %s; %d points; %s" % (edits, said.messages, count,
                                                     refused.messages))
    kept = len(loaded) == 1 and loaded[0].Inertia == "Maxey-Riley" and (
        "NumberOfElements" not in edits or loaded[0].NumberOfElements == 1000)
    bptest.check(named and kept, "a state file's %s is said by name and read as meant: %s" %
                 (edits, said.messages))
    if expect == "refused":
        bptest.check(count == 0 and refused.mentions("ResponseTime"),
                     "a state file's Response Time %s is refused as before saving: %d points, %s"
                     % (edits["ResponseTime"], count, refused.messages))
    else:
        bptest.check(count == 1000, "the state file traces the Inertia it names: %d points" %
                     count)
bptest.finish()
