# Run three times from the GUI's Python shell by displays.xml, once the
# tracer draws in the Bound Particles display with Engine GPU (issue 57: the
# State output holds the GPU display's own state, read back in the Qt view's
# GL context). Each run saves the State output from the Python shell
# (SaveData on port 2, a .vtp in the test's scratch folder, $HOME), or finds
# it saved with File > Save Data by the playback, and finds the file a
# state, not a note (bpStateNote), standing on the last step boundary at or
# before the time the view shows, and the view's picture the same before and
# after the save. Which run it is, Coloring Axis says:
#  Z: right after the Apply that moved the tracer to the GPU (the State output
#     computed on Apply, before the display drew: the save must read the
#     display back, not keep what Apply made); sets X;
#  X: after Next Frame three times, the State output saved by the playback
#     with File > Save Data (gpu_state.vtp; the picture before it kept in
#     builtins._boundparticles_before_save): the Initial State File the
#     playback sets next; records the tracer's updates from here on; sets Y;
#  Y: after the Initial State File applied and Next Frame twice: every
#     update since took fewer steps than a trace from the start (the state
#     was resumed from), the state saved now stands on a later boundary, and
#     equals bit for bit the state of the same GPU trace that never stopped
#     (Initial State File cleared, saved at the same time), with the same
#     picture in the view; sets Z.
import builtins
import os

import gui_check
import gui_render
import numpy
from paraview.simple import FindSource, GetActiveView, OutputPort, Render, SaveData
from state_file import read_state

tracer = FindSource("BoundParticleTracer1")
view = GetActiveView()


def save(name, saved_in_menu=False):
    """Saves the State output where the view stands (or finds it saved by
    File > Save Data, the picture before it kept by the playback); what was
    found."""
    path = os.path.join(os.environ["HOME"], name + ".vtp")
    runs = []
    if saved_in_menu:
        before = builtins._boundparticles_before_save
        runs = ["menu"]
    else:
        before = gui_render.pixels(view)
        observer = tracer.GetClientSideObject().AddObserver("EndEvent",
                                                            lambda *unused: runs.append(1))
        SaveData(path, proxy=OutputPort(tracer, 2))
        tracer.GetClientSideObject().RemoveObserver(observer)
    after = gui_render.pixels(view)
    cells, fields = read_state(path)
    tracer.UpdatePropertyInformation()
    dt = tracer.GetPropertyValue("ResolvedTimeStep")
    shown = view.ViewTime
    start = list(tracer.TimestepValues)[0]
    time = fields.get("bpTime", [float("nan")])[0]
    steps = fields.get("bpSteps", [-1])[0]
    eps = 1e-9 * max(1.0, abs(shown))
    found = {
        "a state, not a note": "bpStateNote" not in fields and
            fields.get("bpStateFormat") == ["BoundParticlesState"],
        "the last boundary at or before the time shown": shown - dt < time <= shown + eps and
            abs(start + steps * dt - time) <= 1e-6 * max(1.0, abs(time)),
        "the picture unchanged": before.shape == after.shape and
            bool(numpy.array_equal(before, after)),
    }
    seen = {"note": fields.get("bpStateNote"), "time shown": shown, "state time": time,
            "steps": steps, "dt": dt,
            "tracer runs in the save": runs[0] if saved_in_menu else len(runs),
            "elements": len(cells.get("bpPositions", [])),
            "pixels changed": int((numpy.abs(before - after).max(axis=1) > 0).sum())
            if before.shape == after.shape else "size"}
    save.picture = before
    return path, cells, fields, found, seen


def record_updates():
    """Every later update of the tracer: its time, steps, whether it
    replayed, and whether an Initial State File was set."""
    updates = []

    def ended(*unused):
        tracer.UpdatePropertyInformation()
        updates.append({"time": tracer.GetPropertyValue("SimulationTime"),
                        "steps": tracer.GetPropertyValue("StepsInLastUpdate"),
                        "replayed": bool(tracer.GetPropertyValue("LastUpdateReplayed")),
                        "from a state": bool(tracer.InitialStateFile)})

    tracer.GetClientSideObject().AddObserver("EndEvent", ended)
    builtins._boundparticles_gpu_save = updates


def check():
    axis = tracer.ColoringAxis
    display_ok = tracer.Engine == "GPU"
    if axis == "Z":
        _, _, _, found, seen = save("gpu_applied")
        found["Engine GPU"] = display_ok
        if gui_check.passed("check_gpu_save (applied)", found, seen):
            tracer.ColoringAxis = "X"
    elif axis == "X":
        _, _, fields, found, seen = save("gpu_state", saved_in_menu=True)
        found["Engine GPU"] = display_ok
        found["after some steps"] = fields.get("bpSteps", [0])[0] > 0
        builtins._boundparticles_gpu_saved = fields
        record_updates()
        if gui_check.passed("check_gpu_save (played)", found, seen):
            tracer.ColoringAxis = "Y"
    else:
        updates = list(builtins._boundparticles_gpu_save)
        saved = builtins._boundparticles_gpu_saved
        _, resumed, fields, found, seen = save("gpu_resumed")
        picture = save.picture
        dt = tracer.GetPropertyValue("ResolvedTimeStep")
        start = list(tracer.TimestepValues)[0]
        from_state = [u for u in updates if u["from a state"]]
        found["Initial State File set"] = tracer.InitialStateFile.endswith("gpu_state.vtp")
        found["a replay from the state"] = any(u["replayed"] for u in from_state)
        found["each update fewer steps than from the start"] = bool(from_state) and all(
            0 <= u["steps"] < round((u["time"] - start) / dt) for u in from_state)
        found["traced on past the state"] = fields.get("bpSteps", [0])[0] > saved["bpSteps"][0]
        # The same GPU trace that never stopped, saved at the same time.
        tracer.InitialStateFile = ""
        Render(view)
        _, straight, straight_fields, straight_found, _ = save("gpu_straight")
        found["the straight trace saved"] = all(straight_found.values())
        found["bit for bit the trace that never stopped"] = (
            straight_fields.get("bpTime") == fields.get("bpTime") and
            resumed.keys() == straight.keys() and
            all(numpy.array_equal(resumed[k], straight[k]) for k in resumed))
        found["the picture of the trace that never stopped"] = bool(
            numpy.array_equal(picture, save.picture))
        seen["updates from the state"] = [(u["steps"], u["replayed"]) for u in from_state]
        seen["state saved at"] = saved["bpTime"][0]
        if gui_check.passed("check_gpu_save (resumed)", found, seen):
            tracer.ColoringAxis = "Z"


gui_check.run("check_gpu_save", check)
