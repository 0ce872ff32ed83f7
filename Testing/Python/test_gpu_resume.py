"""Resume on the GPU engine as a pvpython user does it: the State output saved
with Engine CPU (SaveData on OutputPort(tracer, 2)), then a tracer with Engine
GPU and InitialStateFile shown as Bound Particles: the display uploads the
state and goes on from it, drawing the picture of a GPU trace that never
stopped (the engines agree at rounding, far below a pixel), with no message,
in fewer steps than from the start. The GPU engine runs on this machine's
Mesa llvmpipe."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
folder = bptest.scratch("bp-gpu-resume-")

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[32, 16, 2], NumberOfTimeSteps=21)


def tracer_on(**extra):
    settings = dict(Input=flow, Vectors=["POINTS", "velocity"], Engine="GPU",
                    NumberOfElements=300, Seed=3, ElementShape="Cross",
                    LifetimeRange=[1.0, 3.0], Trails=1, TrailLength=4)
    settings.update(extra)
    return BoundParticleTracer(**settings)


SAVE_AT, LATER = 3.0, 7.5
saver = tracer_on(Engine="CPU")
saver.UpdatePipeline(SAVE_AT)
state = os.path.join(folder, "state.vtp")
SaveData(state, proxy=OutputPort(saver, 2))
bptest.check(os.path.exists(state), "SaveData wrote the state")

view = CreateRenderView(ViewSize=[320, 200])
view.OrientationAxesVisibility = 0
view.CameraPosition = [1.0, 0.5, 4.0]
view.CameraFocalPoint = [1.0, 0.5, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.6


def shown_at(tracer, name, t):
    """The tracer shown as Bound Particles at time t: its picture, the steps
    the update took and the messages said."""
    shown = Show(tracer, view)
    shown.SetRepresentationType("Bound Particles")
    bptest.colour_display(shown, None, None)  # the elements' places, in one colour
    with bptest.CapturedMessages() as messages:
        view.ViewTime = t
        Render(view)
        tracer.UpdatePropertyInformation()
        steps = tracer.GetPropertyValue("StepsInLastUpdate")
        path = os.path.join(folder, name + ".png")
        SaveScreenshot(path, view)
    Delete(shown)
    return path, steps, messages.messages


straight = tracer_on()
expected, straight_steps, said = shown_at(straight, "straight", LATER)
bptest.check(not said, "the straight GPU trace: no messages: %s" % said[:2])
bptest.check(bptest.covered_fraction(expected) > 0.002, "the straight GPU trace draws elements")

resumed = tracer_on(InitialStateFile=state)
got, steps, said = shown_at(resumed, "resumed", LATER)
said = [m for m in said if "L2_NORM_RANGE" not in m]  # ParaView 6.1's reader (test_save_resume.py)
bptest.check(not said, "resumed on the GPU: no messages: %s" % said[:2])
bptest.check(0 < steps < straight_steps,
             "%d steps from the state, %d from the start" % (steps, straight_steps))
mean, pixels = bptest.image_difference(got, expected, threshold=32)
print("resumed on the GPU vs never stopped: mean difference %.4f, pixels differing %.4f, "
      "%d steps vs %d" % (mean, pixels, steps, straight_steps))
bptest.check(mean < 0.05 and pixels < 0.001,
             "the GPU trace resumed from the CPU's state draws the picture of one that never "
             "stopped (mean %.4f, pixels %.4f)" % (mean, pixels))

# The comparison tells traces apart: another seed draws another picture.
fresh, _, _ = shown_at(tracer_on(Seed=4), "other", LATER)
mean, pixels = bptest.image_difference(fresh, expected, threshold=32)
print("another seed: mean difference %.4f, pixels differing %.4f" % (mean, pixels))
bptest.check(pixels > 0.01, "another trace draws another picture (pixels %.4f)" % pixels)

Delete(view)
del view
bptest.finish()
