"""Catalyst analysis script (version 2): traces bound particles through the
simulation's flow one step at a time, and every N steps writes the elements
(`elements_NNNN.vtp`, or `.pvtp` with a piece per process under MPI) and a
picture (`elements_NNNN.png`)."""
import os

from paraview import catalyst
from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingCore import vtkProcessModule

options = catalyst.Options()
LoadPlugin(os.environ["BOUNDPARTICLES_PLUGIN"], ns=globals())
OUT = os.environ.get("BOUNDPARTICLES_INSITU_OUT", ".")
EVERY = int(os.environ.get("BOUNDPARTICLES_INSITU_EVERY", "10"))
LAST = int(os.environ.get("BOUNDPARTICLES_INSITU_LAST", "-1"))
# ParaView writes a serial .vtp from one process only; under MPI each process
# writes its piece of the elements under one .pvtp.
PARALLEL = vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions() > 1
EXTENSION = ".pvtp" if PARALLEL else ".vtp"

# Catalyst's producer: the simulation's grid at the present step.
flow = TrivialProducer(registrationName="input")
tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"], ElementShape="Paddlewheel",
                             NumberOfElements=200, Seed=3, Engine="CPU",
                             # In situ the run's length is not known ahead: the automatic
                             # lifetimes would come from the field alone. Say them.
                             LifetimeRange=[2.0, 4.0])
view = CreateRenderView(ViewSize=[640, 360])
Show(tracer, view)
view.CameraPosition = [1.0, 0.5, 3.0]
view.CameraFocalPoint = [1.0, 0.5, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.55


def catalyst_execute(info):
    tracer.UpdatePipeline(info.time)
    if info.timestep % EVERY == 0 or info.timestep == LAST:
        name = os.path.join(OUT, "elements_%04d" % info.timestep)
        SaveData(name + EXTENSION, proxy=tracer)
        Render(view)
        SaveScreenshot(name + ".png", view)
