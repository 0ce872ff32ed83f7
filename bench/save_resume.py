"""What saving and resuming a trace costs (issue 57, item 3): a trace of N
Strip16 elements is shown at its middle frame and its State output saved
(SaveData on output port 2, binary .vtp); a new tracer with that Initial
State File then goes on to the last frame, and a third traces to the last
frame from the start. Side by side in one process, for each element count:
the state file's size, the time to save it, the resume's time and steps
against the straight trace's, and whether the resumed points are the
straight trace's bits. Medians of --repeats.

    with-display.sh pvpython bench/save_resume.py --plugin BoundParticles.so
"""
import argparse
import os
import statistics
import sys
import tempfile
import time

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tracer_costs import shear_layer, strip16_tracer  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--elements", default="4000,40000", help="element counts, one row each")
parser.add_argument("--frames", type=int, default=101)
parser.add_argument("--resolution", type=int, default=48)
parser.add_argument("--repeats", type=int, default=3)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

flow, dt = shear_layer(AnalyticFlow, args.resolution)
folder = tempfile.mkdtemp(prefix="bp-bench-state-")


def points(tracer):
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    data = servermanager.Fetch(tracer)
    return vtk_to_numpy(data.GetPoints().GetData()).copy() if data.GetPoints() else None


def steps_of(tracer):
    tracer.UpdatePropertyInformation()
    return int(tracer.GetPropertyValue("StepsInLastUpdate"))


def timed(action):
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def measure(elements, path):
    """One round: (save s, state MiB, resume s, resume steps, straight s,
    straight steps, same bits)."""
    # CheckpointMemory 0: the resumed and the straight trace pay for no copies.
    saver = strip16_tracer(BoundParticleTracer, flow, dt, elements, args.frames, CheckpointMemory=0)
    times = list(saver.TimestepValues)
    middle, last = times[len(times) // 2], times[-1]
    saver.UpdatePipeline(middle)
    save = timed(lambda: SaveData(path, proxy=OutputPort(saver, 2)))
    Delete(saver)
    resumed = strip16_tracer(BoundParticleTracer, flow, dt, elements, args.frames,
                             CheckpointMemory=0, InitialStateFile=path)
    resume = timed(lambda: resumed.UpdatePipeline(last))
    resume_steps = steps_of(resumed)
    straight = strip16_tracer(BoundParticleTracer, flow, dt, elements, args.frames,
                              CheckpointMemory=0)
    whole = timed(lambda: straight.UpdatePipeline(last))
    whole_steps = steps_of(straight)
    a, b = points(resumed), points(straight)
    same = a is not None and b is not None and a.shape == b.shape and a.tobytes() == b.tobytes()
    Delete(resumed)
    Delete(straight)
    return save, os.path.getsize(path) / 1048576.0, resume, resume_steps, whole, whole_steps, same


rows = []
for elements in [int(n) for n in args.elements.split(",")]:
    path = os.path.join(folder, "state_%d.vtp" % elements)
    rounds = [measure(elements, path) for _ in range(args.repeats)]
    median = [statistics.median(r[k] for r in rounds) for k in (0, 1, 2, 4)]
    rows.append((elements, median, rounds[0][3], rounds[0][5], all(r[6] for r in rounds)))
    os.remove(path)
os.rmdir(folder)

print("Save at the middle frame, resume to the last, against a straight trace to the last: "
      "Strip16 on the %d^3 shear layer, %d frames (one step each); seconds, medians of %d"
      % (args.resolution, args.frames, args.repeats))
print("| elements | state file (MiB) | save (SaveData) | resume to the last frame | its steps "
      "| straight trace | its steps | resume / straight | same bits |")
print("|---|---|---|---|---|---|---|---|---|")
for elements, (save, size, resume, whole), resume_steps, whole_steps, same in rows:
    print("| %d | %.1f | %.3f | %.3f | %d | %.3f | %d | %.2f | %s |" % (
        elements, size, save, resume, resume_steps, whole, whole_steps, resume / whole,
        "yes" if same else "NO"))
