"""Save the GPU display's own state, as a pvpython user does it: a tracer with
Engine GPU shown as Bound Particles, SaveData on its State output
(OutputPort(tracer, 2)). The file holds the GPU engine's state read back from
the display (no note), at the last step boundary before the time shown, and
saving leaves the picture as it was. Resumed in the GPU display, every later
step is bit for bit the one of a GPU trace that never stopped (compared by
the states both save later); resumed with Engine CPU, the elements agree with
that trace within the engines' parity (docs/engine-specification.md, section
8). The GPU engine runs on this machine's Mesa llvmpipe."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from state_file import read_state  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
folder = bptest.scratch("bp-gpu-save-")

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[32, 16, 2], NumberOfTimeSteps=21)
DIAGONAL = float(np.sqrt(2.0 ** 2 + 1.0 ** 2))  # the double gyre's domain, [0, 2] x [0, 1]


def tracer_on(**extra):
    settings = dict(Input=flow, Vectors=["POINTS", "velocity"], Engine="GPU",
                    NumberOfElements=300, Seed=3, ElementShape="Cross",
                    LifetimeRange=[1.0, 3.0], Trails=1, TrailLength=4)
    settings.update(extra)
    return BoundParticleTracer(**settings)


def save_state(tracer, name):
    path = os.path.join(folder, name + ".vtp")
    with bptest.CapturedMessages() as messages:
        SaveData(path, proxy=OutputPort(tracer, 2))
    said = [m for m in messages.messages if "L2_NORM_RANGE" not in m]
    bptest.check(not said, "%s: saved without messages: %s" % (name, said[:2]))
    cells, fields = read_state(path)
    bptest.check("bpStateNote" not in fields,
                 "%s: a state, not a note: %s" % (name, fields.get("bpStateNote")))
    bptest.check(fields.get("bpStateFormat") == ["BoundParticlesState"],
                 "%s: the file is a Bound Particles state" % name)
    return path, cells, fields


def same_bits(a, b):
    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)


view = CreateRenderView(ViewSize=[320, 200])
view.OrientationAxesVisibility = 0
view.CameraPosition = [1.0, 0.5, 4.0]
view.CameraFocalPoint = [1.0, 0.5, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.6


def show_at(tracer, t, name=None):
    """The tracer shown as Bound Particles at time t (its display, the steps
    the update took, the messages said, and the picture when `name`)."""
    shown = Show(tracer, view)
    shown.SetRepresentationType("Bound Particles")
    bptest.colour_display(shown, None, None)
    with bptest.CapturedMessages() as messages:
        view.ViewTime = t
        Render(view)
        tracer.UpdatePropertyInformation()
        steps = tracer.GetPropertyValue("StepsInLastUpdate")
        picture = None
        if name:
            picture = os.path.join(folder, name + ".png")
            SaveScreenshot(picture, view)
    said = [m for m in messages.messages if "L2_NORM_RANGE" not in m]
    return shown, steps, said, picture


LATER = 7.5

# A GPU trace that never stops: its state at LATER, read back from its display.
straight = tracer_on()
shown, straight_steps, said, _ = show_at(straight, LATER)
bptest.check(not said, "the straight GPU trace: no messages: %s" % said[:2])
_, expected, expected_fields = save_state(straight, "straight-later")
Hide(straight, view)
straight.UpdatePropertyInformation()
dt = straight.GetPropertyValue("ResolvedTimeStep")
# Between two step boundaries: the display shows a short step past the
# boundary the state holds.
SAVE_AT = 3.0 + 2.4 * dt

# The saver: shown at SAVE_AT, saved there; the picture does not change.
saver = tracer_on()
shown, _, said, before = show_at(saver, SAVE_AT, "saver-before")
bptest.check(not said, "the saver: no messages: %s" % said[:2])
state, saved, saved_fields = save_state(saver, "gpu-state")
SaveScreenshot(os.path.join(folder, "saver-after.png"), view)
mean, pixels = bptest.image_difference(os.path.join(folder, "saver-after.png"), before, threshold=0)
bptest.check(mean == 0.0 and pixels == 0.0,
             "saving leaves the display's picture as it was (mean %g, pixels %g)" % (mean, pixels))
time_saved = float(saved_fields["bpTime"][0])
bptest.check(SAVE_AT - dt < time_saved < SAVE_AT,
             "the state stands on the boundary before the time shown, %r: %r (dt %r)"
             % (SAVE_AT, time_saved, dt))
bptest.check(saved["bpPositions"].shape[0] == 300, "the state holds the 300 elements")

# The same trace on the CPU engine saves (nearly) the same state: the GPU
# display's own state, not the CPU engine's, and within the engines' parity.
cpu_saver = tracer_on(Engine="CPU")
cpu_saver.UpdatePipeline(SAVE_AT)
_, cpu_saved, cpu_fields = save_state(cpu_saver, "cpu-state")
bptest.check(float(cpu_fields["bpTime"][0]) == time_saved and
             int(cpu_fields["bpSteps"][0]) == int(saved_fields["bpSteps"][0]),
             "the CPU engine's state stands on the same boundary")
same_generation = cpu_saved["bpGenerations"] == saved["bpGenerations"]
gap = np.abs(cpu_saved["bpPositions"] - saved["bpPositions"])[same_generation].max() / DIAGONAL
print("GPU state vs CPU state at t = %g: %d of 300 in the same generation, positions within "
      "%.3g of the diagonal" % (time_saved, same_generation.sum(), gap))
bptest.check(same_generation.sum() >= 297 and gap < 1e-4,
             "the GPU state agrees with the CPU engine's within parity")
# The display's engine fits every element's pose at every step (its colours
# may need them), the CPU engine only when an output array asks: the poses
# tell the display's state from the CPU engine's (whose positions may agree
# bit for bit, as on Mesa llvmpipe here).
bptest.check(not np.array_equal(cpu_saved["bpPoses"], saved["bpPoses"]),
             "the state saved is the GPU display's (its poses are fitted, the CPU's are not)")
print("positions of the two engines' states bit for bit equal: %s"
      % np.array_equal(cpu_saved["bpPositions"], saved["bpPositions"]))

# The saver goes on to LATER: the read-back changed nothing of its trace.
shown, _, said, _ = show_at(saver, LATER)
_, went_on, _ = save_state(saver, "saver-later")
bptest.check(same_bits(went_on, expected),
             "the saver goes on after saving bit for bit as the straight trace")
Hide(saver, view)

# Resumed in the GPU display: every bit of the straight trace at LATER.
resumed = tracer_on(InitialStateFile=state)
shown, steps, said, _ = show_at(resumed, LATER)
bptest.check(not said, "resumed on the GPU: no messages: %s" % said[:2])
bptest.check(0 < steps < straight_steps,
             "%d steps from the state, %d from the start" % (steps, straight_steps))
_, got, got_fields = save_state(resumed, "gpu-resumed-later")
bptest.check(same_bits(got, expected),
             "the GPU trace resumed from the GPU's state equals one that never stopped, bit "
             "for bit")
bptest.check(float(got_fields["bpTime"][0]) == float(expected_fields["bpTime"][0]),
             "at the same boundary")
Hide(resumed, view)

# Resumed with Engine CPU: the straight GPU trace within the engines' parity.
cpu_resumed = tracer_on(Engine="CPU", InitialStateFile=state)
with bptest.CapturedMessages() as messages:
    cpu_resumed.UpdatePipeline(LATER)
    cpu_resumed.UpdatePropertyInformation()
    cpu_steps = cpu_resumed.GetPropertyValue("StepsInLastUpdate")
said = [m for m in messages.messages if "L2_NORM_RANGE" not in m]
bptest.check(not said, "resumed on the CPU: no messages: %s" % said[:2])
bptest.check(0 < cpu_steps < straight_steps,
             "the CPU engine: %d steps from the state" % cpu_steps)
_, cpu_got, cpu_got_fields = save_state(cpu_resumed, "cpu-resumed-later")
bptest.check(float(cpu_got_fields["bpTime"][0]) == float(expected_fields["bpTime"][0]),
             "the CPU trace resumed stands on the same boundary")
same_generation = cpu_got["bpGenerations"] == expected["bpGenerations"]
gap = np.abs(cpu_got["bpPositions"] - expected["bpPositions"])[same_generation].max() / DIAGONAL
lifetimes = np.abs(cpu_got["bpLifetimes"] - expected["bpLifetimes"])[same_generation].max()
print("CPU resumed from the GPU's state vs GPU never stopped, at t = %g: %d of 300 in the "
      "same generation, positions within %.3g of the diagonal, lifetimes within %.3g"
      % (float(expected_fields["bpTime"][0]), same_generation.sum(), gap, lifetimes))
bptest.check(same_generation.sum() >= 297,
             "generations equal but for at most 1%% (%d differ)" % (300 - same_generation.sum()))
bptest.check(gap < 1e-4, "positions within 1e-4 of the diagonal (%.3g)" % gap)
# The comparison tells traces apart: another seed is far from it.
other = tracer_on(Engine="CPU", Seed=4)
other.UpdatePipeline(LATER)
_, far, _ = save_state(other, "other-seed")
far_gap = np.abs(far["bpPositions"] - expected["bpPositions"]).max() / DIAGONAL
bptest.check(far_gap > 1e-2, "another seed's trace is far from it (%.3g)" % far_gap)

Delete(view)
del view
bptest.finish()
