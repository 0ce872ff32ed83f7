"""An update's progress runs once from 0 to 1, also over an unsteady input
whose update takes one pipeline pass per input time step (it used to restart
at 0 on every pass, so ParaView's progress bar jumped back)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())

flow = AnalyticFlow(Flow="Double Gyre", NumberOfTimeSteps=21)
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, NumberOfElements=500)
seen = []
tracer.GetClientSideObject().AddObserver("ProgressEvent",
                                         lambda o, e: seen.append(o.GetProgress()))
times = list(tracer.TimestepValues)
for name, t in (("replay to the end", times[-1]), ("back to the middle", times[len(times) // 2]),
                ("on to the end", times[-1])):
    del seen[:]
    tracer.UpdatePipeline(t)
    drops = sum(1 for a, b in zip(seen, seen[1:]) if b < a - 1e-9)
    print("%s: %d progress events, %d drops, last %s" % (name, len(seen), drops, seen[-1:]))
    bptest.check(len(seen) > 10, "%s: %d progress events" % (name, len(seen)))
    bptest.check(drops == 0, "%s: progress went back %d times" % (name, drops))
    bptest.check(seen and seen[-1] == 1.0, "%s: progress ends at %s" % (name, seen[-1:]))
bptest.finish()
