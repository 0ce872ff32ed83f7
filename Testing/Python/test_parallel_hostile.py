"""Hostile input under MPI never hangs: each case runs under pvbatch with 2 and
4 ranks within a time limit, and must end on every rank (mpiexec returns only
then) with exit status 0, printing its result from rank 0. A case where one
process's input differs from the others' (data on rank 0 only) must not leave
the others waiting in a collective step: it traces, or every rank fails with
the message (issue 27, items 2 and 11). Neither may a rank whose piece of a
mesh is empty (a serial file read by every rank), alone or among the newest
features in one script (issue 38, item 8). Periodic traces on several ranks,
on an image and on a serial mesh, and warns of a seam whose planes differ
(issue 58, item 5).

Run as the driver; it runs itself under pvbatch with `--case NAME...`. The
cases share one MPI job per rank count (an mpiexec and pvbatch start-up costs
seconds each), in order: before each case every rank logs a marker, so the
messages each rank logs are the case's that its last marker names. A case
that kills or hangs the job (each case has its own time limit) fails by name,
and the cases after it go on in a new job.
"""
import argparse
import builtins
import os
import re
import shutil
import signal
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--case", nargs="+")
parser.add_argument("--pvbatch", default="pvbatch")
parser.add_argument("--mpiexec", default="mpiexec")
parser.add_argument("--meshes", help="(set by the driver) the folder of the tetrahedral meshes")
args = parser.parse_args()

TIME_LIMIT = 90


def rank0_points(script):
    """A PVTrivialProducer whose polydata (points made by `script` from numpy,
    assigning xyz) is filled on rank 0 only: the other ranks have no data."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    import numpy  # noqa: F401
    producer = PVTrivialProducer()
    data = vtkPolyData()
    scope = {"numpy": numpy}
    exec(script, scope)
    points = vtkPoints()
    for x in scope["xyz"]:
        points.InsertNextPoint(*x)
    data.SetPoints(points)
    producer.GetClientSideObject().SetOutput(data)
    return producer


def rank0_table():
    from vtkmodules.vtkCommonCore import vtkFloatArray
    from vtkmodules.vtkCommonDataModel import vtkTable
    producer = PVTrivialProducer()
    table = vtkTable()
    column = vtkFloatArray()
    column.SetName("x")
    column.InsertNextValue(1.0)
    table.AddColumn(column)
    producer.GetClientSideObject().SetOutput(table)
    return producer


def flow(**properties):
    properties.setdefault("Resolution", [24, 24, 24])
    source = AnalyticFlow(**properties)
    source.UpdatePipeline()
    return source


def tracer(input_proxy, **properties):
    properties.setdefault("NumberOfElements", 200)
    return BoundParticleTracer(Input=input_proxy, Vectors=["POINTS", "velocity"], **properties)


def spiked_flow():
    """An ABC flow with one vector of 1e30 in the last rank's block only: that
    rank alone finds its piece unusable."""
    f = ProgrammableFilter(Input=flow(), OutputDataSetType="vtkImageData")
    f.Script = ("from vtkmodules.vtkParallelCore import vtkMultiProcessController\n"
                "out = self.GetOutput(); out.DeepCopy(self.GetInput())\n"
                "c = vtkMultiProcessController.GetGlobalController()\n"
                "if c and c.GetLocalProcessId() == c.GetNumberOfProcesses() - 1:\n"
                "    out.GetPointData().GetArray('velocity').SetTuple3(0, 1e30, 0, 0)\n")
    return f


def write_meshes(folder):
    """A tetrahedral mesh of a smooth flow (`velocity`, and the wavelet's
    `RTData`) as one serial .vtu, which every rank reads and only rank 0 gets
    cells from, and as a .pvtu of 4 pieces."""
    from vtkmodules.vtkFiltersCore import vtkArrayCalculator
    from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
    from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
    from vtkmodules.vtkIOParallelXML import vtkXMLPUnstructuredGridWriter
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(0, 12, 0, 12, 0, 12)
    flow = vtkArrayCalculator()
    flow.SetInputConnection(wavelet.GetOutputPort())
    for a, name in enumerate("xyz"):
        flow.AddCoordinateScalarVariable(name, a)
    flow.SetFunction("sin(z/4)*iHat + cos(x/4)*jHat + (sin(y/4)+0.3)*kHat")
    flow.SetResultArrayName("velocity")
    tets = vtkDataSetTriangleFilter()
    tets.SetInputConnection(flow.GetOutputPort())
    serial = vtkXMLUnstructuredGridWriter()
    serial.SetInputConnection(tets.GetOutputPort())
    serial.SetFileName(os.path.join(folder, "tets.vtu"))
    serial.Write()
    pieces = vtkXMLPUnstructuredGridWriter()
    pieces.SetInputConnection(tets.GetOutputPort())
    pieces.SetFileName(os.path.join(folder, "tets.pvtu"))
    pieces.SetNumberOfPieces(4)
    pieces.SetStartPiece(0)
    pieces.SetEndPiece(3)
    pieces.Write()


def serial_mesh_weighted_by_vectors():
    """The serial .vtu, traced as a script does it without updating the
    reader first (so Vectors is left unnamed and the tracer picks the array),
    weighted by the vectors themselves: rank 0 picked `velocity` and ranks
    with no cells picked nothing, so only they interpolated the weights apart
    and waited in a collective rank 0 never joined (issue 38, item 8)."""
    reader = XMLUnstructuredGridReader(FileName=[os.path.join(args.meshes, "tets.vtu")])
    return BoundParticleTracer(Input=reader, NumberOfElements=200,
                               ReleaseWeights=["POINTS", "velocity"])


def newest_features_together():
    """Issue 38, item 8's script: a serial mesh (Vectors unnamed, weighted by
    the vectors), the same mesh in 4 pieces, Release Weights on an image, a
    lattice with its FTLE map, anchored paddlewheels and a Point Cloud, each
    output fetched. Returns the outputs as (proxy, port)."""
    pieces = XMLPartitionedUnstructuredGridReader(
        FileName=[os.path.join(args.meshes, "tets.pvtu")])
    weighted = Calculator(Input=flow(), ResultArrayName="w", Function="coordsX+1")
    lattice = tracer(flow(), ReleasePattern="Lattice")
    cloud = tracer(flow(), SeedType="Point Cloud")
    cloud.SeedType.NumberOfPoints = 100
    return [(serial_mesh_weighted_by_vectors(), 0),
            (tracer(pieces, ResampleDimensions=[16, 16, 16]), 0),
            (tracer(weighted, ReleaseWeights=["POINTS", "w"]), 0),
            (lattice, 0), (lattice, 1),
            (tracer(flow(), ElementShape="Paddlewheel", Anchor="Centre"), 0),
            (cloud, 0)]


# name: (what to build (a proxy, or a list of (proxy, output port)), time,
# whether it must trace something (every output, for a list), what a
# refusal or warning must say)
CASES = {
    "seeds on rank 0 only": (lambda: tracer(flow(Flow="ABC"), SeedSource=rank0_points(
        "xyz = [(-0.5 + 0.05 * i, 0.1, 0.2) for i in range(20)]")), 0.5, True, None),
    "unsteady input, seeds on rank 0 only": (lambda: tracer(flow(Flow="Double Gyre"),
                                                            SeedSource=rank0_points(
        "xyz = [(-0.5 + 0.05 * i, 0.1, 0.0) for i in range(20)]")), 0.5, True, None),
    "a table on rank 0 only as seeds": (lambda: tracer(flow(), SeedSource=rank0_table()), 0.5,
                                        False, "has no points"),
    "seeds outside the field on rank 0 only": (lambda: tracer(flow(), SeedSource=rank0_points(
        "xyz = [(5, 5, 5)]")), 0.5, False, "None of the Seed Source"),
    "a template on rank 0 only": (lambda: tracer(flow(), ElementTemplate=rank0_points(
        "xyz = [(0, 0, 0), (0.1, 0, 0)]")), 0.5, False, "Element Template"),
    "one rank's field unusable": (lambda: tracer(spiked_flow()), 0.5, False,
                                  "vector array holds values up to 1e+30"),
    "a 2x2x2 field": (lambda: tracer(flow(Resolution=[2, 2, 2])), 0.5, True, "too few cells"),
    "a field of 3 cells along x": (lambda: tracer(flow(Resolution=[4, 2, 2])), 0.5, True, None),
    "a serial mesh weighted by its unnamed vectors": (serial_mesh_weighted_by_vectors, 0.5, True,
                                                      None),
    "the newest features together": (newest_features_together, 0.5, True, None),
    # Seed Type Surface: the ranks weigh the surface's triangles together
    # (each samples what its piece holds) and agree on a refusal.
    "Surface across the pieces": (lambda: tracer(flow(Flow="ABC"), SeedType="Surface",
                                                 SeedSource=Plane(XResolution=10, YResolution=10)),
                                  0.5, True, None),
    "Surface the flow runs along": (lambda: tracer(flow(Flow="Solid Body Rotation"),
                                                   SeedType="Surface", SeedSource=Plane()),
                                    0.5, False, "No flow crosses"),
    # Periodic under MPI: every rank reads the whole periodic axis and hands
    # elements across the seam, along every axis of the ABC flow (whose
    # planes repeat); a serial mesh, resampled, whose other ranks hold no
    # cells, and whose seams differ: warned of after an agreement among the
    # ranks.
    "Periodic on several ranks": (lambda: tracer(flow(), Periodic=[1, 1, 0]), 0.5, True, None),
    "Periodic along every axis": (lambda: tracer(flow(Flow="ABC"), Periodic=[1, 1, 1]), 0.5,
                                  True, None),
    "Periodic on a serial mesh": (lambda: tracer(XMLUnstructuredGridReader(
        FileName=[os.path.join(args.meshes, "tets.vtu")]), Periodic=[1, 1, 0],
        ResampleDimensions=[13, 13, 13]), 0.5, True, "is not a copy of its first"),
}


MARKER = "bp-parallel-hostile case "


def mark(number):
    """Logs MARKER and the case's number on every rank (a programmable source
    runs on each), in the stream and format of the rank's own messages."""
    marker = ProgrammableSource(OutputDataSetType="vtkPolyData")
    marker.Script = ("from vtkmodules.vtkCommonCore import vtkLogger\n"
                     "vtkLogger.Log(vtkLogger.VERBOSITY_WARNING, 'marker', 0, '%s%d')\n" %
                     (MARKER, number))
    marker.UpdatePipeline()
    Delete(marker)


def run_case(number, name):
    from paraview import servermanager
    build, t = CASES[name][:2]
    started = time.time()
    built = build()
    outputs = built if isinstance(built, list) else [(built, 0)]
    counts = []
    for proxy, port in outputs:
        proxy.UpdatePipeline(t)
        data = servermanager.Fetch(proxy, idx=port)
        counts.append(data.GetNumberOfPoints() if data else 0)
    # The fewest: a list traces only if every output does. Python's own min:
    # paraview.simple's `*` brings numpy_interface's, a reduction over every
    # rank that rank 0 alone would enter here, and wait in.
    print("RESULT %d %d %.2f" % (number, builtins.min(counts), time.time() - started), flush=True)


if args.case:
    # The builders above name paraview.simple's functions and the plugin's proxies.
    from paraview.simple import *  # noqa: F401,F403
    LoadPlugin(args.plugin, ns=globals())
    # Not `number`: paraview.simple refills this module's names (numpy's among them).
    for case_number, case_name in enumerate(args.case):
        # Past the time limit the default action of SIGALRM ends rank 0, and
        # mpiexec the job: the driver reports the case without a result.
        signal.alarm(TIME_LIMIT)
        mark(case_number)
        print("case: " + case_name, flush=True)
        run_case(case_number, case_name)
    # The job's end (every rank leaves) within the time limit too.
    signal.alarm(TIME_LIMIT)
    # pvbatch ends with status 1 on sys.exit(), so fall through


# A rank's log line: "(   1.8s) [pvbatch.1       ] file:line   ERR| ...": the
# bracket names the rank (its logger thread).
LOG_LINE = re.compile(r"\(\s*[0-9.]+s\) \[([^\]]*)\]")


def run_job(names, ranks, meshes):
    """Runs the cases in one MPI job of `ranks` ranks, in order, until one ends
    it. A list of (name, exit status or None, seconds, points or None,
    messages, output) for the cases it got to: those with a result ran to
    their end; the first without one ended or hung the job."""
    command = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks),
               args.pvbatch, os.path.abspath(__file__), "--plugin", args.plugin,
               "--meshes", meshes, "--case"] + names
    # Apart: pvbatch prints a line's text and its newline separately, and a
    # log line could fall between them.
    process = bptest.run_group(command, TIME_LIMIT * len(names) + 60, stderr_apart=True)
    out = process.stdout + "\n" + process.stderr
    results = {int(m.group(1)): (int(m.group(2)), float(m.group(3)))
               for m in re.finditer(r"^RESULT (\d+) (\d+) ([0-9.]+)$", process.stdout, re.M)}
    messages, case_of = {}, {}
    for line in process.stderr.splitlines():
        tag = LOG_LINE.search(line)
        rank = tag.group(1).strip() if tag else None
        marker = re.search(MARKER + r"(\d+)", line)
        if marker:
            case_of[rank] = int(marker.group(1))
        elif "ERR|" in line or "WARN|" in line:
            # A rank's message belongs to the case its last marker named.
            number = case_of.get(rank, builtins.max(case_of.values(), default=0))
            messages.setdefault(number, []).append(line[line.find("vtkBoundParticleTracer"):][:400])
    ran = []
    for number, name in enumerate(names):
        if number in results:
            points, seconds = results[number]
            ran.append((name, 0, seconds, points, messages.get(number, []), ""))
            continue
        status = process.returncode if process.returncode != 0 else None
        ran.append((name, status, process.seconds, None, messages.get(number, []), out))
        break
    if len(ran) == len(names) and process.returncode != 0:
        # Every case ended, then the job failed: its last case is reported.
        ran[-1] = ran[-1][:1] + (process.returncode,) + ran[-1][2:5] + (out,)
    return ran


def drive():
    """Runs every case under 2 and 4 ranks and checks how each ended."""
    meshes = tempfile.mkdtemp(prefix="bp-parallel-hostile-")
    write_meshes(meshes)
    for ranks in (2, 4):
        results = {}
        left = list(CASES)
        while left:
            for row in run_job(left, ranks, meshes):
                results[row[0]] = row[1:]
            left = [name for name in left if name not in results]
        for name, (_, _, traces, says) in CASES.items():
            status, seconds, points, messages, out = results[name]
            print("%-40s %d ranks: exit %s, %.1f s, %s" % (
                name, ranks, status, seconds, "no result" if points is None else
                "points %d" % points))
            for m in sorted(set(messages))[:3]:
                print("    " + m)
            if out:
                print(out[-3000:])
            bptest.check(seconds < TIME_LIMIT, "%s, %d ranks: ran past %d s (a hang)" % (
                name, ranks, TIME_LIMIT))
            bptest.check(status == 0 and points is not None, "%s, %d ranks: exited with %s%s" % (
                name, ranks, status, "" if points is not None else ", no result"))
            if points is not None:
                bptest.check((points > 0) == traces, "%s, %d ranks: %d points" % (
                    name, ranks, points))
            said = " | ".join(messages)
            bptest.check(not says or says in said, "%s, %d ranks: no message saying '%s' (%s)" % (
                name, ranks, says, said[:300] or "none"))
    shutil.rmtree(meshes, ignore_errors=True)
    bptest.finish()


if not args.case:
    drive()
