"""The tracer's Interactions output (port 3) as pvpython users meet it.

- In the shear layer (u(z) = 1.25 - z^2 along x) strips released in the
  field's left half are carried onto the side x = 1. With Boundary = Stick
  the port, fetched with servermanager.Fetch, has one Stuck event for each
  particle held on a side, once (the deposition count at t = 1.8, before
  any lifetime ends: the events are the particles of the elements output that
  lie on a side), mostly on the +x side
  (SurfaceId 1, Normal (1, 0, 0)), each where its particle is held, ordered
  by (Time, ElementId, ParticleIndex) with no time past the one shown.
- Going back in time (a checkpoint resumed) gives the events of a new
  tracer traced straight to that time, and forward again those of before.
- Release Again (the default): one Released event per element that left, at
  its centre (ParticleIndex -1), beyond the side.
- The port is named Interactions and its names are in the field data.
"""
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
N = 4  # particles of a Strip4
COUNT = 150
SHOWN = 1.8  # before the lifetime (2) ends: every element still its first generation

flow = AnalyticFlow(Flow="Shear Layer", Resolution=[24, 24, 24])
flow.UpdatePipeline()


def tracer(boundary):
    return BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                               ElementShape="Strip4", NumberOfElements=COUNT,
                               ElementSize=0.1, EmitterCenter=[-0.5, 0, 0],
                               EmitterSize=[0.8, 1.8, 1.8], StepSizeUnit="Time",
                               StepSize=0.02, Duration=2.4, LifetimeRange=[2, 2], Seed=3,
                               Boundary=boundary, OutputArrays=["ElementId", "ParticleIndex"])


def events_at(proxy, time):
    """The Interactions port's data at `time`, and its arrays as numpy."""
    proxy.UpdatePipeline(time)
    data = servermanager.Fetch(proxy, None, None, 3)
    arrays = {name: bptest.point_array(data, name)
              for name in ("ElementId", "ParticleIndex", "Time", "ElementVelocity", "Normal",
                           "SurfaceId", "Interaction")}
    points = bptest.point_array(data, "Normal")  # shape check below
    if data.GetNumberOfPoints():
        points = np.array([data.GetPoint(k) for k in range(data.GetNumberOfPoints())])
    else:
        points = np.zeros((0, 3))
    return data, arrays, points


def rows(arrays, points):
    if arrays["Time"] is None:
        return []
    return sorted(zip(arrays["Time"].tolist(), arrays["ElementId"].tolist(),
                      arrays["ParticleIndex"].tolist(), arrays["Interaction"].tolist(),
                      arrays["SurfaceId"].tolist(), map(tuple, points.tolist())))


stick = tracer("Stick")
bptest.check(stick.SMProxy.GetNumberOfOutputPorts() == 4, "the tracer has 4 output ports")
bptest.check(stick.SMProxy.GetOutputPortName(3) == "Interactions",
             "port 3 is named %s" % stick.SMProxy.GetOutputPortName(3))
data, a, points = events_at(stick, SHOWN)
count = data.GetNumberOfPoints()
print("Stick: %d events at t = %g" % (count, SHOWN))
bptest.check(count > COUNT, "most strips' particles reach the side: %d events" % count)
bptest.check(data.GetNumberOfVerts() == count, "one vertex per event")
for name, components in (("ElementId", 1), ("ParticleIndex", 1), ("Time", 1),
                         ("ElementVelocity", 3), ("Normal", 3), ("SurfaceId", 1),
                         ("Interaction", 1)):
    array = data.GetPointData().GetArray(name)
    bptest.check(array is not None and array.GetNumberOfComponents() == components,
                 "the array %s with %d components" % (name, components))
names = data.GetFieldData().GetAbstractArray("InteractionNames")
bptest.check(names is not None and [names.GetValue(k) for k in range(names.GetNumberOfValues())]
             == ["Released", "Terminated", "Stuck", "Slid", "Bounced", "Passed"],
             "the field data names the interactions")
if count:
    bptest.check(set(a["Interaction"].tolist()) == {2}, "every event is Stuck")
    pairs = list(zip(a["ElementId"].tolist(), a["ParticleIndex"].tolist()))
    bptest.check(len(set(pairs)) == len(pairs), "each particle's contact once")
    on_x = a["SurfaceId"] == 1
    bptest.check(on_x.mean() > 0.8, "mostly on the +x side: %.2f" % on_x.mean())
    bptest.check(np.all(np.abs(points[on_x, 0] - 1.0) < 1e-6), "+x events lie on x = 1")
    bptest.check(np.all(a["Normal"][on_x] == [1, 0, 0]), "+x events' normal is (1, 0, 0)")
    bptest.check(a["Time"].max() <= SHOWN + 1e-9 and a["Time"].min() > 0, "times within the trace")
    keys = list(zip(a["Time"].tolist(), a["ElementId"].tolist(), a["ParticleIndex"].tolist()))
    bptest.check(keys == sorted(keys), "in the trace's order (Time, ElementId, ParticleIndex) forward")
    bptest.check(np.all(a["ElementVelocity"][:, 0] >= -1e-6), "elements moving with the flow")

    # The deposition count against the elements output: every particle on a
    # side there was recorded once, where it is held.
    elements = bptest.fetch(stick, SHOWN)
    xyz = np.array([elements.GetPoint(k) for k in range(elements.GetNumberOfPoints())])
    ids = bptest.point_array(elements, "ElementId")
    index = bptest.point_array(elements, "ParticleIndex")
    on_side = np.any(np.abs(np.abs(xyz) - 1.0) < 1e-6, axis=1)
    held = set(zip(ids[on_side].tolist(), index[on_side].tolist()))
    print("particles on a side: %d, deposited elements: %d"
          % (len(held), len(set(a["ElementId"].tolist()))))
    bptest.check(held == set(pairs), "the events are the particles held on a side: %d and %d"
                 % (len(held), len(pairs)))
    where = {(e, i): xyz[k] for k, (e, i) in enumerate(zip(ids.tolist(), index.tolist()))}
    bptest.check(all(np.abs(where[p] - points[k]).max() < 1e-6 for k, p in enumerate(pairs)),
                 "each event is where its particle is held")

# Back in time: the straight trace's events to that time; forward again, those of before.
later = rows(a, points)
_, back, back_points = events_at(stick, 1.2)
fresh = tracer("Stick")
_, straight, straight_points = events_at(fresh, 1.2)
bptest.check(rows(back, back_points) == rows(straight, straight_points),
             "going back gives the straight trace's %d events (got %d)"
             % (len(rows(straight, straight_points)), len(rows(back, back_points))))
bptest.check(0 < len(rows(back, back_points)) < len(later), "fewer events earlier")
_, again, again_points = events_at(stick, SHOWN)
bptest.check(rows(again, again_points) == later, "forward again: the same events")

# Release Again: an element event at each centre that left.
released = tracer("Release Again")
_, r, r_points = events_at(released, 2.4)
print("Release Again: %d events" % len(rows(r, r_points)))
bptest.check(r["Interaction"] is not None and len(r["Interaction"]) > 20,
             "elements that left are recorded")
if r["Interaction"] is not None:
    bptest.check(set(r["Interaction"].tolist()) == {0}, "every event is Released")
    bptest.check(set(r["ParticleIndex"].tolist()) == {-1}, "element events: ParticleIndex -1")
    beyond = np.abs(r_points).max(axis=1) > 1.0
    bptest.check(beyond.all(), "each at a centre beyond a side")

bptest.finish()
