# Run from the GUI's Python shell by time_back.xml, before Initial State File
# is set in the panel: keeps the picture of the last frame (the trace that
# never stopped) and the steps it took from the start, then goes to the
# middle frame and saves the State output there as File > Save Data does
# (SaveData on port 2, a .vtp in the test's scratch folder, $HOME), and goes
# back to the last frame: the panel's Apply then resumes there.
import builtins
import os

import gui_check
from paraview import servermanager
from paraview.simple import FindSource, GetAnimationScene, OutputPort, SaveData


def save():
    tracer = FindSource("BoundParticleTracer1")
    scene = GetAnimationScene()
    times = list(tracer.TimestepValues)
    scene.AnimationTime = times[-1]
    data = servermanager.Fetch(tracer)
    builtins._boundparticles_straight = [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]
    scene.AnimationTime = times[len(times) // 2]
    path = os.path.join(os.environ["HOME"], "state.vtp")
    SaveData(path, proxy=OutputPort(tracer, 2))
    gui_check.say("save_state", "saved %s (%d bytes) at t = %g" %
                  (path, os.path.getsize(path) if os.path.exists(path) else -1,
                   scene.AnimationTime))
    scene.AnimationTime = times[-1]


gui_check.run("save_state", save)
