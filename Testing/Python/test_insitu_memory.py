"""In situ memory stays flat (issue 42, item 5): 500 steps of the double gyre,
each a new grid made by the "simulation" (numpy) and handed to the tracer
through a trivial producer, as Catalyst's adaptor does; the tracer updated at
each step, its elements released and ended all along (lifetimes of 1 to 2
time units over 50 time units). The process's resident memory (VmRSS) after
the warm-up (step 50) and after step 500 may differ by at most BOUND_MIB.

The bound: one step's grid is 64 x 32 x 2 points of 3 doubles, 96 KiB, so a
trace that kept each step's field (or its copy) would grow by 42 MiB over
the 450 steps measured, five times the bound; bench/insitu_steps.py measured
0.1 MiB of growth between steps 51 and 500 (docs/user-guide.md). With
`--keep-steps` the script itself holds every step it hands over, a leak of
one step a step, and must fail: a check of the check.
"""
import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--steps", "--keep-steps")

from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402
from insitu_feed import feed  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
STEPS = int(args.steps or 500)
WARM_UP = 50
BOUND_MIB = 8.0
DIMS = (64, 32, 2)
DT = 0.1


def grid_at(t):
    """The double gyre (A 0.1, epsilon 0.25, omega pi/5) at t on [0, 2] x [0, 1]."""
    x = numpy.linspace(0.0, 2.0, DIMS[0])
    y = numpy.linspace(0.0, 1.0, DIMS[1])
    xx, yy = numpy.meshgrid(x, y, indexing="xy")
    a, eps, omega = 0.1, 0.25, math.pi / 5.0
    at, bt = eps * math.sin(omega * t), 1.0 - 2.0 * eps * math.sin(omega * t)
    f = at * xx * xx + bt * xx
    u = -math.pi * a * numpy.sin(math.pi * f) * numpy.cos(math.pi * yy)
    v = math.pi * a * numpy.cos(math.pi * f) * numpy.sin(math.pi * yy) * (2.0 * at * xx + bt)
    layer = numpy.stack([u, v, numpy.zeros_like(u)], axis=-1).reshape(-1, 3)
    image = vtkImageData()
    image.SetDimensions(*DIMS)
    image.SetSpacing(2.0 / (DIMS[0] - 1), 1.0 / (DIMS[1] - 1), 0.05)
    velocity = numpy_to_vtk(numpy.concatenate([layer] * DIMS[2]), deep=1)
    velocity.SetName("velocity")
    image.GetPointData().AddArray(velocity)
    return image


producer = PVTrivialProducer()
tracer = BoundParticleTracer(Input=producer, Vectors=["POINTS", "velocity"],
                             ElementShape="Paddlewheel", NumberOfElements=200, Seed=3,
                             Engine="CPU", LifetimeRange=[1.0, 2.0])
kept = []
resident = {}
counts = []
with bptest.CapturedMessages() as said:
    for step in range(1, STEPS + 1):
        t = step * DT
        grid = grid_at(t)
        if args.keep_steps:
            kept.append(grid)
        feed(producer, grid, t)
        tracer.UpdatePipeline(t)
        if step % 50 == 0:
            counts.append(tracer.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints())
            resident[step] = bptest.resident_mib()
            print("step %d (t = %g): %d points, %.1f MiB resident"
                  % (step, t, counts[-1], resident[step]), flush=True)
said.messages = [m for m in said.messages if "New time step is not" not in m]
bptest.check(not said.messages, "nothing said over %d steps: %s" % (STEPS, said.messages[:3]))
bptest.check(counts and min(counts) > 0, "the tracer had elements all along: %s" % counts)
growth = resident[STEPS] - resident[WARM_UP]
print("resident memory after step %d: %.1f MiB, after step %d: %.1f MiB: grew %.2f MiB "
      "(bound %.0f MiB)" % (WARM_UP, resident[WARM_UP], STEPS, resident[STEPS], growth, BOUND_MIB))
bptest.check(growth < BOUND_MIB,
             "resident memory grew %.2f MiB between steps %d and %d (%.1f to %.1f MiB), "
             "more than %.0f MiB" % (growth, WARM_UP, STEPS, resident[WARM_UP], resident[STEPS],
                                     BOUND_MIB))
bptest.finish()
