"""A Seed Source with time steps gives the same trace whatever was shown
before (issue 27, item 4): its points are read at the trace's start, so an
update to t = 2 from nothing and one after t = 0 and t = 1 give the same bits,
for a time-varying source and for a tracer's own output fed back as seeds, on
the CPU engine's output.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
args = parser.parse_args()

from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

LoadPlugin(args.plugin, ns=globals())


def moving_points():
    """Points whose x follows the time asked for (time steps 0 to 3)."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.ScriptRequestInformation = (
        "from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as S\n"
        "self.GetOutputInformation(0).Set(S.TIME_STEPS(), [0.0, 1.0, 2.0, 3.0], 4)\n")
    source.Script = (
        "from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as S\n"
        "from vtkmodules.vtkCommonCore import vtkPoints\n"
        "info = self.GetOutputInformation(0)\n"
        "t = info.Get(S.UPDATE_TIME_STEP()) if info.Has(S.UPDATE_TIME_STEP()) else 0.0\n"
        "p = vtkPoints()\n"
        "for i in range(20): p.InsertNextPoint(-0.8 + 0.2 * t, -0.9 + 0.09 * i, 0.1)\n"
        "self.GetOutput().SetPoints(p)\n")
    return source


def traced(make_seeds, times):
    flow = AnalyticFlow(Flow="Double Gyre", Resolution=[32, 16, 2], Bounds=[-1, 1, -1, 1, 0, 0.1])
    flow.UpdatePipeline()
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"], SeedSource=make_seeds(flow),
                                 ElementShape="Cross", NumberOfElements=60, Seed=3)
    for t in times:
        tracer.UpdatePipeline(t)
    points = vtk_to_numpy(servermanager.Fetch(tracer).GetPoints().GetData()).copy()
    for proxy in list(GetSources().values()):
        Delete(proxy)
    return points


def own_output(flow):
    return BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"], ElementShape="Point",
                               NumberOfElements=40, Seed=5)


for label, make_seeds in (("time-varying source", lambda flow: moving_points()),
                          ("a tracer's output", own_output)):
    fresh = traced(make_seeds, [2.0])
    played = traced(make_seeds, [0.0, 1.0, 2.0])
    bptest.check(len(fresh) > 0, "%s: nothing traced" % label)
    same = fresh.shape == played.shape and (fresh == played).all()
    bptest.check(same, "%s: update(2) from nothing and after 0, 1 differ by %s" % (
        label, abs(fresh - played).max() if fresh.shape == played.shape else "their shapes"))
    print("%s: %d points, the same bits either way: %s" % (label, len(fresh), same))
bptest.finish()
