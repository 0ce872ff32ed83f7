"""The tracer through its proxies: outputs, time, animation, errors."""
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
# Named on every tracer: pvpython takes the default from the active source,
# often another tracer (whose output has 'Velocity'), and a name the input
# lacks is an error.
VELOCITY = ["POINTS", "velocity"]


def points(proxy, time):
    proxy.UpdatePipeline(time)
    data = servermanager.Fetch(proxy)
    if data.GetNumberOfPoints() == 0:
        return None
    return vtk_to_numpy(data.GetPoints().GetData()).copy()


flow = AnalyticFlow(Flow="Shear Layer", Resolution=[24, 24, 24], Bounds=[0, 4, 0, 1, -1, 1])
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Paddlewheel", NumberOfElements=300,
                             Seed=5, Duration=5.0, NumberOfTimeSteps=51)

# A steady input gets time steps, and the animation plays through them.
times = list(tracer.TimestepValues)
bptest.check(len(times) == 51 and abs(times[-1] - 5.0) < 1e-12, "TimestepValues %s" % times[:3])
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
bptest.check(abs(scene.EndTime - 5.0) < 1e-12, "animation ends at %s" % scene.EndTime)
view = CreateRenderView()
display = Show(tracer, view)
frames = []
for t in (0.0, 0.5, 1.0):
    scene.AnimationTime = t
    Render(view)
    data = servermanager.Fetch(tracer)
    frames.append(vtk_to_numpy(data.GetPoints().GetData()).copy())
bptest.check(all(f.shape == (2400, 3) for f in frames), "300 paddlewheels give 2400 points")
bptest.check(abs(frames[1] - frames[0]).max() > 1e-3 and abs(frames[2] - frames[1]).max() > 1e-3,
             "elements move while the animation plays")

# Forward continues; the result equals a fresh run. Backward replays.
fresh = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Paddlewheel", NumberOfElements=300,
                            Seed=5, Duration=5.0, NumberOfTimeSteps=51)
continued = points(tracer, 1.7)
bptest.check((continued == points(fresh, 1.7)).all(), "forward in time equals a fresh run")
back = points(tracer, 0.4)
fresh2 = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Paddlewheel", NumberOfElements=300,
                             Seed=5, Duration=5.0, NumberOfTimeSteps=51)
bptest.check((back == points(fresh2, 0.4)).all(), "backward in time equals a fresh run")

# Outputs: arrays and no NaN.
data = servermanager.Fetch(tracer)
pd = data.GetPointData()
for name in ["Normals", "Velocity", "Speed", "Force", "Lifetime", "ElementId", "ParticleIndex",
             "Vorticity", "Layer", "Radius"]:
    array = pd.GetArray(name)
    bptest.check(array is not None, "array %s present" % name)
    if array is not None:
        values = vtk_to_numpy(array)
        bptest.check(values.size > 0 and (values == values).all(), "array %s is finite" % name)
bptest.check(data.GetNumberOfCells() == 300 * 4, "4 triangles per paddlewheel")

# Bad input: a 1-component array gives an error in the output window and no output.
calc = Calculator(Input=flow, ResultArrayName="speed", Function="mag(velocity)")
with bptest.CapturedMessages() as log:
    bad = BoundParticleTracer(Input=calc, Vectors=["POINTS", "speed"])
    bad.UpdatePipeline(0.5)
bptest.check(log.mentions("1 component"), "1-component array error: %s" % log.messages)
bptest.check(bad.GetDataInformation().GetNumberOfPoints() == 0, "no output for bad input")
with bptest.CapturedMessages() as log:
    tracer.StepSize = 0.0
    tracer.UpdatePipeline(0.5)
bptest.check(log.mentions("StepSize must be positive"), "StepSize error: %s" % log.messages)
bptest.check(tracer.GetDataInformation().GetNumberOfPoints() == 0, "no output for StepSize 0")
tracer.StepSize = 0.5
tracer.UpdatePipeline(0.5)
bptest.check(tracer.GetDataInformation().GetNumberOfPoints() == 2400, "recovers after fixing")

# Any source is an element editor: a sphere as the template.
sphere = Sphere(ThetaResolution=8, PhiResolution=6)
blobs = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementTemplate=sphere, NumberOfElements=20,
                            TemplateSprings="All Pairs")
blobs.UpdatePipeline(0.5)
info = blobs.GetDataInformation()
sphereInfo = sphere.GetDataInformation()
bptest.check(info.GetNumberOfPoints() == 20 * sphereInfo.GetNumberOfPoints(),
             "20 spheres give %d points" % info.GetNumberOfPoints())
bptest.check(info.GetNumberOfCells() == 20 * sphereInfo.GetNumberOfCells(),
             "20 spheres give %d cells" % info.GetNumberOfCells())

# Super sets: a 4 x 3 sheet of crosses, its links output as lines (12 per
# link, one per particle), its elements released on the lattice together.
sheet = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Cross", NumberOfElements=12,
                            Linking="Sheet", LatticeWidth=4, EmitterCenter=[2, 0.5, 0],
                            EmitterSize=[2, 0.5, 0], ReleaseOrientation="Fixed")
sheet.UpdatePipeline(0.5)
data = servermanager.Fetch(sheet)
links = 3 * 3 + 4 * 2
bptest.check(data.GetNumberOfLines() == 12 * links,
             "a 4 x 3 sheet of crosses has %d link lines" % data.GetNumberOfLines())
bptest.check(data.GetNumberOfPolys() == 12 * 10,
             "and its crosses' triangles: %d" % data.GetNumberOfPolys())
sheet.Linking = "Torus"
sheet.UpdatePipeline(0.5)
bptest.check(servermanager.Fetch(sheet).GetNumberOfLines() == 12 * 24, "a torus closes")
# Linear shape matching runs and differs from the rigid fit.
matched = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Paddlewheel", NumberOfElements=50,
                              Restoration="Shape Matching", Seed=2)
rigid = points(matched, 1.0)
matched.ShapeMatchingMode = "Linear"
matched.LinearShapeMatchingBeta = 0.8
linear = points(matched, 1.0)
bptest.check(rigid is not None and linear is not None and rigid.shape == linear.shape and
             abs(rigid - linear).max() > 1e-4, "linear shape matching changes the trace")

# A Seed Source: a Line's 10 points are the release positions, in order.
line = Line(Point1=[0.5, 0.2, -0.5], Point2=[3.5, 0.8, 0.5], Resolution=9)
seeded = BoundParticleTracer(Input=flow, Vectors=VELOCITY, SeedSource=line, ElementShape="Square",
                             NumberOfElements=20, Seed=4)
start = seeded.TimestepValues[0]
placed = points(seeded, start).reshape(20, 4, 3).mean(axis=1)
line_points = vtk_to_numpy(servermanager.Fetch(line).GetPoints().GetData())
expected = numpy.vstack([line_points, line_points])  # 20 elements cycle the 10 points
bptest.check(abs(placed - expected).max() < 1e-5,
             "elements start at the seed points in order (worst %.3g)" %
             abs(placed - expected).max())
seeded.SeedSource = None
unseeded = points(seeded, start).reshape(20, 4, 3).mean(axis=1)
bptest.check(abs(unseeded - expected).max() > 0.1, "without it, the emitter box again")
# An image as the Seed Source is read whole (not cut to the field's extent):
# 30^3 seed points over a 24^3 field, one Point element on each.
image_seeds = ResampleToImage(Input=flow, SamplingDimensions=[30, 30, 30])
whole = BoundParticleTracer(Input=flow, Vectors=VELOCITY, SeedSource=image_seeds,
                            ElementShape="Point", NumberOfElements=27000, Seed=1)
with bptest.CapturedMessages() as log:
    centres = points(whole, whole.TimestepValues[0])
bptest.check(not log.messages, "an image Seed Source: no messages (%s)" % log.messages[:1])
distinct = len(numpy.unique(numpy.round(centres, 5), axis=0))
bptest.check(distinct == 27000, "all 27,000 seed points used (%d)" % distinct)
Delete(whole)
# Seed points outside the field are skipped, and the tracer says how many.
half_out = Line(Point1=[2.0, 0.5, 0.0], Point2=[6.0, 0.5, 0.0], Resolution=9)
skipping = BoundParticleTracer(Input=flow, Vectors=VELOCITY, SeedSource=half_out,
                               ElementShape="Square", NumberOfElements=20, Seed=4)
with bptest.CapturedMessages() as log:
    placed = points(skipping, skipping.TimestepValues[0]).reshape(20, 4, 3).mean(axis=1)
bptest.check(log.mentions("5 of the Seed Source's 10 points lie outside the field"),
             "the outside seed points are counted: %s" % log.messages)
bptest.check((placed[:, 0] <= 4.0).all(), "no element starts outside (x up to %.3f)" %
             placed[:, 0].max())
Delete(skipping)
# The same for the Element Template: cleared, the built-in shape again.
seeded.ElementTemplate = Plane(XResolution=2, YResolution=2)
bptest.check(points(seeded, start).shape == (20 * 9, 3), "a 3 x 3 plane as the element")
seeded.ElementTemplate = None
bptest.check(points(seeded, start).shape == (20 * 4, 3), "cleared, Square elements again")

# A release window: one burst at t = 0.5, followed; before it nothing is drawn
# (the elements' points are there, without cells).
burst = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Square",
                            NumberOfElements=40, Seed=6, Duration=5.0, NumberOfTimeSteps=51,
                            LifetimeRange=[10.0, 10.0], ReleaseWindow=1, ReleaseStart=0.5,
                            ReleaseStop=0.5)
counts = {}
for t in (0.5, 0.6, 1.5):
    burst.UpdatePipeline(t)
    data = servermanager.Fetch(burst)
    counts[t] = (data.GetNumberOfPoints(), data.GetNumberOfCells())
# The step that holds t = 0.5 releases them: the state at 0.5 comes before it.
bptest.check(counts[0.5] == (160, 0), "before the burst: no cells (%s)" % (counts[0.5],))
# Lifetimes left are never negative, even for those whose life just ended.
lifetimes = vtk_to_numpy(servermanager.Fetch(burst).GetPointData().GetArray("Lifetime"))
bptest.check(lifetimes.min() >= 0.0, "Lifetime >= 0 (%g)" % lifetimes.min())
# A window outside the offered times says that nothing will be released.
late = BoundParticleTracer(Input=flow, Vectors=VELOCITY, NumberOfElements=10, Duration=5.0,
                           ReleaseWindow=1, ReleaseStart=100.0, ReleaseStop=200.0)
with bptest.CapturedMessages() as log:
    late.UpdatePipeline(1.0)
bptest.check(log.mentions("No element is released"), "a window out of range: %s" % log.messages)
late.ReleaseStart = float("nan")
with bptest.CapturedMessages() as log:
    late.UpdatePipeline(1.0)
bptest.check(log.mentions("ReleaseStart and ReleaseStop must be numbers"),
             "a NaN window: %s" % log.messages)
Delete(late)
# Those that leave the field are not released again: a burst only thins out.
bptest.check(counts[0.6][0] == 160 and 30 < counts[0.6][1] <= 40,
             "after the burst: about 40 squares (%s)" % (counts[0.6],))
bptest.check(0 < counts[1.5][1] <= counts[0.6][1],
             "followed at t = 1.5: %d squares" % counts[1.5][1])

Delete(view)
del view

# A tracer with an automatic time line made on a time-varying filter shown at
# the view's time: its probe of the field at the first time step leaves the
# filter's output at the view's time, as its display and a script find it.
gyre = AnalyticFlow(Flow="Double Gyre", Resolution=[40, 24, 6], NumberOfTimeSteps=9)
doubled = Calculator(Input=gyre, Function="velocity*2", ResultArrayName="doubled")
gyre_view = CreateRenderView(ViewSize=[160, 120])
Show(doubled, gyre_view)
gyre_times = list(gyre.TimestepValues)
gyre_view.ViewTime = gyre_times[5]
Render(gyre_view)
held = doubled.GetClientSideObject().GetOutputDataObject(0)
before = vtk_to_numpy(held.GetPointData().GetArray("doubled")).copy()
automatic = BoundParticleTracer(Input=doubled, Vectors=["POINTS", "doubled"], NumberOfElements=20)
automatic.UpdatePipelineInformation()
bptest.check(len(automatic.TimestepValues) > 0, "the automatic time line was resolved")
held_time = held.GetInformation().Get(held.DATA_TIME_STEP())
after = vtk_to_numpy(held.GetPointData().GetArray("doubled"))
bptest.check(held_time == gyre_times[5] and numpy.array_equal(before, after),
             "the filter's output stays at the view's time %g: it holds %g" %
             (gyre_times[5], held_time))
Delete(automatic)
Delete(gyre_view)
del gyre_view
bptest.finish()
