# Run from the GUI's Python shell by time_back.xml after Initial State File
# was set in the panel and applied at the last frame: the tracer replayed
# from the state saved at the middle frame (save_state.py), taking only the
# steps after it, and shows the picture of the trace that never stopped;
# sets Coloring Axis to Z.
import builtins

import gui_check
from paraview import servermanager
from paraview.simple import FindSource


def check():
    tracer = FindSource("BoundParticleTracer1")
    data = servermanager.Fetch(tracer)
    shown = [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]
    tracer.UpdatePropertyInformation()
    steps = tracer.GetPropertyValue("StepsInLastUpdate")
    times = list(tracer.TimestepValues)
    total = round((times[-1] - times[0]) / tracer.GetPropertyValue("ResolvedTimeStep"))
    found = {
        "Initial State File set": tracer.InitialStateFile.endswith("state.vtp"),
        "a replay": tracer.GetPropertyValue("LastUpdateReplayed") == 1,
        "from the state: about half the steps": 0 < steps <= total // 2 + 2,
        "the picture of the trace that never stopped":
            len(shown) > 0 and shown == builtins._boundparticles_straight,
    }
    if gui_check.passed("check_resumed", found, {"steps": steps, "of": total}):
        tracer.ColoringAxis = "Z"


gui_check.run("check_resumed", check)
