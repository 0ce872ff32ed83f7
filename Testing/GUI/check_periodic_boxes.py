# Run from the GUI's Python shell by walls.xml, twice, after clicks on the
# Periodic property's check boxes (X, Y, Z) were applied:
#  1. after Z was ticked beside X: the tracer's Periodic is 1 0 1; saves the
#     state (a .pvsm in the test's scratch folder, $HOME), deletes the
#     pipeline, loads the state and shows the loaded tracer's panel (whose
#     boxes walls.xml then checks); says it passed by setting the loaded
#     tracer's Coloring Axis to X;
#  2. after X was unticked there: Periodic is 0 0 1; sets Coloring Axis to Y.
import builtins
import os

import gui_check
from paraview.simple import Delete, FindSource, LoadState, SaveState, SetActiveSource


def check():
    tracer = FindSource("BoundParticleTracer1")
    reloaded = getattr(builtins, "_boundparticles_periodic_reloaded", False)
    expected = [0, 0, 1] if reloaded else [1, 0, 1]
    found = {"Periodic %s" % " ".join(map(str, expected)): list(tracer.Periodic) == expected}
    if reloaded:
        if gui_check.passed("check_periodic_boxes", found):
            tracer.ColoringAxis = "Y"
        return
    path = os.path.join(os.environ["HOME"], "periodic.pvsm")
    SaveState(path)
    SetActiveSource(None)
    for name in ("BoundParticleTracer1", "Calculator1", "AnalyticFlow1"):
        Delete(FindSource(name))
    LoadState(path)
    loaded = FindSource("BoundParticleTracer1")
    builtins._boundparticles_periodic_reloaded = True
    found["a tracer loaded from the state"] = loaded is not None
    found["loaded with Periodic 1 0 1"] = loaded is not None and \
        list(loaded.Periodic) == [1, 0, 1]
    if gui_check.passed("check_periodic_boxes", found, {"state": path}):
        loaded.ColoringAxis = "X"
        SetActiveSource(loaded)


gui_check.run("check_periodic_boxes", check)
