"""What the tracer takes from its input by default, as a new user meets it
(issue 38 item 3): of several 3-component arrays, the input's active
vectors, else the one named like a velocity (VEL over ACCL and DISPL, as on
Exodus's can), else the first; and Output Messages says which it traces and
why, once per choice. A flat field whose vectors cross its plane (issue 46
item 5) keeps its elements in the plane, and says so once.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments()

from paraview.simple import *  # noqa: E402,F401,F403

LoadPlugin(args.plugin, ns=globals())


def can_like(active=None, names=("ACCL", "DISPL", "VEL")):
    """An image with the can's three point arrays (acceleration 1e7 times the
    velocity), `active` marked as its active vectors."""
    source = ProgrammableSource(OutputDataSetType="vtkImageData")
    source.ScriptRequestInformation = (
        "from paraview import util\n"
        "util.SetOutputWholeExtent(self, [0, 8, 0, 8, 0, 8])\n")
    source.Script = (
        "import numpy\n"
        "from vtkmodules.util.numpy_support import numpy_to_vtk\n"
        "out = self.GetOutput()\n"
        "out.SetExtent(0, 8, 0, 8, 0, 8)\n"
        "out.SetSpacing(0.1, 0.1, 0.1)\n"
        "for name, scale in zip(%r, (1e7, 0.01, 1.0)):\n"
        "    a = numpy_to_vtk(numpy.tile([scale, 0.5 * scale, 0.0], (729, 1)), deep=True)\n"
        "    a.SetName(name)\n"
        "    out.GetPointData().AddArray(a)\n"
        "if %r:\n"
        "    out.GetPointData().SetActiveVectors(%r)\n" % (list(names), active, active))
    source.UpdatePipeline()
    return source


# The can: VEL, not the first array (ACCL).
can = can_like()
tracer = BoundParticleTracer(Input=can)
bptest.check(list(tracer.Vectors) == ["POINTS", "VEL"],
             "the velocity is picked over ACCL and DISPL: %s" % list(tracer.Vectors))
with bptest.CapturedMessages(texts=True) as said:
    tracer.UpdatePipeline(0.5)
    tracer.StepSize = 0.4  # a replay with the same choice says nothing more
    tracer.UpdatePipeline(0.5)
notes = [m for m in said.messages if "traces 'VEL'" in m]
bptest.check(len(notes) == 1 and "named like a velocity" in notes[0] and
             "ACCL, DISPL" in notes[0],
             "Output Messages says once what is traced and why: %s" % said.messages)
# Another choice is said again.
tracer.Vectors = ["POINTS", "ACCL"]
with bptest.CapturedMessages(texts=True) as said:
    tracer.UpdatePipeline(0.5)
bptest.check(said.mentions("traces 'ACCL' (as Vectors asks)"),
             "a choice made in Vectors is said: %s" % said.messages)
Delete(tracer)

# The input's own active vectors win over a name.
marked = can_like(active="ACCL")
tracer = BoundParticleTracer(Input=marked)
bptest.check(list(tracer.Vectors) == ["POINTS", "ACCL"],
             "the input's active vectors are kept: %s" % list(tracer.Vectors))
with bptest.CapturedMessages(texts=True) as said:
    tracer.UpdatePipeline(0.5)
bptest.check(said.mentions("the input's active vectors"),
             "and said to be the active vectors: %s" % said.messages)
Delete(tracer)

# No name like a velocity: the first, as before.
plain = can_like(names=("first", "second", "third"))
tracer = BoundParticleTracer(Input=plain)
bptest.check(list(tracer.Vectors) == ["POINTS", "first"],
             "with no velocity name, the first: %s" % list(tracer.Vectors))
Delete(tracer)

# A flat image (one z point, at z = 0.25) whose vectors cross its plane: the
# elements stay in it, and that is said once.
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
flat = ProgrammableSource(OutputDataSetType="vtkImageData")
flat.ScriptRequestInformation = (
    "from paraview import util\n"
    "util.SetOutputWholeExtent(self, [0, 20, 0, 10, 0, 0])\n")
flat.Script = (
    "import numpy\n"
    "from vtkmodules.util.numpy_support import numpy_to_vtk\n"
    "out = self.GetOutput()\n"
    "out.SetExtent(0, 20, 0, 10, 0, 0)\n"
    "out.SetOrigin(0.0, 0.0, 0.25)\n"
    "out.SetSpacing(0.1, 0.1, 1.0)\n"
    "v = numpy_to_vtk(numpy.tile([0.3, 0.1, 0.5], (231, 1)), deep=True)\n"
    "v.SetName('velocity')\n"
    "out.GetPointData().SetVectors(v)\n")
flat.UpdatePipeline()
tracer = BoundParticleTracer(Input=flat, NumberOfElements=50)
with bptest.CapturedMessages() as said:
    for t in tracer.TimestepValues[::10]:
        tracer.UpdatePipeline(t)
z = vtk_to_numpy(servermanager.Fetch(tracer).GetPoints().GetData())[:, 2]
crossing = [m for m in said.messages if "crosses its plane" in m or "cross its plane" in m]
bptest.check(len(crossing) == 1 and "flat along Z" in crossing[0] and "up to 0.5" in crossing[0],
             "vectors across a flat field's plane are said once: %s" % said.messages)
bptest.check(abs(z - 0.25).max() < 1e-5, "the elements stay in the plane (off by %.3g)" %
             abs(z - 0.25).max())
Delete(tracer)

# One array only: nothing to say.
single = AnalyticFlow(Flow="ABC", Resolution=[8, 8, 8])
single.UpdatePipeline()
tracer = BoundParticleTracer(Input=single)
with bptest.CapturedMessages(texts=True) as said:
    tracer.UpdatePipeline(0.5)
found = [m for m in said.messages if "traces " in m]
bptest.check(not found,
             "no note where there is no choice: %s" % said.messages)
bptest.finish()
