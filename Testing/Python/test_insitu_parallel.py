"""In situ under MPI (issue 42, items 2 and 5), each case a pvbatch --symmetric
job of 2 ranks, each rank handing a trivial producer (whole extent set, as
Catalyst's adaptor sets it) its own piece of the double gyre one step at a
time:

- "far": the gyre far from the origin (origin (1e6, -2e5, 3e3)), each rank
  its slab along x with no ghost layers, so the tracer gathers its blocks
  and ghost layers from the pieces; the elements the job writes at the last
  step (a .pvtp) equal a post hoc trace of the same steps (one process, the
  steps read from disk), matched by ElementId and ParticleIndex within 1e-4
  of the domain.
- "periodic": "far" with a drift of 0.5 along x added to the gyre (a
  Calculator after the producer, and after the reader post hoc) and
  Periodic along x: each rank gathers the whole x axis from both pieces, and
  the elements that cross the seam move to the rank that owns their new
  centres; in situ equals post hoc as above.
- "empty", "bare": rank 0 holds the whole grid, rank 1 no points (an empty
  image with the arrays, or a bare vtkImageData()): rank 1 gathers its
  block on rank 0's grid, and the elements equal post hoc as above.
- "gap": the pieces leave points of the whole extent uncovered;
- "arrays": one rank's piece holds a point array the other's does not;
- "grids": one rank's piece lies half a cell off the other's grid:
  every rank fails with the message that says so, outputs nothing, and the
  job ends (no rank waits forever) within the time limit.

Run as the driver; it runs itself under mpiexec with `--case NAME,...`: the
cases share one job (an mpiexec and two pvbatch start-ups cost seconds), in
order, each within its own time limit; a case that ends or hangs the job
fails by name, and the cases after it go on in a new job.
"""
import os
import shutil
import signal
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--case", "--cases", "--pvbatch", "--mpiexec", "--work")

from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from insitu_feed import by_particle, farthest, feed  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
RANKS = 2
TIME_LIMIT = 120
STEPS = 12
DIMS = (48, 24, 2)
ORIGIN = (1.0e6, -2.0e5, 3.0e3)
SPACING = (2.0 / (DIMS[0] - 1), 1.0 / (DIMS[1] - 1), 0.05)
DOMAIN = 2.0
SETTINGS = dict(Vectors=["POINTS", "velocity"], ElementShape="Paddlewheel", NumberOfElements=150,
                Seed=3, Engine="CPU", LifetimeRange=[2.0, 4.0])
LAST_X = DIMS[0] - 1
# Each case's pieces of the point extent along x, by rank (y and z whole),
# and what the case does to rank 1's piece.
PIECES = {
    "far": [(0, 23), (23, LAST_X)],      # sharing one plane of points, no ghost layers
    "periodic": [(0, 23), (23, LAST_X)],  # as far, Periodic along x
    "empty": [(0, LAST_X), None],        # rank 1 holds no points (its arrays, empty)
    "bare": [(0, LAST_X), None],         # rank 1 holds a bare vtkImageData()
    "gap": [(0, 20), (30, LAST_X)],      # points 21 to 29 nobody's
    "arrays": [(0, 23), (23, LAST_X)],   # rank 1 holds one more array
    "grids": [(0, 23), (23, LAST_X)],    # rank 1's piece moved by half a cell
}
TRACED = ("far", "periodic", "empty", "bare")
DEFAULT_CASES = list(PIECES)
MESSAGES = {"gap": "do not cover the extent", "arrays": "hold different point arrays",
            "grids": "lie on different grids"}


def rank1_piece(name, data):
    """Rank 1's piece of a step as case `name` hands it over."""
    from vtkmodules.vtkCommonCore import vtkFloatArray
    from vtkmodules.vtkCommonDataModel import vtkImageData
    if name == "bare":
        return vtkImageData()
    if name == "empty":
        empty = vtkImageData()
        for a in range(data.GetPointData().GetNumberOfArrays()):
            array = data.GetPointData().GetArray(a)
            copy = array.NewInstance()
            copy.SetName(array.GetName())
            copy.SetNumberOfComponents(array.GetNumberOfComponents())
            empty.GetPointData().AddArray(copy)
        return empty
    if name == "arrays":
        extra = vtkFloatArray()
        extra.SetName("pressure")
        extra.SetNumberOfTuples(data.GetNumberOfPoints())
        extra.Fill(1.0)
        data.GetPointData().AddArray(extra)
    if name == "grids":
        data.SetOrigin(ORIGIN[0] + 0.5 * SPACING[0], ORIGIN[1], ORIGIN[2])
    return data


def traced(name, source):
    """The tracer of case `name` on `source` (the producer in situ, the
    reader post hoc): for "periodic" the gyre drifting along x, periodic
    there (the gyre alone never crosses its sides)."""
    if name != "periodic":
        return BoundParticleTracer(Input=source, **SETTINGS)
    drifting = Calculator(Input=source, ResultArrayName="drifting",
                          Function="velocity + 0.5*iHat")
    return BoundParticleTracer(Input=drifting, **dict(SETTINGS, Vectors=["POINTS", "drifting"]),
                               Periodic=[1, 0, 0])


def step_file(work, k):
    return os.path.join(work, "flow_%04d.vti" % k)


def write_steps(work):
    """The steps as whole grids and a .pvd over them (the post hoc input)."""
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
    from vtkmodules.vtkImagingCore import vtkImageChangeInformation
    flow = AnalyticFlow(Flow="Double Gyre", Resolution=list(DIMS), Bounds=[0, 2, 0, 1, 0, 0.05],
                        NumberOfTimeSteps=STEPS)
    flow.UpdatePipeline()
    times = list(flow.TimestepValues)
    with open(os.path.join(work, "flow.pvd"), "w") as pvd:
        pvd.write('<VTKFile type="Collection" version="0.1"><Collection>\n')
        for k, t in enumerate(times):
            flow.UpdatePipeline(t)
            moved = vtkImageChangeInformation()
            moved.SetInputData(flow.GetClientSideObject().GetOutputDataObject(0))
            moved.SetOutputOrigin(*ORIGIN)
            moved.SetOutputSpacing(*SPACING)
            writer = vtkXMLImageDataWriter()
            writer.SetInputConnection(moved.GetOutputPort())
            writer.SetFileName(step_file(work, k))
            writer.Write()
            pvd.write('<DataSet timestep="%.17g" file="%s"/>\n'
                      % (t, os.path.basename(step_file(work, k))))
        pvd.write("</Collection></VTKFile>\n")
    return times


def run_case(name):
    """On every rank: hands this rank's piece of each step to the tracer;
    writes its points and whether it said the case's message."""
    from vtkmodules.vtkImagingCore import vtkExtractVOI
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    controller = vtkMultiProcessController.GetGlobalController()
    rank = controller.GetLocalProcessId()
    first, last = PIECES[name][rank] or PIECES[name][0]
    whole = [0, LAST_X, 0, DIMS[1] - 1, 0, DIMS[2] - 1]
    with open(os.path.join(args.work, "flow.pvd")) as pvd:
        times = [float(line.split('"')[1]) for line in pvd if "timestep=" in line]
    producer = PVTrivialProducer()
    producer.GetClientSideObject().SetWholeExtent(whole)
    tracer = traced(name, producer)
    points = 0
    started = time.time()
    with bptest.CapturedMessages() as said:
        for k, t in enumerate(times):
            reader = vtkXMLImageDataReader()
            reader.SetFileName(step_file(args.work, k))
            piece = vtkExtractVOI()
            piece.SetInputConnection(reader.GetOutputPort())
            piece.SetVOI(first, last, *whole[2:])
            piece.Update()
            data = piece.GetOutput().NewInstance()
            data.DeepCopy(piece.GetOutput())
            if rank == 1:
                data = rank1_piece(name, data)
            feed(producer, data, t)
            tracer.UpdatePipeline(t)
            points = tracer.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()
        if name in TRACED:
            SaveData(os.path.join(args.work, "elements_%s.pvtp" % name), proxy=tracer)
    wanted = MESSAGES.get(name)
    # In a file of its own: the ranks' printed lines can interleave.
    with open(os.path.join(args.work, "result_%s_%d.txt" % (name, rank)), "w") as result:
        result.write("%d %d %.2f %s" % (points, int(bool(wanted) and said.mentions(wanted)),
                                        time.time() - started,
                                        " | ".join(said.messages)[:300].replace("\n", " ")))


def read_results(name, work):
    """(points, said the message, seconds, messages) by rank, for the ranks
    that finished case `name`."""
    results = {}
    for rank in range(RANKS):
        path = os.path.join(work, "result_%s_%d.txt" % (name, rank))
        if os.path.exists(path):
            with open(path) as result:
                parts = result.read().split(" ", 3)
            results[rank] = (int(parts[0]), parts[1] == "1", float(parts[2]),
                             parts[3] if len(parts) > 3 else "")
    return results


def run_job(names, work):
    """Runs the cases in one job, in order, until one ends it; checks how each
    ended and returns their results by name (those it got to)."""
    command = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", str(RANKS),
               args.pvbatch, "--symmetric", os.path.abspath(__file__), "--plugin", args.plugin,
               "--case", ",".join(names), "--work", work]
    process = bptest.run_group(command, TIME_LIMIT * len(names) + 60)
    out = process.stdout
    done = {}
    for name in names:
        results = read_results(name, work)
        complete = sorted(results) == list(range(RANKS))
        last = name == names[-1]
        # The job's status is the case's that ended it (or the last case's).
        status = process.returncode if not complete or last else 0
        seconds = max([r[2] for r in results.values()] if complete else [process.seconds])
        print("%s: exit %s, %.1f s, %s" % (name, status, seconds,
                                           {k: v[:2] + v[3:] for k, v in results.items()}))
        bptest.check(seconds < TIME_LIMIT, "%s: ran past %d s (a hang)\n%s"
                     % (name, TIME_LIMIT, out[-2000:]))
        bptest.check(status == 0 and complete, "%s: exited with %s, results from ranks %s\n%s"
                     % (name, status, sorted(results), out[-2000:]))
        done[name] = {rank: r[:2] + r[3:] for rank, r in results.items()}
        if not complete:
            break
    return done


def compare(name, work, times):
    insitu = OpenDataFile(os.path.join(work, "elements_%s.pvtp" % name))
    insitu.UpdatePipeline()
    got = by_particle(servermanager.Fetch(insitu))
    flow = PVDReader(FileName=os.path.join(work, "flow.pvd"))
    flow.UpdatePipeline()
    posthoc = traced(name, flow)
    posthoc.UpdatePipeline(times[-1])
    want = by_particle(servermanager.Fetch(posthoc))
    gap = farthest(got, want)
    centre = [sum(p[a] for p in want.values()) / max(1, len(want)) for a in range(3)]
    print("%s: %d particles in situ, %d post hoc (around %s), %g apart"
          % (name, len(got), len(want), centre, gap))
    bptest.check(abs(centre[0] - ORIGIN[0] - 1.0) < 1.0 and abs(centre[1] - ORIGIN[1] - 0.5) < 0.5,
                 "%s: the post hoc elements are in the moved field (around %s)" % (name, centre))
    bptest.check(gap <= 1e-4 * DOMAIN, "%s, far from the origin under %d ranks: in situ equals "
                 "post hoc (%d and %d particles, %g apart)" % (name, RANKS, len(got), len(want),
                                                               gap))


def drive():
    work = tempfile.mkdtemp(prefix="bp-insitu-parallel-")
    times = write_steps(work)
    names = args.cases.split(",") if args.cases else DEFAULT_CASES
    outcomes = {}
    while len(outcomes) < len(names):
        outcomes.update(run_job([name for name in names if name not in outcomes], work))
    for name in names:
        results = outcomes[name]
        if name in TRACED:
            if len(results) == RANKS:
                bptest.check(sum(points for points, _, _ in results.values()) > 0,
                             "%s: the ranks traced (%s)" % (name, results))
                bptest.check(not any(m for _, _, m in results.values()),
                             "%s: nothing said on any rank (%s)" % (name, results))
                compare(name, work, times)
            continue
        for rank in range(RANKS):
            points, said, messages = results.get(rank, (None, False, ""))
            bptest.check(points == 0 and said, "%s: rank %d fails with '%s' and outputs nothing "
                         "(%s points; said: %s)" % (name, rank, MESSAGES[name], points,
                                                    messages or "nothing"))
    shutil.rmtree(work, ignore_errors=True)
    bptest.finish()


if args.case:
    for case_name in args.case.split(","):
        # Past the time limit the default action of SIGALRM ends the rank,
        # and mpiexec the job: the driver reports the case without results.
        signal.alarm(TIME_LIMIT)
        run_case(case_name)
    # The job's end (every rank leaves) within the time limit too.
    signal.alarm(TIME_LIMIT)
    # pvbatch ends with status 1 on sys.exit(), so fall through
else:
    drive()
