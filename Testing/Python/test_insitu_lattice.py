"""In situ lattice releases and the FTLE map (issue 42, item 2): the double
gyre handed to the tracer one step at a time, elements released on a lattice
(Release Pattern = Lattice) with ElementFTLE and ElementStretch on, gets the
elements of a post hoc trace of the same steps (matched by ElementId and
ParticleIndex within 1e-4 of the domain, their FTLE within 1e-4 of its
range), and the FTLE map (output port 1) has the post hoc map's points and
values. Nothing is said on the way.
"""
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--steps")

from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from insitu_feed import by_particle, copy_of, farthest, feed  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
STEPS = int(args.steps or 16)
DOMAIN = 2.0
SETTINGS = dict(Vectors=["POINTS", "velocity"], ElementShape="Cross", RestorationIterations=0,
                NumberOfElements=400, ElementSize=0.04, ReleaseOrientation="Fixed",
                ReleasePattern="Lattice", EmitterCenter=[1.0, 0.5, 0.0],
                EmitterSize=[2.0, 1.0, 0.0], LifetimeRange=[2.5, 2.5], MinimumReleaseSpeed=0.0,
                Engine="CPU",
                OutputArrays=["ElementFTLE", "ElementStretch", "ElementId", "ParticleIndex"])

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[65, 33, 2], Bounds=[0, 2, 0, 1, -0.01, 0.01],
                    NumberOfTimeSteps=STEPS)
flow.UpdatePipeline()
times = list(flow.TimestepValues)


def outputs(tracer, t):
    """(elements by particle, their ElementFTLE by particle, the FTLE map) at `t`."""
    tracer.UpdatePipeline(t)
    data = servermanager.Fetch(tracer)
    ftle_map = servermanager.Fetch(tracer, 0, None, 1)
    ids = zip(vtk_to_numpy(data.GetPointData().GetArray("ElementId")),
              vtk_to_numpy(data.GetPointData().GetArray("ParticleIndex")))
    ftle = vtk_to_numpy(data.GetPointData().GetArray("ElementFTLE"))
    return (by_particle(data), {(int(e), int(p)): ftle[k] for k, (e, p) in enumerate(ids)},
            ftle_map)


def map_values(image):
    """(points, {array: values}) of the FTLE map."""
    arrays = {}
    for name in ("FTLE", "Stretch", "Age", "vtkValidPointMask"):
        a = image.GetPointData().GetArray(name)
        arrays[name] = None if a is None else vtk_to_numpy(a).astype(float)
    points = numpy.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
    return points, arrays


def compare_maps(label, got, want):
    gp, ga = map_values(got)
    wp, wa = map_values(want)
    print("%s: FTLE map of %d points in situ, %d post hoc" % (label, len(gp), len(wp)))
    bptest.check(len(wp) > 0 and gp.shape == wp.shape and numpy.abs(gp - wp).max() <= 1e-9,
                 "%s: the FTLE map's points in situ are the post hoc map's (%d, %d)"
                 % (label, len(gp), len(wp)))
    valid = wa["vtkValidPointMask"]
    bptest.check(valid is not None and valid.sum() > 0.5 * len(valid),
                 "%s: most of the post hoc map is valid (%s)"
                 % (label, None if valid is None else "%d of %d" % (valid.sum(), len(valid))))
    for name in ("FTLE", "Stretch", "Age", "vtkValidPointMask"):
        g, w = ga[name], wa[name]
        if g is None or w is None or g.shape != w.shape:
            bptest.check(False, "%s: the map's %s in situ and post hoc (%s, %s)"
                         % (label, name, None if g is None else g.shape,
                            None if w is None else w.shape))
            continue
        scale = max(1.0, float(numpy.abs(w).max()))
        gap = float(numpy.abs(g - w).max()) if len(w) else 0.0
        print("  %s: range [%g, %g], %g apart" % (name, w.min(), w.max(), gap))
        bptest.check(gap <= 1e-4 * scale, "%s: the map's %s in situ equals post hoc (%g apart)"
                     % (label, name, gap))


posthoc = BoundParticleTracer(Input=flow, **SETTINGS)
checked = (times[STEPS // 2], times[-1])
reference = {t: outputs(posthoc, t) for t in checked}
producer = PVTrivialProducer()
insitu = BoundParticleTracer(Input=producer, **SETTINGS)
with bptest.CapturedMessages() as said:
    for t in times:
        feed(producer, copy_of(flow, t), t)
        insitu.UpdatePipeline(t)
        if t not in reference:
            continue
        got_points, got_ftle, got_map = outputs(insitu, t)
        want_points, want_ftle, want_map = reference[t]
        label = "t = %g" % t
        gap = farthest(got_points, want_points)
        print("%s: %d particles in situ, %d post hoc, %g apart"
              % (label, len(got_points), len(want_points), gap))
        bptest.check(gap <= 1e-4 * DOMAIN, "%s: lattice elements in situ equal post hoc "
                     "(%d and %d particles, %g apart)"
                     % (label, len(got_points), len(want_points), gap))
        if set(got_ftle) == set(want_ftle) and want_ftle:
            values = numpy.array([want_ftle[k] for k in want_ftle])
            worst = max(abs(got_ftle[k] - want_ftle[k]) for k in want_ftle)
            print("%s: ElementFTLE in [%g, %g], %g apart" % (label, values.min(), values.max(),
                                                             worst))
            bptest.check(values.max() > 0.0 and worst <= 1e-4 * max(1.0, values.max()),
                         "%s: ElementFTLE in situ equals post hoc (%g apart)" % (label, worst))
        compare_maps(label, got_map, want_map)
said.messages = [m for m in said.messages if "New time step is not" not in m]
bptest.check(not said.messages, "nothing said in situ: %s" % said.messages[:3])
bptest.finish()
