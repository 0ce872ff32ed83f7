"""The plugin loads through LoadPlugin or PV_PLUGIN_PATH and offers the proxies
and property names that scripts rely on."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--from-plugin-path")
import paraview.simple as simple  # noqa: E402
from vtkmodules.vtkCommonCore import vtkSMPTools  # noqa: E402

# The process's SMP backend is the user's: the tracer never changes it.
backend = vtkSMPTools.GetBackend()

if args.from_plugin_path is None:
    simple.LoadPlugin(args.plugin, ns=globals())
    tracer_type, source_type = globals()["BoundParticleTracer"], globals()["AnalyticFlow"]
else:
    # PV_PLUGIN_PATH is read when the session starts.
    bptest.check(hasattr(simple, "BoundParticleTracer"),
                 "PV_PLUGIN_PATH did not load the plugin (%s)" % os.environ.get("PV_PLUGIN_PATH"))
    tracer_type = getattr(simple, "BoundParticleTracer", None)
    source_type = getattr(simple, "AnalyticFlow", None)
    if tracer_type is None:
        bptest.finish()

flow = source_type(Flow="Shear Layer", Resolution=[16, 16, 16])
flow.UpdatePipeline()
tracer = tracer_type(Input=flow)
expected = ["Vectors", "ElementShape", "NumberOfElements", "ElementSize", "EmitterCenter",
            "EmitterSize", "ReleaseOrientation", "LifetimeRange", "StepSize", "Integrator",
            "Restoration", "RestorationIterations", "ResetWhen", "Seed", "TimestepValues"]
names = tracer.ListProperties()
for name in expected:
    bptest.check(name in names, "property %s is missing" % name)
shapes = tracer.GetProperty("ElementShape").Available
bptest.check(shapes == ["Point", "Square", "Strip4", "Strip8", "Strip16", "Cross", "Paddlewheel",
                        "Tetrahedron", "Fish"], "ElementShape offers %s" % shapes)
flows = flow.GetProperty("Flow").Available
bptest.check(len(flows) == 6 and "Double Gyre" in flows, "Flow offers %s" % flows)
# The emitter defaults to the field's bounds.
bptest.check(list(tracer.EmitterCenter) == [0.0, 0.0, 0.0], "EmitterCenter %s" % tracer.EmitterCenter)
bptest.check(list(tracer.EmitterSize) == [2.0, 2.0, 2.0], "EmitterSize %s" % tracer.EmitterSize)
bptest.check(tracer.Vectors[1] == "velocity", "Vectors %s" % tracer.Vectors)
tracer.UpdatePipeline(0.5)
bptest.check(tracer.GetDataInformation().GetNumberOfPoints() == 8000,
             "1000 Strip8 elements give %d points" % tracer.GetDataInformation().GetNumberOfPoints())
bptest.check(vtkSMPTools.GetBackend() == backend, "the SMP backend changed from %s to %s" % (
    backend, vtkSMPTools.GetBackend()))
bptest.finish()
