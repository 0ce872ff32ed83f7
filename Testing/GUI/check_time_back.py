# Run twice from the GUI's Python shell by time_back.xml (time_back_watch.py
# records the tracer's updates). First, after three Previous Frame presses:
# drags the time back (the scene's time set as the time slider sets it), then
# finds every update since the last frame answered from a checkpoint (no
# replay, at most two steps) and the shown points equal to those a replay from
# the start gives at that time; sets Coloring Axis to X. Second, after Play Backwards: the same
# for every frame played, ending at the first; sets Coloring Axis to Y.
import builtins

import gui_check
from paraview import servermanager
from paraview.simple import FindSource, GetAnimationScene

MOST_STEPS = 2  # one checkpoint a step here: a step back is one step and the frame's short one

updates = builtins._boundparticles_time_back
tracer = FindSource("BoundParticleTracer1")
scene = GetAnimationScene()
times = list(tracer.TimestepValues)
first = tracer.ColoringAxis == "Z"
if first:
    scene.AnimationTime = times[len(times) // 2]  # the slider dragged back to the middle


def points_at(source, t):
    source.UpdatePipeline(t)
    data = servermanager.Fetch(source)
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def check():
    shown = scene.AnimationTime
    answered = list(updates)
    resumed = points_at(tracer, shown)
    # The same trace replayed from the start (a change of Checkpoint Memory
    # replays), then put back as it was.
    budget = tracer.CheckpointMemory
    tracer.CheckpointMemory = 0
    same = resumed == points_at(tracer, shown)
    tracer.CheckpointMemory = budget
    expected = 4 if first else len(times) // 2  # 3 Previous Frame and a drag; the frames played
    found = {
        "updates recorded": len(answered) >= expected,
        # The first frame is the start itself: placing the elements, no step.
        "none replayed from the start (but to it)":
            not any(u["replayed"] and u["steps"] > 0 for u in answered),
        "each at most %d steps" % MOST_STEPS: all(u["steps"] <= MOST_STEPS for u in answered),
        "the picture is the one a replay from the start gives": same,
        "at the middle" if first else "at the first frame":
            abs(shown - (times[len(times) // 2] if first else times[0])) < 1e-9,
    }
    seen = {"updates": len(answered), "steps": sorted({u["steps"] for u in answered}),
            "time": shown}
    if gui_check.passed("check_time_back (%s)" % ("back" if first else "reverse"), found, seen):
        tracer.ColoringAxis = "X" if first else "Y"
    # Any change replays (Checkpoint Memory put back, Coloring Axis): replay
    # here, so that Play Backwards starts from a trace with its checkpoints.
    points_at(tracer, shown)
    del updates[:]


gui_check.run("check_time_back", check)
