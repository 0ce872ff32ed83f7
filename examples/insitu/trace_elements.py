"""Catalyst analysis script (version 2): traces bound particles through the
simulation's flow one step at a time, and every N steps writes the elements
(`elements_NNNN.vtp`, or `.pvtp` with a piece per process under MPI) and a
picture (`elements_NNNN.png`).

With the GPU engine (the simulation's `--engine GPU`, on one process) the
Bound Particles display traces in the render view's GL context and draws
the elements there, rendering every step: the elements live on the GPU, so
only the pictures are written.

Checkpoints (the simulation's `--checkpoint-every K`): every K steps the
trace's state is written with the solver's checkpoint (`state_NNNN.vtp`, or
`.pvtp` under MPI: the tracer's State output, its third). A simulation
restarted from its checkpoint N (`--restart-from N`) hands step N first, and
the tracer goes on from the state saved there (its Initial State File)."""
import os

from paraview import catalyst
from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingCore import vtkProcessModule

options = catalyst.Options()
LoadPlugin(os.environ["BOUNDPARTICLES_PLUGIN"], ns=globals())
OUT = os.environ.get("BOUNDPARTICLES_INSITU_OUT", ".")
EVERY = int(os.environ.get("BOUNDPARTICLES_INSITU_EVERY", "10"))
LAST = int(os.environ.get("BOUNDPARTICLES_INSITU_LAST", "-1"))
ENGINE = os.environ.get("BOUNDPARTICLES_INSITU_ENGINE", "CPU")
CHECKPOINT_EVERY = int(os.environ.get("BOUNDPARTICLES_INSITU_CHECKPOINT_EVERY", "0"))
CHECKPOINTS = os.environ.get("BOUNDPARTICLES_INSITU_CHECKPOINTS", OUT)
RESTART = int(os.environ.get("BOUNDPARTICLES_INSITU_RESTART", "-1"))
# ParaView writes a serial .vtp from one process only; under MPI each process
# writes its piece of the elements under one .pvtp.
PARALLEL = vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions() > 1
EXTENSION = ".pvtp" if PARALLEL else ".vtp"

# The tracer's settings, the camera and the colours (the example's test reads them here).
SETTINGS = {"Vectors": ["POINTS", "velocity"], "ElementShape": "Paddlewheel",
            "NumberOfElements": 200, "Seed": 3,
            # In situ the run's length is not known ahead: the automatic
            # lifetimes would come from the field alone. Say them.
            "LifetimeRange": [2.0, 4.0]}
# Obliquely from above: a paddlewheel's blades stand across the flow's
# plane, so straight from above they would be seen edge on.
CAMERA = {"CameraPosition": [1.0, -1.1, 1.7], "CameraFocalPoint": [1.0, 0.45, 0.0],
          "CameraViewUp": [0.0, 0.74, 0.68], "CameraViewAngle": 30.0}
# Coloured by speed over the double gyre's range (A pi = 0.31, a little more
# where the gyres' edges move): the same colours at every step, in any run.
SPEEDS = [0.0, 0.35]

# Catalyst's producer: the simulation's grid at the present step.
flow = TrivialProducer(registrationName="input")
tracer = BoundParticleTracer(Input=flow, Engine=ENGINE, **SETTINGS)


def state_name(step):
    return os.path.join(CHECKPOINTS, "state_%04d%s" % (step, EXTENSION))


if RESTART >= 0 and os.path.exists(state_name(RESTART)):
    # The simulation restarted from its checkpoint: the trace goes on from
    # the state saved with it (on either engine).
    tracer.InitialStateFile = state_name(RESTART)
elif RESTART >= 0:
    print("Restart: no trace state %s (a run with the GPU engine saves none): the trace starts "
          "afresh at step %d." % (state_name(RESTART), RESTART))
if CHECKPOINT_EVERY > 0 and ENGINE != "CPU":
    print("Checkpoints: the GPU display keeps its state on the GPU and cannot save it; the "
          "trace's state is not written (run with --engine CPU to checkpoint the trace).")
SIZE = [640, 360]
view = CreateRenderView(ViewSize=SIZE, OrientationAxesVisibility=0)
shown = Show(tracer, view)
if ENGINE != "CPU":
    shown.SetRepresentationType("Bound Particles")
ColorBy(shown, ("POINTS", "Speed"))
GetColorTransferFunction("Speed").RescaleTransferFunction(*SPEEDS)


def render():
    # Set each time: the first render resets the camera to the data.
    for key, value in CAMERA.items():
        setattr(view, key, value)
    Render(view)


def catalyst_execute(info):
    written = info.timestep % EVERY == 0 or info.timestep == LAST
    name = os.path.join(OUT, "elements_%04d" % info.timestep)
    if ENGINE != "CPU":
        # The display steps the elements in its render: one each step.
        view.ViewTime = info.time
        render()
    else:
        tracer.UpdatePipeline(info.time)
    checkpoint = CHECKPOINT_EVERY > 0 and info.timestep % CHECKPOINT_EVERY == 0
    if checkpoint and info.timestep > max(RESTART, 0) and ENGINE == "CPU":
        # The state at the step just traced: every data time is a step
        # boundary, so a restart from this step goes on bit for bit.
        SaveData(state_name(info.timestep), proxy=OutputPort(tracer, 2))
    if written:
        if ENGINE == "CPU":
            SaveData(name + EXTENSION, proxy=tracer)
            render()
        SaveScreenshot(name + ".png", view, ImageResolution=SIZE)
