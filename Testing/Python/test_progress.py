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


# An abort from a progress observer (as a script, or ParaView 6.1's Abort
# button, asks) stops that update partway; the next update runs in full.
def simulation_time():
    """The output's time, read in place (a Fetch would update the tracer again)."""
    output = tracer.GetClientSideObject().GetOutputDataObject(0)
    value = output.GetFieldData().GetArray("SimulationTime")
    return value.GetValue(0) if value else float("nan")


def abort_halfway(algorithm, event):
    if algorithm.GetProgress() >= 0.5:
        algorithm.SetAbortExecuteAndUpdateTime()


tracer.Seed = 5  # a new configuration: the next update replays from the start
tag = tracer.GetClientSideObject().AddObserver("ProgressEvent", abort_halfway)
tracer.UpdatePipeline(times[-1])
tracer.GetClientSideObject().RemoveObserver(tag)
stopped = simulation_time()
print("aborted: output time %g (nan: none) of %g" % (stopped, times[-1]))
bptest.check(not stopped == times[-1], "the abort did not stop the update")
flow.NumberOfTimeSteps = 21  # unchanged: nothing upstream clears the request
tracer.UpdatePipeline(times[-2])
tracer.UpdatePipeline(times[-1])
bptest.check(simulation_time() == times[-1],
             "after an abort the next updates stop too (t = %g)" % simulation_time())
bptest.finish()
