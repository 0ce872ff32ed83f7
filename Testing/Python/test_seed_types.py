"""Seed Types (issue 29, item 3) from pvpython: the tracer's Seed Type list
(Emitter Box, Point Cloud, Line; Surface has test_surface_seeds.py) as in the
Stream Tracer. Each releases where
it says, in order; the point cloud is the same for the same Seed and on a 2D
field fills the disc in its plane; changing a seed's parameter replays; a
connected Seed Source wins; the seed warnings name the Seed Type; a state
file brings the choice and its parameters back.
"""
import os
import sys
import xml.etree.ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments()

import numpy  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
VELOCITY = ["POINTS", "velocity"]


def centres(tracer, time=None):
    """Each element's mean position, by ElementId, at `time` (default the start)."""
    tracer.UpdatePipeline(tracer.TimestepValues[0] if time is None else time)
    data = servermanager.Fetch(tracer)
    if data.GetNumberOfPoints() == 0:
        return numpy.zeros((0, 3))
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
    return numpy.array([points[ids == e].mean(axis=0) for e in numpy.unique(ids)])


flow = AnalyticFlow(Flow="Shear Layer", Resolution=[24, 24, 24], Bounds=[0, 4, 0, 1, -1, 1])
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Square",
                             NumberOfElements=40, Seed=4)

# The list, its default and the data-based defaults of each entry (ParaView
# 5.13 and later list the labels as Python names, without spaces; either
# spelling sets the property).
available = tracer.GetProperty("SeedType").Available
bptest.check([a.replace(" ", "") for a in available] == ["EmitterBox", "PointCloud", "Line", "Surface"],
             "the list: %s" % available)
bptest.check(tracer.SeedType.GetXMLLabel() == "Emitter Box",
             "the default is the emitter box (%s)" % tracer.SeedType.GetXMLLabel())
box = centres(tracer)
bptest.check(len(box) == 40 and numpy.ptp(box[:, 0]) > 2.0,
             "the box spreads the elements over the field (x span %.2f)" % numpy.ptp(box[:, 0]))
tracer.SeedType = "Line"
bptest.check(list(tracer.SeedType.Point1) == [0, 0, -1] and list(tracer.SeedType.Point2) == [4, 1, 1]
             and tracer.SeedType.Resolution == 1000,
             "the line defaults to the field's diagonal, 1001 points (%s %s %d)" %
             (list(tracer.SeedType.Point1), list(tracer.SeedType.Point2),
              tracer.SeedType.Resolution))
tracer.SeedType = "Point Cloud"
bptest.check(list(tracer.SeedType.Center) == [2, 0.5, 0] and
             abs(tracer.SeedType.Radius - 0.4) < 1e-12 and tracer.SeedType.NumberOfPoints == 1000,
             "the cloud defaults to the field's centre, a tenth of its size (%s %g %d)" %
             (list(tracer.SeedType.Center), tracer.SeedType.Radius,
              tracer.SeedType.NumberOfPoints))

# Line: the elements start on its points, in order.
tracer.SeedType = "Line"
tracer.SeedType.Point1 = [0.5, 0.2, -0.5]
tracer.SeedType.Point2 = [3.5, 0.8, 0.5]
tracer.SeedType.Resolution = 39
placed = centres(tracer)
expected = numpy.linspace([0.5, 0.2, -0.5], [3.5, 0.8, 0.5], 40)
error = abs(placed - expected).max() if placed.shape == expected.shape else float("inf")
bptest.check(error < 1e-4, "elements start on the line's points in order (worst %.3g)" % error)
# A seed's parameter set on its own proxy replays the trace.
tracer.SeedType.Point2 = [3.5, 0.8, 0.0]
moved = centres(tracer)
expected = numpy.linspace([0.5, 0.2, -0.5], [3.5, 0.8, 0.0], 40)
error = abs(moved - expected).max() if moved.shape == expected.shape else float("inf")
bptest.check(error < 1e-4, "a new Point2 replays from the new line (worst %.3g)" % error)

# Point Cloud: inside the sphere, spread through it, each element at a point
# of its own; the same for the same Seed, another for another.
tracer.SeedType = "Point Cloud"
tracer.SeedType.Center = [2.0, 0.5, 0.0]
tracer.SeedType.Radius = 0.3
tracer.SeedType.NumberOfPoints = 40
cloud = centres(tracer)
distance = numpy.linalg.norm(cloud - [2.0, 0.5, 0.0], axis=1)
bptest.check(len(cloud) == 40 and distance.max() <= 0.3 + 1e-5 and distance.max() > 0.2,
             "the cloud's elements lie in the sphere and fill it (farthest %.3f)" % distance.max())
bptest.check(len(numpy.unique(cloud.round(6), axis=0)) == 40, "40 distinct points")
again = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Square",
                            NumberOfElements=40, Seed=4, SeedType="Point Cloud")
again.SeedType.Center = [2.0, 0.5, 0.0]
again.SeedType.Radius = 0.3
again.SeedType.NumberOfPoints = 40
bptest.check(numpy.array_equal(centres(again), cloud), "the same Seed, the same cloud, bit for bit")
again.Seed = 5
bptest.check(not numpy.allclose(centres(again), cloud), "another Seed, another cloud")
Delete(again)

# A 2D field: the cloud fills the disc in the field's plane (a ball squashed
# onto it would put about 65% of the points within R/sqrt(2), the disc 50%).
flat = AnalyticFlow(Flow="Double Gyre", Resolution=[48, 24, 1], Bounds=[0, 2, 0, 1, 0.3, 0.3])
flat.UpdatePipeline()
planar = BoundParticleTracer(Input=flat, Vectors=VELOCITY, ElementShape="Point",
                             NumberOfElements=400, SeedType="Point Cloud")
planar.SeedType.Center = [1.0, 0.5, 0.9]
planar.SeedType.Radius = 0.3
planar.SeedType.NumberOfPoints = 400
disc = centres(planar)
radial = numpy.linalg.norm(disc[:, :2] - [1.0, 0.5], axis=1) if len(disc) else numpy.ones(1)
inner = float((radial < 0.3 / numpy.sqrt(2.0)).mean())
bptest.check(len(disc) == 400 and abs(disc[:, 2] - 0.3).max() < 1e-6,
             "on a 2D field the cloud lies in its plane z = 0.3")
bptest.check(radial.max() <= 0.3 + 1e-5 and 0.4 < inner < 0.6,
             "and fills the disc evenly (%.2f within R/sqrt(2))" % inner)
Delete(planar)
Delete(flat)

# The seed warnings name the Seed Type and what to raise.
crowded = BoundParticleTracer(Input=flow, Vectors=VELOCITY, NumberOfElements=100,
                              SeedType="Line")
crowded.SeedType.Point1 = [0.5, 0.5, 0.0]
crowded.SeedType.Point2 = [3.5, 0.5, 0.0]
crowded.SeedType.Resolution = 6
with bptest.CapturedMessages() as log:
    crowded.UpdatePipeline(crowded.TimestepValues[0])
bptest.check(log.mentions("100 elements share the Line's 7 points") and
             log.mentions("Raise the Line's Resolution"),
             "more than twice as many elements as line points: %s" % log.messages)
crowded.SeedType = "Point Cloud"
crowded.SeedType.NumberOfPoints = 10
with bptest.CapturedMessages() as log:
    crowded.UpdatePipeline(crowded.TimestepValues[0])
bptest.check(log.mentions("share the Point Cloud's 10 points") and
             log.mentions("Number Of Points"),
             "more than twice as many elements as cloud points: %s" % log.messages)
Delete(crowded)
still_flow = Calculator(Input=AnalyticFlow(Flow="Hurricane", Resolution=[16, 16, 16]),
                        ResultArrayName="v", Function="coordsX*iHat")
still_flow.UpdatePipeline()
still = BoundParticleTracer(Input=still_flow, Vectors=["POINTS", "v"], NumberOfElements=21,
                            SeedType="Line")
still.SeedType.Point1 = [0.0, -0.5, 0.0]
still.SeedType.Point2 = [0.0, 0.5, 0.0]
still.SeedType.Resolution = 20
with bptest.CapturedMessages() as log:
    still.UpdatePipeline(still.TimestepValues[0])
    # Back from a later time: a replay of the same configuration says nothing again.
    still.UpdatePipeline(still.TimestepValues[3])
    still.UpdatePipeline(still.TimestepValues[1])
said = [m for m in log.messages if "slower than 1%" in m]
bptest.check(len(said) == 1 and "of the Line's 21 points in the flow lie where it is slower" in
             said[0], "seeds in still flow, said once: %s" % log.messages)
Delete(still)
# Parameters a script or a state file got wrong are said, with what is used.
odd = BoundParticleTracer(Input=still_flow, Vectors=["POINTS", "v"], NumberOfElements=10,
                          SeedType="Point Cloud")
for properties, words in (({"Radius": -0.2}, "Radius -0.2 is not a positive number"),
                          ({"Radius": -1e30}, "Radius -1e+30 is not a positive number"),
                          ({"NumberOfPoints": 0}, "Number Of Points 0 is below 1"),
                          ({"NumberOfPoints": -5}, "Number Of Points -5 is below 1")):
    odd.SeedType = "Point Cloud"
    odd.SeedType.Radius = 0.3
    odd.SeedType.NumberOfPoints = 100
    for name, value in properties.items():
        setattr(odd.SeedType, name, value)
    with bptest.CapturedMessages() as log:
        odd.UpdatePipeline(odd.TimestepValues[0])
    bptest.check(log.mentions(words), "%s is said: %s" % (properties, log.messages))
odd.SeedType = "Line"
for resolution in (0, -3):
    odd.SeedType.Resolution = resolution
    with bptest.CapturedMessages() as log:
        odd.UpdatePipeline(odd.TimestepValues[0])
    bptest.check(log.mentions("Line's Resolution %d is below 1" % resolution),
                 "Resolution %d is said: %s" % (resolution, log.messages))
Delete(odd)
# A few seeds in still flow (about 1% of a cloud) are not worth a warning.
few = BoundParticleTracer(Input=still_flow, Vectors=["POINTS", "v"], NumberOfElements=1000,
                          SeedType="Point Cloud")
few.SeedType.Center = [0.0, 0.0, 0.0]
few.SeedType.Radius = 0.4
few.SeedType.NumberOfPoints = 1000
with bptest.CapturedMessages() as log:
    few.UpdatePipeline(few.TimestepValues[0])
bptest.check(not log.mentions("slower than 1%"),
             "a small share of seeds in still flow is not warned of: %s" % log.messages)
Delete(few)

# A connected Seed Source wins over the Seed Type, and says so.
tracer.SeedType = "Line"
source = Line(Point1=[1.0, 0.5, 0.5], Point2=[3.0, 0.5, 0.5], Resolution=39)
tracer.SeedSource = source
with bptest.CapturedMessages() as log:
    from_source = centres(tracer)
expected = numpy.linspace([1.0, 0.5, 0.5], [3.0, 0.5, 0.5], 40)
error = abs(from_source - expected).max() if from_source.shape == expected.shape else float("inf")
bptest.check(error < 1e-4, "a Seed Source's points are used (worst %.3g)" % error)
bptest.check(log.mentions("A Seed Source is connected") and log.mentions("Seed Type Line"),
             "the unused Seed Type is named: %s" % log.messages)
tracer.SeedSource = None
Delete(source)
error = abs(centres(tracer) - moved).max()
bptest.check(error < 1e-4, "disconnected, the Seed Type's line again (worst %.3g)" % error)

# With Linking the super set is placed in the emitter box, as with a Seed Source.
linked = BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Cross",
                             NumberOfElements=20, Linking="Chain", SeedType="Line")
with bptest.CapturedMessages() as log:
    linked.UpdatePipeline(linked.TimestepValues[0])
bptest.check(log.mentions("the Line is not used"), "Linking ignores the Line: %s" % log.messages)
Delete(linked)

# A state file saves the choice and its parameters, and reloads them.
tracer.SeedType = "Line"
before = centres(tracer)
state = os.path.join(bptest.scratch("bp-seed-types-"), "seeds.pvsm")
SaveState(state)
ResetSession()
LoadPlugin(args.plugin, ns=globals())
LoadState(state)
loaded = FindSource("BoundParticleTracer1")
bptest.check(loaded is not None and loaded.SeedType.GetXMLLabel() == "Line" and
             list(loaded.SeedType.Point2) == [3.5, 0.8, 0.0] and loaded.SeedType.Resolution == 39,
             "the state brings back the Line and its parameters")
if loaded is not None:
    bptest.check(loaded.GetProperty("SeedType").Available == available,
                 "and the whole list (%s)" % loaded.GetProperty("SeedType").Available)
    loaded.SeedType = "Point Cloud"
    bptest.check(list(loaded.SeedType.Center) == [2.0, 0.5, 0.0] and
                 loaded.SeedType.NumberOfPoints == 40,
                 "the other entries' parameters too (%s, %d)" %
                 (list(loaded.SeedType.Center), loaded.SeedType.NumberOfPoints))
    loaded.SeedType = "Line"
    after = centres(loaded)
    bptest.check(after.shape == before.shape and abs(after - before).max() < 1e-6,
                 "and the same trace")

# A state file from before there were Seed Types (the same file without the
# SeedType property and its proxies) loads with the emitter box.
tree = xml.etree.ElementTree.parse(state)
for parent in tree.getroot().iter():
    for child in list(parent):
        if ((child.tag == "Proxy" and child.get("group") == "bound_particle_seed_types") or
                (child.tag in ("Property", "Item") and child.get("name") == "SeedType")):
            parent.remove(child)
older = os.path.join(os.path.dirname(state), "before-seed-types.pvsm")
tree.write(older)
ResetSession()
LoadPlugin(args.plugin, ns=globals())
with bptest.CapturedMessages() as log:
    LoadState(older)
    old = FindSource("BoundParticleTracer1")
    spread = centres(old) if old is not None else numpy.zeros((0, 3))
bptest.check(old is not None and old.SeedType.GetXMLLabel() == "Emitter Box" and
             old.GetProperty("SeedType").Available == available,
             "an older state file gets the Emitter Box and the whole list")
bptest.check(len(spread) == 40 and numpy.ptp(spread[:, 0]) > 2.0 and not log.messages,
             "and traces in the box without a message (%s)" % log.messages[:1])
bptest.finish()
