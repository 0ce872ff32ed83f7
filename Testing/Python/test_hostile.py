"""Hostile input never kills or hangs ParaView: a table of inputs a fuzzing run
found harmful, traced by pvpython under an 8 GiB address-space limit and a
time limit per case.

Each case must end with exit status 0 (no signal, no abort), within its time
limit, with finite output; a case the tracer must refuse must also say why,
naming the problem. Run as the driver (`--plugin P`); the driver runs itself
with `--case NAME ...`. The cases share processes, each case in a fresh
session, which saves a pvpython start-up per case: those in BIG (that ask for
more memory than the machine has) share one, those in DRAWN (that draw in a
view) another, and the rest a third. A case that kills or hangs its process
fails by name, and the cases after it go on in a new one, so a regression in
one case never takes the others with it.
"""
import argparse
import hashlib
import json
import math
import os
import resource
import signal
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--case", nargs="+")
parser.add_argument("--pvpython", default="pvpython")
parser.add_argument("--scratch", help="a folder for the cases' files")
args = parser.parse_args()

ADDRESS_LIMIT = 8 << 30


def result_file(scratch, name):
    """Where a case's process writes the case's result (json): a file, not
    the process's output, which ParaView's log shares and may cut."""
    return os.path.join(scratch, hashlib.sha1(name.encode()).hexdigest() + ".json")
TIME_LIMIT = 120


def times_source(times, speed=0.1):
    """A programmable image source with the given TIME_STEPS (in any order)."""
    source = ProgrammableSource(OutputDataSetType="vtkImageData")
    source.ScriptRequestInformation = (
        "from paraview import util\n"
        "util.SetOutputWholeExtent(self, [0, 8, 0, 8, 0, 8])\n"
        "info = self.GetOutputInformation(0)\n"
        "from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as S\n"
        "info.Set(S.TIME_STEPS(), %r, %d)\n" % (list(times), len(times)))
    source.Script = (
        "import numpy\n"
        "out = self.GetOutput()\n"
        "out.SetExtent(0, 8, 0, 8, 0, 8)\n"
        "out.SetSpacing(0.1, 0.1, 0.1)\n"
        "from vtkmodules.util.numpy_support import numpy_to_vtk\n"
        "v = numpy_to_vtk(numpy.tile([%r, 0.5 * %r, 0.0], (729, 1)), deep=True)\n"
        "v.SetName('v')\n"
        "out.GetPointData().AddArray(v)\n" % (speed, speed))
    return source


def scaled_flow(factor):
    """An ABC flow whose velocity is multiplied by `factor` (wrong byte order, units)."""
    return Calculator(Input=AnalyticFlow(Flow="ABC", Resolution=[16, 16, 16]),
                      Function="velocity*%r" % factor, ResultArrayName="v")


def int64_flow():
    """An ABC flow's velocity as int64 values of 2^62."""
    return masked_flow(
        "a = numpy_to_vtk(numpy.full((n, 3), 2**62, dtype=numpy.int64), deep=True)\n"
        "a.SetName('v'); out.GetPointData().AddArray(a)", resolution=12)


def wrapped_template():
    """A triangle whose second point id is 2^32 + 1 (it used to wrap to 1)."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "from vtkmodules.vtkCommonCore import vtkPoints\n"
        "from vtkmodules.vtkCommonDataModel import vtkCellArray\n"
        "p = vtkPoints()\n"
        "for x in ((0, 0, 0), (1, 0, 0), (0, 1, 0)): p.InsertNextPoint(x)\n"
        "c = vtkCellArray(); c.InsertNextCell(3)\n"
        "for i in (0, 2**32 + 1, 2): c.InsertCellPoint(i)\n"
        "out = self.GetOutput(); out.SetPoints(p); out.SetPolys(c)\n")
    return source


def polygon(sides):
    """A regular polygon as one cell: fanned, its first corner has a spring to every other."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "from vtkmodules.vtkFiltersSources import vtkRegularPolygonSource\n"
        "p = vtkRegularPolygonSource(); p.SetNumberOfSides(%d); p.GeneratePolylineOff()\n"
        "p.Update(); self.GetOutput().ShallowCopy(p.GetOutput())\n" % sides)
    return source


def masked_flow(mask_script, resolution=16):
    """An ABC flow changed by `mask_script`: it sees the output image `out`,
    its point count n and coordinates xyz (numpy, n x 3), and assigns `mask`
    to add it as vtkValidPointMask, or changes `out` itself."""
    f = ProgrammableFilter(Input=AnalyticFlow(Flow="ABC", Resolution=[resolution] * 3),
                           OutputDataSetType="vtkImageData")
    f.Script = ("import numpy\n"
                "from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy\n"
                "out = self.GetOutput(); out.ShallowCopy(self.GetInput())\n"
                "n = out.GetNumberOfPoints()\n"
                "xyz = numpy.array([out.GetPoint(i) for i in range(n)])\n"
                "mask = None\n" + mask_script + "\n"
                "if mask is not None:\n"
                "    a = numpy_to_vtk(numpy.ascontiguousarray(mask), deep=True)\n"
                "    a.SetName('vtkValidPointMask')\n"
                "    out.GetPointData().AddArray(a)\n")
    return f


def string_mask_flow():
    """A vtkValidPointMask of strings."""
    return masked_flow(
        "from vtkmodules.vtkCommonCore import vtkStringArray\n"
        "s = vtkStringArray(); s.SetName('vtkValidPointMask')\n"
        "for i in range(n): s.InsertNextValue('1')\n"
        "out.GetPointData().AddArray(s)")


def cell_mask_flow():
    """A vtkValidPointMask given as cell data."""
    return masked_flow(
        "c = numpy_to_vtk(numpy.ones(out.GetNumberOfCells(), dtype=numpy.uint8), deep=True)\n"
        "c.SetName('vtkValidPointMask'); out.GetCellData().AddArray(c)")


def table_source():
    """A table: data with no points."""
    source = ProgrammableSource(OutputDataSetType="vtkTable")
    source.Script = ("from vtkmodules.vtkCommonCore import vtkFloatArray\n"
                     "a = vtkFloatArray(); a.SetName('x'); a.InsertNextValue(1.0)\n"
                     "self.GetOutput().AddColumn(a)\n")
    return source


def empty_mesh():
    """An unstructured grid with nothing in it."""
    return ProgrammableSource(OutputDataSetType="vtkUnstructuredGrid", Script="pass")


def vertex_cloud():
    """Points with vectors and vertex cells, no surface or volume."""
    return Calculator(Input=PointSource(NumberOfPoints=50, Radius=1.0), Function="iHat",
                      ResultArrayName="v")


def half_nan_mesh():
    """Tetrahedra whose vectors are NaN where x > 0.3: those count as outside."""
    return PythonCalculator(
        Input=Tetrahedralize(Input=flow()), ArrayName="velocity",
        Expression="numpy.where(points[:, 0:1] > 0.3, numpy.nan, 1.0) * "
                   "inputs[0].PointData['velocity']")


def two_lines():
    return GroupDatasets(Input=[Line(Point1=[-0.5, -0.5, 0], Point2=[0.5, -0.5, 0]),
                                Line(Point1=[-0.5, 0.5, 0], Point2=[0.5, 0.5, 0])])


def overflowing_bpvol():
    """A .bpvol whose dimensions multiply to 2^64 points, with an empty data file."""
    folder = args.scratch or bptest.scratch("bp-hostile-")
    with open(os.path.join(folder, "empty.raw"), "wb"):
        pass
    path = os.path.join(folder, "overflow.bpvol")
    with open(path, "w") as f:
        json.dump({"dimensions": [2097152, 2097152, 4194304], "scalar_type": "float32",
                   "byte_order": "little", "files": ["empty.raw"]}, f)
    return OpenDataFile(path)


def tracer(input_proxy, **properties):
    properties.setdefault("NumberOfElements", 200)
    return BoundParticleTracer(Input=input_proxy, **properties)


def flow(**properties):
    properties.setdefault("Resolution", [16, 16, 16])
    return AnalyticFlow(**properties)


def seeded(kind, **seed_properties):
    """A tracer on the default flow releasing from Seed Type `kind`, its
    parameters set as a script or a state file could."""
    made = tracer(flow(), SeedType=kind)
    for name, value in seed_properties.items():
        setattr(made.SeedType, name, value)
    return made


def surface(source, **flow_properties):  # Seed Type Surface over `source`
    return tracer(flow(**flow_properties), SeedType="Surface", SeedSource=source)


def NONE(r):  # a case's check: nothing released
    return r["points"] == 0


def nan_plane(where):
    """A Plane whose points are NaN where `where` (of x) holds."""
    return ProgrammableFilter(Input=Plane(XResolution=4, YResolution=4), Script=(
        "import numpy\nfrom vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy\n"
        "out = self.GetOutput()\nout.DeepCopy(self.GetInput())\np = vtk_to_numpy(out.GetPoints()"
        ".GetData()).astype(float)\nx = p[:, 0]\np[numpy.asarray(%s) & (x == x), :] = numpy.nan\n"
        "out.GetPoints().SetData(numpy_to_vtk(p, deep=True))\n" % where))


def reloaded(made, edits=None):
    """The tracer `made` saved in a state file (its values replaced by the
    texts in `edits`, by property name), the session reset and the file
    loaded again, as a user reopens a saved state."""
    import re
    path = os.path.join(args.scratch, "state-%d.pvsm" % os.getpid())
    SaveState(path)  # noqa: F405
    with open(path) as f:
        text = f.read()
    for name, value in (edits or {}).items():
        text = re.sub(r'(name="%s"[^>]*>\s*<Element index="0" value=")[^"]*(")' % name,
                      r"\g<1>%s\g<2>" % value, text)
    with open(path, "w") as f:
        f.write(text)
    ResetSession()  # noqa: F405
    LoadPlugin(args.plugin, ns=globals())  # noqa: F405
    LoadState(path)  # noqa: F405
    return [s for s in GetSources().values()  # noqa: F405
            if s.GetXMLName() == "BoundParticleTracer"][0]


def gpu_display(template_points):
    """The Bound Particles display with the GPU engine and a sphere of about
    `template_points` points as the element."""
    phi = int(math.sqrt(template_points / 2))
    sphere = Sphere(ThetaResolution=2 * phi, PhiResolution=phi)
    return tracer(flow(Flow="ABC"), NumberOfElements=10, Engine="GPU",
                  TemplateSprings="Edges", ElementTemplate=sphere), "Bound Particles"


# name: (what to build, time, the word a refusal must contain or None where the
# input is valid and must trace with finite output)
CASES = {
    "unsorted times": (lambda: tracer(times_source([0, 2, 1, 3]), Vectors=["POINTS", "v"]),
                       1.0, "out of order"),
    "duplicate times": (lambda: tracer(times_source([0, 1, 1, 2]), Vectors=["POINTS", "v"]),
                        1.0, "duplicate"),
    "NaN time": (lambda: tracer(times_source([0, float("nan"), 2]), Vectors=["POINTS", "v"]),
                 1.0, "finite"),
    "infinite time": (lambda: tracer(times_source([0, 1, float("inf")]),
                                     Vectors=["POINTS", "v"]), 1.0, "finite"),
    "infinite view time": (lambda: tracer(flow()), float("inf"), None),
    # Composite and mesh input is resampled (issue 28): overlapping blocks
    # trace, meshes that carry no flow are refused with a reason.
    "multiblock of unsteady images": (
        lambda: tracer(GroupDatasets(
            Input=[flow(Flow="Double Gyre"), flow(Flow="Double Gyre")])), 1.0, None,
        lambda r: r["points"] > 0),
    "multiblock of steady images": (
        lambda: tracer(GroupDatasets(Input=[flow(), flow()])), 1.0, None,
        lambda r: r["points"] > 0),
    "empty unstructured grid": (lambda: tracer(empty_mesh()), 1.0, "no cells",
                                lambda r: r["points"] == 0),
    "point cloud with vectors, no cells": (
        lambda: tracer(vertex_cloud(), Vectors=["POINTS", "v"]), 1.0, "points or lines",
        lambda r: r["points"] == 0),
    "lines with vectors": (
        lambda: tracer(Calculator(Input=Line(), Function="iHat", ResultArrayName="v"),
                       Vectors=["POINTS", "v"]), 1.0, "points or lines",
        lambda r: r["points"] == 0),
    "curved surface mesh": (
        lambda: tracer(Calculator(Input=Sphere(), Function="iHat", ResultArrayName="v"),
                       Vectors=["POINTS", "v"]), 1.0, "plane of constant",
        lambda r: r["points"] == 0),
    "mesh with NaN vectors in half": (
        lambda: tracer(half_nan_mesh(), Vectors=["POINTS", "velocity"]), 1.0, None,
        lambda r: r["points"] > 0),
    "Resample Dimensions of 2^33 points": (
        lambda: tracer(Tetrahedralize(Input=flow()), ResampleDimensions=[2048, 2048, 2048]), 1.0,
        "more than", lambda r: r["points"] == 0),
    "Resample Dimensions of 2^30 points": (
        lambda: tracer(Tetrahedralize(Input=flow()), ResampleDimensions=[1024, 1024, 1024]), 1.0,
        "fewer points", lambda r: r["points"] == 0),
    "Resample Dimensions of 1 along an axis": (
        lambda: tracer(Tetrahedralize(Input=flow()), ResampleDimensions=[1, 16, 16]), 1.0,
        "at least 2", lambda r: r["points"] == 0),
    "resolution 4096^3": (lambda: tracer(flow(Resolution=[4096, 4096, 4096])), 1.0,
                          "Resolution"),
    "all pairs on 20k points": (
        lambda: tracer(flow(), NumberOfElements=2, TemplateSprings="All Pairs",
                       ElementTemplate=Sphere(
                           ThetaResolution=200, PhiResolution=100)), 1.0, "All Pairs"),
    "2^26 point elements": (lambda: tracer(flow(), ElementShape="Point",
                                           NumberOfElements=1 << 26), 1.0, "GiB"),
    # An automatic Duration follows any speed; a Duration the user set is refused
    # when the field is too fast to reach it in bounded steps.
    "fast field (wrong byte order)": (lambda: tracer(scaled_flow(4.3e8), Vectors=["POINTS", "v"],
                                                     Duration=10.0), 1.0, "steps"),
    "int64 values of 2^62": (lambda: tracer(int64_flow(), Vectors=["POINTS", "v"]), 1.0,
                             "byte order"),
    "step size 1e-12": (lambda: tracer(flow(), StepSizeUnit="Time", StepSize=1e-12), 1.0,
                        "steps"),
    "duration 1e12": (lambda: tracer(flow(), Duration=1e12), 1e12, "steps"),
    "speed 1e20": (lambda: tracer(scaled_flow(1e20), Vectors=["POINTS", "v"]), 1.0,
                   "byte order"),
    "speed 1e30": (lambda: tracer(scaled_flow(1e30), Vectors=["POINTS", "v"]), 1.0,
                   "byte order"),
    "spacing 1e-300": (lambda: tracer(flow(Bounds=[0, 1e-298, 0, 1e-298, 0, 1e-298])), 1e-298,
                       "rescale"),
    "coordinate 1e300": (lambda: tracer(flow(Bounds=[0, 1e300, 0, 1, 0, 1])), 1.0, "rescale"),
    "duration 1e-300": (lambda: tracer(flow(), Duration=1e-300), 1e-300, "time span"),
    "100-gon at relaxation 0.2": (
        lambda: tracer(flow(), Restoration="Jacobi", RelaxationFactor=0.2,
                       ElementTemplate=polygon(100)), 2.0, None),
    "paddlewheel at relaxation 1": (lambda: tracer(flow(), ElementShape="Paddlewheel",
                                                   Restoration="Jacobi",
                                                   RelaxationFactor=1.0), 2.0, None),
    "fish at relaxation 1.5": (lambda: tracer(flow(), ElementShape="Fish", Restoration="Jacobi",
                                              RelaxationFactor=1.5), 2.0, None),
    "cross at relaxation 1.5": (lambda: tracer(flow(), ElementShape="Cross", Restoration="Jacobi",
                                               RelaxationFactor=1.5), 2.0, None),
    "emitter outside the field": (lambda: tracer(flow(), EmitterCenter=[50, 50, 50],
                                                 EmitterSize=[0.1, 0.1, 0.1]), 1.0, "outside"),
    "template id beyond 32 bits": (lambda: tracer(flow(), ElementTemplate=wrapped_template()), 1.0,
                                   "uses point"),
    ".bpvol dimensions overflowing 64 bits": (lambda: tracer(overflowing_bpvol()), 0.0,
                                              "dimensions"),
    "GPU template of 20k points": (lambda: gpu_display(20000), 1.0, "GL_MAX_TEXTURE_SIZE"),
    "GPU template of 200k points": (lambda: gpu_display(200000), 1.0, "GL_MAX_TEXTURE_SIZE"),
    "GPU template of 2k points": (lambda: gpu_display(2000), 1.0, None),
    # Issue 27: seeds, templates and masks of any kind of data.
    "multiblock seed source, unsteady input": (
        lambda: tracer(flow(Flow="Double Gyre"), SeedSource=two_lines()), 0.5, None,
        lambda r: r["class"] == "vtkPolyData" and r["points"] == 200 * 8),
    "multiblock seed source, steady input": (
        lambda: tracer(flow(Flow="ABC"), SeedSource=two_lines()), 0.5, None,
        lambda r: r["class"] == "vtkPolyData" and r["points"] == 200 * 8),
    "multiblock seed source, Bound Particles display": (
        lambda: (tracer(flow(Flow="ABC"), SeedSource=two_lines(), Engine="GPU"),
                 "Bound Particles"), 0.5, None,
        lambda r: r["class"] == "vtkPolyData" and r["points"] > 0),
    "multiblock element template": (
        lambda: tracer(flow(), ElementTemplate=GroupDatasets(Input=[Sphere(), Sphere()])), 1.0,
        "Extract Block"),
    "table as seed source": (lambda: tracer(flow(), SeedSource=table_source()), 1.0,
                             "no points"),
    "seed image larger than the field": (
        lambda: tracer(flow(), SeedSource=Wavelet()), 1.0, "outside the field",
        lambda r: r["points"] > 0 and all(abs(b) < 1.3 for b in r["bounds"])),
    "every seed outside the field": (
        lambda: tracer(flow(), SeedSource=Line(Point1=[5, 5, 5], Point2=[6, 6, 6])), 1.0,
        "None of the Seed Source", lambda r: r["points"] == 0),
    "seeds at 1e30": (
        lambda: tracer(flow(), SeedSource=Line(Point1=[1e30] * 3, Point2=[2e30] * 3)), 1.0,
        "None of the Seed Source", lambda r: r["points"] == 0),
    "every seed in masked cells": (
        lambda: tracer(masked_flow("mask = (xyz[:, 0] > 0).astype(numpy.uint8)"),
                       Vectors=["POINTS", "velocity"],
                       SeedSource=Line(Point1=[-0.9, 0, 0], Point2=[-0.2, 0, 0])), 1.0,
        "cells outside the flow", lambda r: r["points"] == 0),
    "some seeds in masked cells": (
        lambda: tracer(masked_flow("mask = (xyz[:, 0] > 0).astype(numpy.uint8)"),
                       Vectors=["POINTS", "velocity"],
                       SeedSource=Line(Point1=[-0.9, 0, 0], Point2=[0.9, 0, 0])), 1.0,
        "cells outside the flow", lambda r: r["points"] > 0),
    "mask with one valid point": (
        lambda: tracer(masked_flow("mask = numpy.zeros(n, numpy.uint8); mask[n // 2] = 1"),
                       Vectors=["POINTS", "velocity"]), 1.0, "No cell of the field",
        lambda r: r["points"] == 0),
    "mask of 3 components": (
        lambda: tracer(masked_flow("mask = numpy.ones((n, 3), numpy.uint8)"),
                       Vectors=["POINTS", "velocity"]), 1.0, "3 components",
        lambda r: r["points"] > 0),
    "mask of the wrong length": (
        lambda: tracer(masked_flow("mask = numpy.ones(n // 2, numpy.uint8)"),
                       Vectors=["POINTS", "velocity"]), 1.0, "values for", lambda r: r["points"] > 0),
    "mask as cell data": (lambda: tracer(cell_mask_flow(), Vectors=["POINTS", "velocity"]), 1.0,
                          "cell data", lambda r: r["points"] > 0),
    "mask of strings": (lambda: tracer(string_mask_flow(), Vectors=["POINTS", "velocity"]), 1.0,
                        "vtkStringArray", lambda r: r["points"] > 0),
    "mask of NaN": (
        lambda: tracer(masked_flow("mask = numpy.full(n, numpy.nan)"),
                       Vectors=["POINTS", "velocity"]), 1.0, "outside the flow's domain",
        lambda r: r["points"] == 0),
    "input times 1e-7 apart": (lambda: tracer(times_source([0, 1, 1 + 1e-7, 2]),
                                              Vectors=["POINTS", "v"]), 1.5, None),
    "input times 1e-7 apart, GPU": (
        lambda: (tracer(times_source([0, 1, 1 + 1e-7, 2]), Vectors=["POINTS", "v"],
                        Engine="GPU"), "Bound Particles"), 2.0, None),
    "trail spacing 1e7": (lambda: tracer(flow(), Trails=1, TrailSpacing=10000000), 1.0,
                          "TrailSpacing", lambda r: r["points"] == 0),
    "trail spacing 0 with trails off": (lambda: tracer(flow(), Trails=0, TrailSpacing=0), 1.0,
                                        None),
    # Heavy particles (issue 44): each bad setting is refused by its name.
    "negative Response Time": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=-1.0), 1.0, "ResponseTime",
        lambda r: r["points"] == 0),
    "NaN Response Time": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=float("nan")), 1.0,
        "ResponseTime", lambda r: r["points"] == 0),
    "Density Ratio 0": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", DensityRatio=0.0), 1.0, "DensityRatio",
        lambda r: r["points"] == 0),
    "NaN Gravity": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", Gravity=[0, float("nan"), 0]), 1.0,
        "Gravity", lambda r: r["points"] == 0),
    "infinite Gravity": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", Gravity=[0, 0, float("inf")]), 1.0,
        "Gravity", lambda r: r["points"] == 0),
    "Inertia with Anchor": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", Anchor="Centre"), 1.0, "Anchor",
        lambda r: r["points"] == 0),
    "Response Time far below the step": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=1e-9, Gravity=[0, 0, -1e6]),
        1.0, "close to massless", lambda r: r["points"] > 0),
    # Issue 53: below float's smallest a response time keeps its sign.
    "Response Time -1e-46": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=-1e-46), 1.0, "ResponseTime",
        lambda r: r["points"] == 0),
    "Response Time -1e-300": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=-1e-300), 1.0,
        "ResponseTime", lambda r: r["points"] == 0),
    "Response Time 5e-324": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=5e-324), 1.0,
        "close to massless", lambda r: r["points"] > 0),
    "Response Time 1e-300": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", ResponseTime=1e-300), 1.0,
        "close to massless", lambda r: r["points"] > 0),
    # Heavy elements in still fluid and in noise: they settle in the box,
    # stepped by their settling; nothing says they will not move or blames
    # Gravity (the noise's step of 4e10 threw them 3.5e9 out of it).
    "heavy elements in 1e-12 noise": (
        lambda: tracer(scaled_flow(1e-12), Vectors=["POINTS", "v"], Inertia="Maxey-Riley",
                       ResponseTime=0.05, Gravity=[0, 0, -2]), float("inf"), None,
        lambda r: r["points"] > 0 and all(abs(b) < 1.3 for b in r["bounds"]) and
        not r["messages"]),
    "heavy elements in still fluid": (
        lambda: tracer(scaled_flow(0.0), Vectors=["POINTS", "v"], Inertia="Maxey-Riley",
                       ResponseTime=0.05, Gravity=[0, 0, -2]), float("inf"), None,
        lambda r: r["points"] > 0 and all(abs(b) < 1.3 for b in r["bounds"]) and
        not r["messages"]),
    # State files whose values ParaView's loading reads as 0 (issue 53).
    "NaN Response Time (state file)": (
        lambda: reloaded(tracer(flow(), Inertia="Maxey-Riley", ResponseTime=float("nan"))),
        # ParaView 5.11 and 5.13 write the NaN as 'NaN', 6.x as 'nan'.
        1.0, "gives ResponseTime the value '", lambda r: r["points"] == 0 and any(
            "ResponseTime (the particles' response time" in m for m in r["messages"])),
    "Inertia as text (state file)": (
        lambda: reloaded(tracer(flow(), Inertia="Maxey-Riley", ResponseTime=-1.0),
                         {"Inertia": "Maxey-Riley"}), 1.0, "the value 'Maxey-Riley'",
        lambda r: r["points"] == 0 and any(
            "ResponseTime (the particles' response time" in m for m in r["messages"])),
    "seeds with Linking": (
        lambda: tracer(flow(), ElementShape="Cross", Linking="Ring", SeedSource=Line()), 1.0,
        "Seed Source is not used", lambda r: r["points"] > 0),
    # Issue 29: seeds that would show nothing moving say so.
    "1000 elements on 7 seed points": (
        lambda: tracer(flow(Flow="Hurricane"), NumberOfElements=1000,
                       SeedSource=Line(Point1=[-0.9, -0.9, 0], Point2=[0.9, 0.9, 0],
                                       Resolution=6)), 1.0, "on top of one another",
        lambda r: r["points"] > 0),
    "seeds in still flow": (
        lambda: tracer(Calculator(Input=flow(Flow="Hurricane"), ResultArrayName="v",
                                  Function="coordsX*iHat"), Vectors=["POINTS", "v"],
                       NumberOfElements=21,
                       SeedSource=Line(Point1=[0, -0.5, 0], Point2=[0, 0.5, 0], Resolution=20)),
        1.0, "barely move", lambda r: r["points"] > 0),
    # Seed Types with values no panel would offer.
    "Line of a billion points": (
        lambda: seeded("Line", Point1=[-0.5, 0, 0], Point2=[0.5, 0, 0], Resolution=1000000000),
        1.0, "releases take the first 65536", lambda r: r["points"] > 0),
    "Point Cloud at a NaN centre": (
        lambda: seeded("Point Cloud", Center=[float("nan"), 0, 0]), 1.0, "not finite",
        lambda r: r["points"] == 0),
    "Point Cloud far outside the field": (
        lambda: seeded("Point Cloud", Center=[50, 50, 50], Radius=1e30, NumberOfPoints=65536),
        1.0, "outside the field", lambda r: r["points"] == 0),
    "Point Cloud of radius 0": (
        lambda: seeded("Point Cloud", Center=[0, 0, 0], Radius=0.0), 1.0, None,
        lambda r: r["points"] > 0),
    # Seed Type Surface (an inlet) over surfaces that carry no flux.
    "Surface, no Seed Source": (lambda: seeded("Surface"), 1.0, "no Seed Source", NONE),
    "Surface of points and lines only": (lambda: surface(GroupDatasets(
        Input=[PointSource(), Line()])), 1.0, "no surface with area", NONE),
    "Surface outside the field": (lambda: surface(Plane(Origin=[5] * 3, Point1=[6, 5, 5],
                                  Point2=[5, 6, 5])), 1.0, "outside the field", NONE),
    "Surface of NaN points": (lambda: surface(nan_plane("True")), 1.0, "not finite", NONE),
    "Surface, some points NaN": (lambda: surface(nan_plane("x > 0.3"), Flow="ABC"), 1.0,
                                 "not finite", lambda r: r["points"] > 0),
    "Surface the flow runs along": (lambda: surface(Plane(), Flow="Solid Body Rotation"), 1.0,
                                    "No flow crosses", NONE),
    "seeds with a stale emitter box": (
        lambda: tracer(flow(), EmitterCenter=[50, 50, 50], EmitterSize=[0.1, 0.1, 0.1],
                       MinimumReleaseSpeed=0.5, SeedSource=Line()), 1.0, None),
    "seeds on the boundary with Any Particle": (
        lambda: tracer(flow(), ResetWhen="Any Particle Leaves",
                       SeedSource=Line(Point1=[-1, -1, -1], Point2=[1, -1, -1])), 1.0,
        "half an element"),
    "unknown output array": (
        lambda: tracer(flow(), OutputArrays=["Velocity", "NoSuchArray"]), 1.0,
        "no array named 'NoSuchArray'", lambda r: r["points"] > 0),
    "burst at the last offered time": (
        lambda: tracer(flow(), Duration=2.0, NumberOfTimeSteps=5, ReleaseWindow=1,
                       ReleaseStart=2.0, ReleaseStop=2.0), 2.0, "last offered time"),
    "heavy particles backward": (
        lambda: tracer(flow(), Inertia="Maxey-Riley", TimeDirection="Backward"), 1.0,
        "Time Direction = Backward", lambda r: r["points"] == 0),
    "backward release window outside the data's times": (
        lambda: tracer(flow(), Duration=2.0, NumberOfTimeSteps=5, TimeDirection="Backward",
                       ReleaseWindow=1, ReleaseStart=5.0, ReleaseStop=6.0), 1.0,
        "lies outside the offered times [0, 2]"),
    "backward burst at the first offered time": (
        lambda: tracer(flow(), Duration=2.0, NumberOfTimeSteps=5, TimeDirection="Backward",
                       ReleaseWindow=1, ReleaseStart=0.0, ReleaseStop=0.0), 0.0,
        "first offered time"),
    "stiffness out of range (state file)": (
        lambda: tracer(flow(), Restoration="Shape Matching", ShapeMatchingStiffness=5.0), 1.0,
        "outside [0, 1]", lambda r: r["points"] > 0),
    "origin 1e25": (lambda: tracer(masked_flow("out.SetOrigin(1e25, 0, 0)"),
                                   Vectors=["POINTS", "velocity"]), 1.0,
                    "too far from the world origin", lambda r: r["points"] == 0),
}


# Cases that share a process apart from the others: allocations far past the
# machine (a process their regression ends or bloats holds no other kind of
# case), and displays (a view left alive after a failed case must not reach
# the cases that draw nothing).
BIG = {
    "Resample Dimensions of 2^33 points", "Resample Dimensions of 2^30 points",
    "resolution 4096^3", "all pairs on 20k points", "2^26 point elements",
    "template id beyond 32 bits", ".bpvol dimensions overflowing 64 bits",
    "Line of a billion points",
}
DRAWN = {
    "GPU template of 20k points", "GPU template of 200k points", "GPU template of 2k points",
    "multiblock seed source, Bound Particles display",
}
assert BIG <= set(CASES) and DRAWN <= set(CASES), "a case named in BIG or DRAWN is not in CASES"


def run_case(name, seconds_from):
    """Builds the case, updates it (drawing it where it names a display), and
    writes its result file: the messages and whether the output is finite."""
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy
    LoadPlugin(args.plugin, ns=globals())
    build, t = CASES[name][:2]
    with bptest.CapturedMessages() as log:
        made = build()
        proxy, display = made if isinstance(made, tuple) else (made, None)
        if display:
            view = CreateRenderView()
            view.ViewSize = [200, 150]
            shown = Show(proxy, view)
            shown.SetRepresentationType(display)
            view.ViewTime = t
            Render(view)
        proxy.UpdatePipeline(t)
        data = servermanager.Fetch(proxy)
        if display:
            # pvpython crashes at exit with a view left alive (without this plugin too).
            Delete(shown)
            Delete(view)
            del view
    points = data.GetNumberOfPoints() if data and data.IsA("vtkDataSet") else 0
    bounds = list(data.GetBounds()) if points else []
    finite = True
    if points:
        finite = numpy.isfinite(vtk_to_numpy(data.GetPoints().GetData())).all()
        pd = data.GetPointData()
        for k in range(pd.GetNumberOfArrays()):
            a = pd.GetArray(k)
            if a is not None:
                finite = finite and numpy.isfinite(vtk_to_numpy(a)).all()
    # Plain Python values for json: under ParaView 5.13 with numpy 2 a numpy.bool
    # reached the result after a Programmable Source ran, and json refuses those.
    result = {"name": name, "points": int(points), "finite": True if finite else False,
              "class": str(data.GetClassName()) if data else "",
              "bounds": [float(b) for b in bounds],
              "messages": [str(m) for m in log.messages],
              "seconds": time.time() - seconds_from}
    path = result_file(args.scratch, name)
    with open(path + ".part", "w") as out:
        json.dump(result, out)
    os.replace(path + ".part", path)


if args.case:
    # The builders above name paraview.simple's functions and the plugin's proxies.
    from paraview.simple import *  # noqa: F401,F403
    LoadPlugin(args.plugin, ns=globals())
    for number, name in enumerate(args.case):
        if number:
            ResetSession()  # noqa: F405
        print("case: " + name, flush=True)
        started = time.time()
        # Past the time limit the default action of SIGALRM ends the process,
        # which the driver reports as this case's hang.
        signal.alarm(TIME_LIMIT)
        run_case(name, started)
        signal.alarm(0)
    sys.exit(0)


def limit_address_space():
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_LIMIT, ADDRESS_LIMIT))


def run_cases_process(names, scratch):
    """Runs the cases in one process, in order, until one ends it; a list of
    (name, exit status, output, seconds, result) for those it ran: the cases
    with a result file ran to their end (status 0); the first without one
    ended the process (its status, and the process's output)."""
    started = time.time()
    process = bptest.run_group(
        [args.pvpython, os.path.abspath(__file__), "--plugin", args.plugin, "--scratch", scratch,
         "--case"] + names, TIME_LIMIT * len(names) + 60, preexec_fn=limit_address_space,
        env=os.environ)
    out = process.stdout
    ran = []
    for name in names:
        path = result_file(scratch, name)
        if not os.path.exists(path):
            # The case that ended the process (or, with status 0, one that wrote nothing).
            status = process.returncode if process.returncode != 0 else None
            ran.append((name, status, out, time.time() - started, None))
            break
        with open(path) as saved:
            result = json.load(saved)
        ran.append((name, 0, "", result["seconds"], result))
    return ran


def run_shared(names, scratch, results):
    """Runs the cases in as few processes as their failures allow: the next
    process starts at the first case without a result."""
    while names:
        for row in run_cases_process(names, scratch):
            results[row[0]] = row[1:]
        names = [name for name in names if name not in results]


def run_all(names, scratch):
    """Every case: (exit status, output, seconds, result) by name."""
    results = {}
    for group in (BIG, DRAWN):
        run_shared([name for name in names if name in group], scratch, results)
    run_shared([name for name in names if name not in BIG | DRAWN], scratch, results)
    return results


scratch_folder = tempfile.TemporaryDirectory(prefix="bp-hostile-")
scratch = scratch_folder.name
results = run_all(list(CASES), scratch)
for name, case in CASES.items():
    refusal = case[2]
    expect = case[3] if len(case) > 3 else None
    status, out, seconds, result = results[name]
    print("%-40s exit %s, %.1f s, %s" % (name, status, seconds,
                                         "no result" if result is None else
                                         "%d points, %d message(s)" % (result["points"],
                                                                       len(result["messages"]))))
    if status != 0 or result is None:
        print(out[-2500:])
    bptest.check(status == 0, "%s: exited with %s%s" % (
        name, status, " (signal %d)" % -status if status is not None and status < 0 else ""))
    bptest.check(seconds < TIME_LIMIT, "%s: ran past %d s" % (name, TIME_LIMIT))
    if result is None:
        bptest.check(False, "%s: printed no result" % name)
        continue
    bptest.check(result["finite"], "%s: the output holds non-finite values" % name)
    said = " | ".join(result["messages"])
    if refusal:
        bptest.check(refusal in said, "%s: refused without naming '%s' (messages: %s)" %
                     (name, refusal, said[:300] or "none"))
        print("    " + (result["messages"] or ["(no message)"])[-1][-240:].strip())
    else:
        # A valid input may warn, never fail.
        errors = [m for m in result["messages"] if "ERROR" in m]
        bptest.check(not errors, "%s: an error for a valid input: %s" % (
            name, errors[0][:300] if errors else ""))
        if expect is None:
            bptest.check(result["points"] > 0, "%s: traced nothing (messages: %s)" %
                         (name, said[:300] or "none"))
    if expect is not None:
        bptest.check(expect(result), "%s: unexpected output (%s %d points, bounds %s)" % (
            name, result["class"], result["points"], result["bounds"]))
scratch_folder.cleanup()
bptest.finish()
