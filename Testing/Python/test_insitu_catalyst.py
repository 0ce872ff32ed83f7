"""In situ through Catalyst (issue 42): an example simulation hands the
double gyre to Catalyst one step at a time, on one process or under MPI with
each process holding its piece; its analysis script traces and writes the
elements every N steps. The simulation is the Python one
(`paraview.catalyst.bridge`: pvpython, or pvbatch --symmetric under mpiexec)
or the C++ one (`--simulation`: Catalyst's vtkCPProcessor, under mpiexec for
several ranks). The elements at the last step equal a post hoc trace of the
same steps, written to disk by the simulation and read back, matched by
ElementId and ParticleIndex within 1e-4 of the domain; no message is said on
the way. With `--engine GPU` (one process) the Bound Particles display traces
in the Catalyst render view: its last picture equals the picture of a post
hoc trace of the same steps drawn by the GPU engine in a view set up alike.

With the CPU engine the run also writes a checkpoint at step 30 (the
solver's and the trace's state), and the simulation restarted from it goes
on to the same last elements, bit for bit (issue 57: save and resume).
"""
import ast
import os

import numpy
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--pvpython", "--pvbatch", "--example", "--simulation", "--script",
                        "--steps", "--ranks", "--mpiexec", "--engine")
engine = args.engine or "CPU"
steps = int(args.steps or 50)
ranks = int(args.ranks or 1)
work = bptest.scratch("bp-insitu-")
RESTART = 30  # the checkpoint a restarted run goes on from
options = ["--plugin", args.plugin, "--steps", str(steps), "--every", "10", "--engine", engine]
mpiexec = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)] if ranks > 1 else []
# ParaView's own notes: the bridge initializes ParaView, 5.11's Catalyst
# hands its producer the first step twice, and 6.1 with no X display tries X
# before it renders the picture through EGL.
THEIRS = ("initialized before", "New time step is not", "bad X server connection")


def simulate(more):
    """Runs the example simulation with `more` options; checks it ran and said nothing."""
    if args.simulation:
        command = mpiexec + [args.simulation, "--script", args.script] + options + more
    elif ranks > 1:
        command = mpiexec + [args.pvbatch, "--symmetric", args.example] + options + more
    else:
        command = [args.pvpython, args.example] + options + more
    print("running", " ".join(command), flush=True)
    process = bptest.run_group(command, 400, stderr_apart=True)
    stdout, stderr = process.stdout, process.stderr
    print(stdout[-3000:], stderr[-3000:])
    bptest.check(process.returncode == 0, "the simulation ran (%d)" % process.returncode)
    said = [line for line in (stdout + stderr).splitlines() if "WARN" in line or "ERR" in line]
    said = [line for line in said if not any(note in line for note in THEIRS)]
    bptest.check(not said, "nothing said while tracing in situ: %s" % said)


simulate(["--out", os.path.join(work, "out"), "--write-steps", os.path.join(work, "steps"),
          "--checkpoint-every", str(RESTART)])



def analysis_script():
    """SETTINGS, CAMERA and SPEEDS as the example's analysis script sets them."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "insitu",
                        "trace_elements.py")
    with open(path) as text:
        tree = ast.parse(text.read())
    return {node.targets[0].id: ast.literal_eval(node.value) for node in tree.body
            if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Name)
            and node.targets[0].id in ("SETTINGS", "CAMERA", "SPEEDS")}


from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

LoadPlugin(args.plugin, ns=globals())


def by_particle(data):
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
    index = vtk_to_numpy(data.GetPointData().GetArray("ParticleIndex"))
    points = vtk_to_numpy(data.GetPoints().GetData())
    return {(int(e), int(p)): points[k] for k, (e, p) in enumerate(zip(ids, index))}


last = steps - 1
picture = os.path.join(work, "out", "elements_%04d.png" % last)
bptest.check(os.path.exists(picture), "a picture written")
flow = PVDReader(FileName=os.path.join(work, "steps", "flow.pvd"))
flow.UpdatePipeline()
times = list(flow.TimestepValues)
bptest.check(len(times) == steps, "the simulation wrote %d steps (%d)" % (steps, len(times)))
script = analysis_script()
posthoc = BoundParticleTracer(Input=flow, Engine=engine, **script["SETTINGS"])
view = CreateRenderView(ViewSize=[640, 360], OrientationAxesVisibility=0)
shown = Show(posthoc, view)
if engine == "GPU":
    shown.SetRepresentationType("Bound Particles")
ColorBy(shown, ("POINTS", "Speed"))
GetColorTransferFunction("Speed").RescaleTransferFunction(*script["SPEEDS"])
for t in times if engine == "GPU" else times[-1:]:
    view.ViewTime = t
    for key, value in script["CAMERA"].items():
        setattr(view, key, value)
    Render(view)
drawn = os.path.join(work, "posthoc.png")
SaveScreenshot(drawn, view)
Delete(view)  # before the process ends: GLX would fail to make it current then
del view
covered = bptest.covered_fraction(drawn)
print("the post hoc picture: %g covered" % covered)
bptest.check(covered > 0.02, "the post hoc picture shows elements (%g covered)" % covered)
shows = bptest.covered_fraction(picture)
bptest.check(shows > 0.02, "the in situ picture shows elements (%g covered)" % shows)
if engine == "GPU":
    # The elements live on the GPU: the pictures are what can be compared.
    mean, differing = bptest.image_difference(picture, drawn)
    print("GPU: in situ and post hoc pictures: %g of the pixels differ (mean %g)" % (differing, mean))
    bptest.check(differing <= 0.001, "the GPU engine's picture in situ is the post hoc one "
                 "(%g of the pixels differ)" % differing)
    bptest.finish()
# One process writes a .vtp, several a .pvtp over their pieces.
EXTENSION = "pvtp" if ranks > 1 else "vtp"


def elements_written(folder):
    """The elements the run into `folder` wrote at the last step."""
    reader = OpenDataFile(os.path.join(work, folder, "elements_%04d.%s" % (last, EXTENSION)))
    reader.UpdatePipeline()
    return by_particle(servermanager.Fetch(reader))


got = elements_written("out")
posthoc.UpdatePipeline(times[-1])
want = by_particle(servermanager.Fetch(posthoc))
bptest.check(len(got) > 0 and set(got) == set(want),
             "the same particles in situ and post hoc (%d, %d)" % (len(got), len(want)))
if set(got) == set(want) and got:
    gap = max(abs(got[key] - want[key]).max() for key in got)
    print("in situ and post hoc %g apart" % gap)
    bptest.check(gap <= 1e-4 * 2.0, "in situ equals post hoc at the last step (%g apart)" % gap)

# The simulation restarted from its checkpoint: the trace goes on from the
# state saved there, to the very bits of the run that never stopped.
state = os.path.join(work, "out", "state_%04d.%s" % (RESTART, EXTENSION))
bptest.check(os.path.exists(state), "the trace's state written with the checkpoint")
simulate(["--out", os.path.join(work, "restarted"), "--checkpoints", os.path.join(work, "out"),
          "--restart-from", str(RESTART)])


def arrays_written(folder):
    """Every point array (and the points) the run into `folder` wrote at the
    last step, by element and particle (under MPI each piece holds its
    elements in the order they reached it)."""
    reader = OpenDataFile(os.path.join(work, folder, "elements_%04d.%s" % (last, EXTENSION)))
    reader.UpdatePipeline()
    data = servermanager.Fetch(reader)
    arrays = {"points": vtk_to_numpy(data.GetPoints().GetData())}
    for i in range(data.GetPointData().GetNumberOfArrays()):
        array = data.GetPointData().GetArray(i)
        arrays[array.GetName()] = vtk_to_numpy(array)
    order = numpy.lexsort((arrays["ParticleIndex"], arrays["ElementId"]))
    return {name: values[order] for name, values in arrays.items()}


uninterrupted, restarted = arrays_written("out"), arrays_written("restarted")
bptest.check(len(uninterrupted["points"]) > 0 and restarted.keys() == uninterrupted.keys() and
             all(numpy.array_equal(restarted[k], uninterrupted[k]) for k in uninterrupted),
             "the restarted run's last elements are the uninterrupted run's, every array bit for "
             "bit (%s)" % sorted(uninterrupted))
bptest.finish()
