"""Time Direction = Backward and the FTLE map: the double gyre's crosses
released on a lattice at T = 10 and traced back to 0 carry the backward FTLE,
whose ridges are the attracting structures. Against numpy's finite
differences of the backward flow map (RK4 from T down to 0 through the same
sampled field, demo/ftle_map.py's sampling): correlation > 0.95, the ridges
(top 10%) shared > 90%, median relative difference < 2%, as the forward map's
check (test_ftle_map.py). The forward reference is another map: the
backward one does not correlate with it as closely.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "demo"))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
import ftle_map  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
LoadPlugin(args.plugin, ns=ftle_map.__dict__)
paraview.simple._DisableFirstRenderCameraReset()
COUNTS = (60, 30)
T = ftle_map.T


gyre, tracer = ftle_map.gyre_scene(counts=COUNTS, lattice=True)
tracer.TimeDirection = "Backward"
with bptest.CapturedMessages() as messages:
    tracer.UpdatePipeline(0.0)
    image, points, values, valid = ftle_map.ftle_image(tracer)
bptest.check(not messages.messages, "no warnings: %s" % messages.messages[:3])
bptest.check(valid.all(), "every point of the map valid: %d of %d" % (valid.sum(), len(valid)))
times = np.arange(0.0, T + 0.25, 0.5)
field = ftle_map.sampled_field(gyre, times)
reference = ftle_map.reference_ftle(field, times, points, 0.0, ftle_map.SIZE / 2, t_start=T)
stats = ftle_map.compare(values, reference, valid)
print("backward FTLE map against numpy: %s" %
      ", ".join("%s %.4g" % kv for kv in sorted(stats.items())))
bptest.check(stats["correlation"] > 0.95, "correlation %.3f" % stats["correlation"])
bptest.check(stats["ridge_overlap"] > 0.9, "ridges overlap %.3f" % stats["ridge_overlap"])
bptest.check(stats["median_relative_error"] < 0.02,
             "median relative difference %.4f" % stats["median_relative_error"])
forward = ftle_map.reference_ftle(field, times, points, T, ftle_map.SIZE / 2)
other = ftle_map.compare(values, forward, valid)
print("backward FTLE map against the forward reference: %s" %
      ", ".join("%s %.4g" % kv for kv in sorted(other.items())))
bptest.check(other["correlation"] < stats["correlation"] - 0.1,
             "the forward map is another: correlation %.3f" % other["correlation"])
map_time = OutputPort(tracer, 1).GetDataInformation().DataInformation.GetTime()
bptest.check(map_time == 0.0, "the map is stamped with the time shown (%s)" % map_time)
# Between two input time steps (0.5 apart) too: the time shown, not the
# last step read.
tracer.UpdatePipeline(2.25)
map_time = OutputPort(tracer, 1).GetDataInformation().DataInformation.GetTime()
bptest.check(map_time == 2.25, "at 2.25 the map is stamped with the time shown (%s)" % map_time)

bptest.finish()
