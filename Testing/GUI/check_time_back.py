# Run twice from the GUI's Python shell by time_back.xml (time_back_watch.py
# records the tracer's updates). First, after three Previous Frame presses:
# drags the time back (the scene's time set as the time slider sets it), then
# finds every update since the last frame answered from the nearest
# checkpoint (at most the steps between two of them, and the frame's short
# one) and the shown points equal to those a replay from
# the start gives at that time; sets Coloring Axis to X. Second, after Play Backwards: the same
# for every frame played, ending at the first; sets Coloring Axis to Y.
import builtins

import gui_check
from paraview import servermanager
from paraview.simple import FindSource, GetAnimationScene

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
    spacing = max([u["spacing"] for u in answered] or [0])  # the automatic Checkpoint Memory's
    total = round((times[-1] - times[0]) / tracer.GetPropertyValue("ResolvedTimeStep"))
    found = {
        "updates recorded": len(answered) >= expected,
        "checkpoints kept": 0 < spacing < total,
        # Before the first checkpoint the start is the nearest (a replay of as few steps).
        "each within the checkpoints' spacing": all(u["steps"] <= spacing + 1 for u in answered),
        "the picture is the one a replay from the start gives": same,
        "at the middle" if first else "at the first frame":
            abs(shown - (times[len(times) // 2] if first else times[0])) < 1e-9,
    }
    seen = {"updates": len(answered), "steps": sorted({u["steps"] for u in answered}),
            "spacing": spacing, "steps to the end": total,
            "time": shown}
    if gui_check.passed("check_time_back (%s)" % ("back" if first else "reverse"), found, seen):
        tracer.ColoringAxis = "X" if first else "Y"
    # Any change replays (Checkpoint Memory put back, Coloring Axis): replay
    # here, so that Play Backwards starts from a trace with its checkpoints.
    points_at(tracer, shown)
    del updates[:]


gui_check.run("check_time_back", check)
