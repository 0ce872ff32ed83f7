"""One trace, written sorted by element for comparison across process counts.

Runs under pvpython (built-in), pvbatch under mpiexec (one piece per rank), or
pvpython connected to a pvserver (--connect host:port). Writes <output>.npz
with, per trace and time, the points, ElementId, ParticleIndex and Velocity
sorted by (ElementId, ParticleIndex), and the process that output each point.
"""
import argparse
import glob
import os
import sys

import numpy

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--connect", help="host:port of a pvserver")
parser.add_argument("--render", help="write a picture per remote-render threshold here")
parser.add_argument("--rectilinear", help="a .vtr vector field with stretched z layers to trace")
parser.add_argument("--bpvol", help="the same field as a raw volume series (.bpvol)")
parser.add_argument("--data", help="the shared real data sets' folder (read in place)")
parser.add_argument("--resume-from", action="append", default=[], metavar="NAME=STATE",
                    help="a state saved by another run (on another number of processes) to go "
                         "on from, as the case resumed_from_NAME")
args = parser.parse_args()

if args.connect:
    host, port = args.connect.rsplit(":", 1)
    Connect(host, int(port))
    LoadPlugin(args.plugin, remote=True, ns=globals())
    LoadPlugin(args.plugin, remote=False, ns=globals())
else:
    LoadPlugin(args.plugin, ns=globals())


PLANE_Z = 0.25  # the flat field's plane (test_parallel.py checks the points stay in it)


def updated(source):
    """The source, run: a tracer made on it takes the field's bounds as its
    emitter box (ParaView 6 gives a box of size 0 at the origin before)."""
    source.UpdatePipeline()
    return source


def traces():
    """Steady ABC with crosses reset as they leave; unsteady double gyre with points."""
    abc = updated(AnalyticFlow(Flow="ABC", Resolution=[40, 36, 32], Bounds=[0, 2, 0, 1.8, 0, 1.6]))
    crosses = BoundParticleTracer(
        Input=abc, ElementShape="Cross", NumberOfElements=400, Seed=3, Duration=1.0,
        NumberOfTimeSteps=11, LifetimeRange=[0.2, 0.5], Integrator="Runge-Kutta 4",
        Restoration="Shape Matching", StepSize=0.5)
    gyre = updated(AnalyticFlow(Flow="Double Gyre", Resolution=[48, 24, 2],
                                Bounds=[0, 2, 0, 1, 0, 0.1], NumberOfTimeSteps=6))
    points = BoundParticleTracer(Input=gyre, ElementShape="Point", NumberOfElements=2000, Seed=9,
                                 LifetimeRange=[1.0, 3.0])
    return {"crosses": (crosses, [0.5, 1.0]), "points": (points, None)}


def plane_of_kinds(first, second, at=(0.0, 0.0, 0.0)):
    """The plane x = 0 over y, z in [-1, 1], moved by `at`, as two cells
    along y with the cell array Kind (0 Gate, 1 Outlet, 2 Wall): `first` for
    y < 0, `second` for y > 0. Its points in double (far from the origin a
    float would move them)."""
    x, y, z = at
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "from vtkmodules.vtkFiltersSources import vtkPlaneSource\n"
        "from vtkmodules.vtkCommonCore import vtkIntArray\n"
        "p = vtkPlaneSource(); p.SetOutputPointsPrecision(1)\n"
        "p.SetOrigin(%r, %r, %r); p.SetPoint1(%r, %r, %r)\n"
        "p.SetPoint2(%r, %r, %r); p.SetXResolution(2); p.Update()\n"
        "out = self.GetOutput(); out.ShallowCopy(p.GetOutput())\n"
        "k = vtkIntArray(); k.SetName('Kind'); k.InsertNextValue(%d); k.InsertNextValue(%d)\n"
        "out.GetCellData().AddArray(k)\n" % (x, y - 1, z - 1, x, y + 1, z - 1, x, y - 1, z + 1,
                                               first, second))
    return source


# Far from the origin, at a negative y: where the far variants of the
# Surfaces' cases (gates_far, surface_walls_far, mask_slip_far) move their
# field and surfaces. The engines work relative to the field's first point
# (engine specification, section 5), so 1e7 loses nothing in float.
FAR = (1.0e7 + 0.375, -2.5e6 - 0.625, 0.0)


def moved(bounds, at=FAR):
    """`bounds` (x0, x1, y0, y1, z0, z1) moved by `at`."""
    return [b + at[k // 2] for k, b in enumerate(bounds)]


def placement_traces():
    """Fields anywhere in space: the Analytic Flow's default bounds [-1, 1]^3;
    projected coordinates ~1e6 from the origin; a field at negative
    coordinates on every axis; thin, long boxes of anisotropic cells that the
    block split cuts along X, Y and Z in turn; steady and unsteady."""
    cases = {}
    hurricane = updated(AnalyticFlow(Flow="Hurricane", Resolution=[24, 24, 24]))
    cases["hurricane"] = (BoundParticleTracer(Input=hurricane, ElementShape="Cross",
                                              NumberOfElements=800, Seed=4), [0.5, 1.0])
    # Releases from a Seed Source: every process takes the whole line's points.
    line = Line(Point1=[-0.9, -0.8, -0.7], Point2=[0.9, 0.8, 0.7], Resolution=40)
    cases["seeded"] = (BoundParticleTracer(Input=hurricane, SeedSource=line, ElementShape="Cross",
                                           NumberOfElements=400, Seed=4), [0.5, 1.0])
    # Back in time: every process resumes from the same checkpoint (spaced by
    # the whole system's state), back to 0.45 after 1.0, then on to 0.8; the
    # same trace run straight to 0.45 is what the step back must give.
    for name, times in (("back", [1.0, 0.45, 0.8]), ("back_fresh", [0.45, 1.0])):
        cases[name] = (BoundParticleTracer(Input=hurricane, ElementShape="Cross",
                                           NumberOfElements=400, Seed=4, CheckpointMemory=64,
                                           LifetimeRange=[0.3, 0.6]), times)
    # Save and resume: the state at 0.5 saved as a user does it (SaveData on
    # the State output, .pvtp: a piece per process, process 0's holding
    # every element), and a new tracer that goes on from it to 1.0 must
    # trace what one that never stopped does (test_parallel.py:
    # check_save_resume), on the same number of processes; and from the
    # states other runs saved on other numbers of processes, whose elements
    # this run's processes split by their centres (check_resume_across).
    # The field's far corner rounds differently on 4 processes than on 1 and
    # 2 (each piece places its points from its own first one): the step that
    # follows from its cell length must not.
    skewed = updated(AnalyticFlow(Flow="ABC", Resolution=[13, 36, 11],
                                  Bounds=[-32.71, -31.6405, -16.5, -15.3741, 28.791, 32.455]))

    def resumable(**extra):
        return BoundParticleTracer(Input=skewed, ElementShape="Cross", NumberOfElements=400,
                                   Seed=12, Duration=1.0, NumberOfTimeSteps=11,
                                   LifetimeRange=[0.3, 0.6], **extra)
    saver = resumable()
    saver.UpdatePipeline(0.5)
    state = os.path.abspath(args.output) + "-state.pvtp"
    SaveData(state, proxy=OutputPort(saver, 2))
    Delete(saver)
    cases["resumed"] = (resumable(InitialStateFile=state), [1.0])
    cases["resumed_straight"] = (resumable(), [1.0])
    for named in args.resume_from:
        tag, path = named.split("=", 1)
        cases["resumed_from_" + tag] = (resumable(InitialStateFile=path), [1.0])
    # Walls: the hurricane's inflow and updraft carry crosses onto the
    # field's sides, where Stick holds them; the Interactions output (port
    # 3), gathered on process 0, is the same on any number of processes.
    cases["walls"] = (BoundParticleTracer(Input=hurricane, ElementShape="Cross",
                                          NumberOfElements=400, Seed=4, Boundary="Stick",
                                          LifetimeRange=[2, 2]), [0.5, 1.0])
    # Gates and an outlet (the Surfaces input, whole on every process): the
    # plane x = 0 in two cells, a gate (y < 0) and an outlet (y > 0) by a
    # cell array; the passages gathered on process 0 are the same on any
    # number of processes.
    cases["gates"] = (plane_tracer(hurricane, (0, 1)), [0.5, 1.0])
    # A Slip wall (y < 0) and a gate (y > 0) of the Surfaces: each particle
    # kept off the wall on its process as on one.
    cases["surface_walls"] = (plane_tracer(hurricane, (2, 0), Boundary="Slip"), [0.5, 1.0])
    # Seed Types: every process computes the same points (the cloud's from
    # the Seed, not from a process's own random sequence).
    cloud = BoundParticleTracer(Input=hurricane, ElementShape="Cross", NumberOfElements=400,
                                Seed=4, SeedType="Point Cloud")
    cloud.SeedType.Center = [0.1, -0.2, 0.0]
    cloud.SeedType.Radius = 0.6
    cloud.SeedType.NumberOfPoints = 400
    cases["seed_cloud"] = (cloud, [0.5, 1.0])
    seed_line = BoundParticleTracer(Input=hurricane, ElementShape="Cross", NumberOfElements=400,
                                    Seed=4, SeedType="Line")
    seed_line.SeedType.Point1 = [-0.9, 0.7, -0.5]
    seed_line.SeedType.Point2 = [0.9, -0.7, 0.5]
    seed_line.SeedType.Resolution = 199
    cases["seed_line"] = (seed_line, [0.5, 1.0])
    # Seed Type Surface: every process weighs the Seed Source's surface by
    # the flux through it from the velocities the processes holding each
    # triangle sampled, and draws the same points.
    inlet = BoundParticleTracer(Input=hurricane, ElementShape="Cross", NumberOfElements=400,
                                Seed=4, SeedType="Surface",
                                SeedSource=Box(Center=[0.4, 0.0, 0.0], XLength=0.6,
                                               YLength=0.4, ZLength=0.8))
    cases["seed_surface"] = (inlet, [0.5, 1.0])
    # Spins and trails: each element's poses travel with it between pieces.
    trails = BoundParticleTracer(Input=hurricane, ElementShape="Cross", NumberOfElements=400,
                                 Seed=6, Trails=1, TrailLength=3, TrailSpacing=2)
    trails.OutputArrays = list(trails.OutputArrays) + ["ElementSpin"]
    cases["trails"] = (trails, [0.5, 1.0])
    # Anchor = Centre: elements held at their release centres, turning, and
    # released again (in another piece) as their short lives end.
    anchored = BoundParticleTracer(Input=hurricane, ElementShape="Paddlewheel",
                                   NumberOfElements=400, Seed=8, Anchor="Centre",
                                   Restoration="Shape Matching", LifetimeRange=[0.3, 0.6])
    anchored.OutputArrays = list(anchored.OutputArrays) + ["ElementSpin"]
    cases["anchored"] = (anchored, [0.5, 1.0])
    # Heavy particles settling through the hurricane: each particle's slip
    # velocity travels with its element between pieces.
    heavy = BoundParticleTracer(Input=hurricane, ElementShape="Square", NumberOfElements=400,
                                Seed=9, Inertia="Maxey-Riley", ResponseTime=0.05,
                                DensityRatio=500, Gravity=[0, 0, -2])
    heavy.OutputArrays = list(heavy.OutputArrays) + ["SlipVelocity"]
    cases["inertial"] = (heavy, [0.5, 1.0])
    # Heavy particles on a flat field (2D data): Gravity's component across
    # the plane is dropped alike on every process, so all stay in it.
    flat = updated(AnalyticFlow(Flow="Double Gyre", Resolution=[48, 24, 1],
                                Bounds=[0, 2, 0, 1, PLANE_Z, PLANE_Z]))
    flat_heavy = BoundParticleTracer(Input=flat, ElementShape="Square", NumberOfElements=400,
                                     Seed=9, Inertia="Maxey-Riley", ResponseTime=0.05,
                                     DensityRatio=500, Gravity=[0, -0.5, -9.81])
    flat_heavy.OutputArrays = list(flat_heavy.OutputArrays) + ["SlipVelocity"]
    cases["inertial_plane"] = (flat_heavy, [0.5, 1.0])
    # A release window: hidden elements cross pieces and are released together.
    cases["window"] = (BoundParticleTracer(Input=hurricane, ElementShape="Square",
                                           NumberOfElements=600, Seed=5, ReleaseWindow=1,
                                           ReleaseStart=0.3, ReleaseStop=0.6,
                                           LifetimeRange=[0.2, 0.4]), [0.5, 1.0])
    # Lattice releases: element ids are global, so every process computes the
    # same point; points in the stagnant core are never shown.
    cases["lattice"] = (BoundParticleTracer(Input=hurricane, ElementShape="Cross",
                                            NumberOfElements=700, Seed=5, ReleasePattern="Lattice",
                                            LifetimeRange=[0.2, 0.4]), [0.5, 1.0])
    # Release Weights: every process draws against the whole field's weights,
    # on an image and through a resampled mesh.
    weights = updated(Calculator(Input=hurricane, ResultArrayName="w", Function="coordsX+1"))
    cases["weighted"] = (BoundParticleTracer(Input=weights, ElementShape="Cross",
                                             NumberOfElements=600, Seed=5,
                                             Vectors=["POINTS", "velocity"],
                                             ReleaseWeights=["POINTS", "w"],
                                             LifetimeRange=[0.2, 0.4]), [0.5, 1.0])
    weighted_hexes = updated(CleantoGrid(Input=ImageDatatoPointSet(Input=weights)))
    cases["weighted_mesh"] = (BoundParticleTracer(
        Input=weighted_hexes, ElementShape="Cross", NumberOfElements=400, Seed=5,
        Vectors=["POINTS", "velocity"], ReleaseWeights=["POINTS", "w"],
        ResampleDimensions=[24, 24, 24], LifetimeRange=[0.2, 0.4]), [0.5, 1.0])
    far = updated(AnalyticFlow(Flow="ABC", Resolution=[48, 12, 10],
                               Bounds=[1e6, 1e6 + 4, -2e6, -2e6 + 1, 5e5, 5e5 + 0.8]))
    cases["far_x"] = (BoundParticleTracer(Input=far, ElementShape="Strip4", NumberOfElements=600,
                                          Seed=5, Duration=1.0, NumberOfTimeSteps=11,
                                          LifetimeRange=[0.3, 0.6]), [0.5, 1.0])
    negative = updated(AnalyticFlow(Flow="Shear Layer", Resolution=[10, 40, 12],
                                    Bounds=[-7, -6, -9, -5, -3, -2.5]))
    cases["negative_y"] = (BoundParticleTracer(Input=negative, ElementShape="Square",
                                               NumberOfElements=500, Seed=6, Duration=2.0,
                                               NumberOfTimeSteps=11), [1.0, 2.0])
    gyre = updated(AnalyticFlow(Flow="Double Gyre", Resolution=[12, 8, 40],
                                Bounds=[-3, -1, 4, 5, -10, -6], NumberOfTimeSteps=5))
    cases["unsteady_z"] = (BoundParticleTracer(Input=gyre, ElementShape="Point",
                                               NumberOfElements=1200, Seed=7), [1.0, 2.0])
    # Time Direction = Backward: released at the time line's end (2) and
    # traced back through the reversed flow, to 1 and on to 0; on the source
    # unsteady_z left at 2, with the ghost layers its trace asked for.
    cases["backward"] = (BoundParticleTracer(Input=gyre, ElementShape="Point",
                                             NumberOfElements=1200, Seed=7,
                                             TimeDirection="Backward"), [1.0, 0.0])
    # unsteady_z again, started on the source the backward trace left at 0:
    # each process's piece comes with that trace's ghost layers, not the two
    # a new tracer asks for, and the next step's with two. It must trace
    # what unsteady_z did (test_parallel.py: check_shared_start).
    cases["shared_start"] = (BoundParticleTracer(Input=gyre, ElementShape="Point",
                                                 NumberOfElements=1200, Seed=7), [1.0, 2.0])
    # Meshes, resampled inside the tracer: each rank locates the grid points
    # in its piece of cells. Hexahedra (an image's cells as an unstructured
    # grid) interpolate alike whichever piece holds a point; so do two
    # curvilinear zones sharing a face, and an unsteady curvilinear grid.
    abc = updated(AnalyticFlow(Flow="ABC", Resolution=[24, 20, 16], Bounds=[0, 2, 0, 1.8, 0, 1.6]))
    hexes = updated(CleantoGrid(Input=ImageDatatoPointSet(Input=abc)))
    cases["mesh"] = (BoundParticleTracer(
        Input=hexes, ElementShape="Cross", NumberOfElements=400, Seed=3, Duration=1.0,
        NumberOfTimeSteps=11, Vectors=["POINTS", "velocity"], ResampleDimensions=[24, 20, 16]),
        [0.5, 1.0])
    # A mesh with a spherical hole (clipped away), resampled: the hole's
    # cells are outside the flow, and with Slip their faces are a wall.
    cases["mask_slip"] = (hole_tracer(hexes, [1.0, 0.9, 0.8]), [0.5, 1.0])
    cases.update(far_surface_traces())
    zones = updated(GroupDatasets(Input=[
        ImageDatatoPointSet(Input=AnalyticFlow(Flow="ABC", Resolution=[12, 20, 16],
                                               Bounds=[0, 1, 0, 1.8, 0, 1.6])),
        ImageDatatoPointSet(Input=AnalyticFlow(Flow="ABC", Resolution=[13, 20, 16],
                                               Bounds=[1, 2, 0, 1.8, 0, 1.6]))]))
    cases["zones"] = (BoundParticleTracer(
        Input=zones, ElementShape="Strip4", NumberOfElements=500, Seed=4, Duration=1.0,
        NumberOfTimeSteps=11, Vectors=["POINTS", "velocity"]), [0.5, 1.0])
    moving = updated(ImageDatatoPointSet(Input=AnalyticFlow(
        Flow="Double Gyre", Resolution=[40, 20, 2], Bounds=[0, 2, 0, 1, 0, 0.05],
        NumberOfTimeSteps=5)))
    cases["mesh_unsteady"] = (BoundParticleTracer(
        Input=moving, ElementShape="Point", NumberOfElements=1200, Seed=7,
        Vectors=["POINTS", "velocity"]), [1.0, 2.0])
    cases["ftle"] = (ftle_trace(), [1.0, 2.0])
    cases.update(periodic_traces())
    if args.rectilinear:
        grid = XMLRectilinearGridReader(FileName=[args.rectilinear])
        grid.UpdatePipeline()  # the emitter's defaults come from the input's bounds
        cases["rectilinear"] = (BoundParticleTracer(
            Input=grid, ElementShape="Cross", NumberOfElements=500, Seed=8, Duration=1.0,
            NumberOfTimeSteps=6, Vectors=["POINTS", "velocity"]), [0.6, 1.0])
    if args.bpvol:
        series = OpenDataFile(args.bpvol)
        series.UpdatePipeline()
        cases["bpvol"] = (BoundParticleTracer(
            Input=series, ElementShape="Cross", NumberOfElements=500, Seed=8, Duration=1.0,
            NumberOfTimeSteps=6), [0.6, 1.0])
    if args.data:
        carotid = XMLImageDataReader(FileName=[os.path.join(args.data, "carotid.vti")])
        carotid.UpdatePipeline()
        cases["carotid"] = (BoundParticleTracer(
            Input=carotid, ElementShape="Strip4", NumberOfElements=600, Seed=9, Duration=1.0,
            NumberOfTimeSteps=11, Vectors=["POINTS", "velocity"]), [0.5, 1.0])
        # The automatic Duration from the field's scale, probed on every rank.
        combustor = updated(XMLImageDataReader(
            FileName=[os.path.join(args.data, "combustor.vti")]))
        cases["combustor"] = (BoundParticleTracer(
            Input=combustor, ElementShape="Strip4", NumberOfElements=600, Seed=10), None)
    return cases


def far_surface_traces():
    """gates, surface_walls and mask_slip moved by FAR, the Surfaces and the
    hole with their fields: the same passages, slides and ends on any number
    of processes as near the origin (test_parallel.py: REQUIRED_EVENTS says
    which must occur, check_far_moved compares them with the near cases')."""
    hurricane = updated(AnalyticFlow(Flow="Hurricane", Resolution=[24, 24, 24],
                                     Bounds=moved([-1, 1, -1, 1, -1, 1])))
    abc = updated(AnalyticFlow(Flow="ABC", Resolution=[24, 20, 16],
                               Bounds=moved([0, 2, 0, 1.8, 0, 1.6])))
    hexes = updated(CleantoGrid(Input=ImageDatatoPointSet(Input=abc)))
    return {"gates_far": (plane_tracer(hurricane, (0, 1), at=FAR), [0.5, 1.0]),
            "surface_walls_far": (plane_tracer(hurricane, (2, 0), at=FAR, Boundary="Slip"),
                                  [0.5, 1.0]),
            "mask_slip_far": (hole_tracer(hexes, moved([1.0, 1.0, 0.9, 0.9, 0.8, 0.8])[::2]),
                              [0.5, 1.0])}


def plane_tracer(hurricane, kinds, at=(0.0, 0.0, 0.0), **extra):
    """Crosses in `hurricane` with plane_of_kinds(*kinds), moved by `at`, as
    the Surfaces (gates, surface_walls)."""
    return BoundParticleTracer(Input=hurricane, ElementShape="Cross", NumberOfElements=400,
                               Seed=4, LifetimeRange=[2, 2], Surfaces=plane_of_kinds(*kinds, at=at),
                               SurfaceInteractionArray="Kind", **extra)


def hole_tracer(hexes, centre):
    """Crosses in the mesh `hexes` with a spherical hole of radius 0.45 at
    `centre` clipped away, resampled, Slip on the hole's faces (mask_slip)."""
    holed = updated(Clip(Input=hexes, ClipType="Sphere", Invert=0))
    holed.ClipType.Center = centre
    holed.ClipType.Radius = 0.45
    holed.UpdatePipeline()
    return BoundParticleTracer(
        Input=holed, ElementShape="Cross", NumberOfElements=400, Seed=3, Duration=1.0,
        NumberOfTimeSteps=11, Vectors=["POINTS", "velocity"], ResampleDimensions=[24, 20, 16],
        Boundary="Slip")


def ftle_trace():
    """Spring-free crosses on a 40 x 20 lattice over the double gyre, with
    ElementFTLE and ElementStretch: Release Pattern = Lattice (the FTLE map,
    port 1, is then gathered on process 0)."""
    gyre = updated(AnalyticFlow(Flow="Double Gyre", Resolution=[64, 32, 2],
                                Bounds=[0, 2, 0, 1, -0.01, 0.01], NumberOfTimeSteps=5))
    tracer = BoundParticleTracer(Input=gyre, ElementShape="Cross", RestorationIterations=0,
                                 NumberOfElements=800, ElementSize=0.02,
                                 ReleaseOrientation="Fixed", Integrator="Runge-Kutta 4",
                                 StepSizeUnit="Time", StepSize=0.05, FramesPerInputStep=1,
                                 LifetimeRange=[10, 10], MinimumReleaseSpeed=0.0)
    tracer.OutputArrays = list(tracer.OutputArrays) + ["ElementFTLE", "ElementStretch"]
    tracer.ReleasePattern = "Lattice"
    tracer.EmitterCenter = [1.0, 0.5, 0.0]
    tracer.EmitterSize = [2.0, 1.0, 0.0]
    return tracer


# Periodic along x and y: a Wavelet image over [-10, 10] x [-5, 5] x [-8, 8]
# (spacing 1) in the uniform flow (1, 0.5, 0), whose period along x (20 at
# speed 1) and along y (10 at 0.5) is 20; and the same image as a mesh of
# hexahedra, resampled onto the same grid. Compared at 1, halfway and one
# period later (test_parallel.py: check_periodic). The processes split z, the
# one axis not periodic, into blocks with ghost layers (4 here, for an element
# and a step): each reads whole x-y planes over a part of z, which the
# periodic_blocks case records per rank in <output>-extent-<rank>.txt
# (EXTENT_SCRIPT), saved as "periodic_extents".
PERIODIC_TIMES = [1.0, 11.0, 21.0]

# A pass-through that appends the extent it passes on (the one the tracer
# asked its input for) to a file per rank.
EXTENT_SCRIPT = (
    "from vtkmodules.vtkParallelCore import vtkMultiProcessController\n"
    "out = self.GetOutput(); out.ShallowCopy(self.GetInput())\n"
    "c = vtkMultiProcessController.GetGlobalController()\n"
    "r = c.GetLocalProcessId() if c else 0\n"
    "with open(%r + '-extent-%%d.txt' %% r, 'a') as f:\n"
    "    f.write(' '.join(str(v) for v in out.GetExtent()) + '\\n')\n" % args.output)
for stale in glob.glob(args.output + "-extent-*.txt"):
    os.remove(stale)


def periodic_extents():
    """Each rank's last recorded extent of the periodic_blocks case, in rank
    order (rows of 6)."""
    rows = []
    for rank in range(len(glob.glob(args.output + "-extent-*.txt"))):
        with open(args.output + "-extent-%d.txt" % rank) as f:
            rows.append([int(v) for v in f.read().split("\n")[-2].split()])
    return numpy.array(rows, dtype=int).reshape(-1, 6)


def periodic_traces():
    """Strips that cross both periodic seams, and the pieces' boundaries, on
    their way back to where they were after one period: every process reads
    the whole of both axes (cuts them from the resampled grid) and hands each
    element that moves across a seam to the process that owns its new
    centre."""
    wavelet = Wavelet(WholeExtent=[-10, 10, -5, 5, -8, 8])
    wind = updated(Calculator(Input=wavelet, ResultArrayName="wind", Function="iHat + 0.5*jHat"))
    hexes = updated(CleantoGrid(Input=ImageDatatoPointSet(Input=wind)))
    cases = {}
    for name, field, extra in (("periodic", wind, {}),
                               ("periodic_mesh", hexes, {"ResampleDimensions": [21, 11, 17]})):
        tracer = BoundParticleTracer(Input=field, Vectors=["POINTS", "wind"], ElementShape="Strip4",
                                     NumberOfElements=400, ElementSize=1.0,
                                     EmitterCenter=[0, 0, 0], EmitterSize=[18, 8, 15],
                                     StepSizeUnit="Time", StepSize=0.05, Duration=22,
                                     LifetimeRange=[100, 100], Seed=5, Periodic=[0, 1, 0], **extra)
        # Traced first periodic along y only, then along x too: under MPI
        # each process then reads the whole x axis as well, and the time step
        # it held (its block's share of x) must not serve the new trace.
        tracer.UpdatePipeline(11.0)
        tracer.Periodic = [1, 1, 0]
        cases[name] = (tracer, PERIODIC_TIMES)
    # Periodic along x and y from the start, on a field of its own, passed
    # through EXTENT_SCRIPT: the extent each rank asks for. (After a change
    # of Periodic the producer may give the union of the old and new
    # extents, which the tracer crops.)
    own = Calculator(Input=Wavelet(WholeExtent=[-10, 10, -5, 5, -8, 8]), ResultArrayName="wind",
                     Function="iHat + 0.5*jHat")
    cases["periodic_blocks"] = (BoundParticleTracer(
        Input=ProgrammableFilter(Input=own, Script=EXTENT_SCRIPT), Vectors=["POINTS", "wind"],
        ElementShape="Strip4", NumberOfElements=400, ElementSize=1.0, EmitterCenter=[0, 0, 0],
        EmitterSize=[18, 8, 15], StepSizeUnit="Time", StepSize=0.05, Duration=1.0, Seed=6,
        Periodic=[1, 1, 0]), [0.5, 1.0])
    return cases


# The cases whose Interactions output (port 3) is compared: Stick's contacts,
# Release Again's elements leaving, back in time and straight, the passages
# of a gate and an outlet, the slides along a wall of the Surfaces and along
# a mesh's hole, near the origin and far from it.
EVENT_CASES = ("walls", "back", "back_fresh", "gates", "surface_walls", "mask_slip",
               "gates_far", "surface_walls_far", "mask_slip_far")
EVENT_ARRAYS = (("Time", 1), ("ElementId", 1), ("ParticleIndex", 1), ("Interaction", 1),
                ("SurfaceId", 1), ("Normal", 3), ("ElementVelocity", 3), ("SurfaceCell", 1))


def interactions(tracer, time):
    """Process 0's Interactions output (every process's events) at `time` as
    rows: the point, then EVENT_ARRAYS' columns. The tracer is updated at
    that time first: Fetch's own update asks for none, and its port would
    stay at the time it was first fetched at."""
    tracer.UpdatePipeline(time)
    data = servermanager.Fetch(tracer, 0, None, 3)
    count = data.GetNumberOfPoints()
    columns = [vtk_to_numpy(data.GetPoints().GetData()).reshape(count, 3).astype(float)
               if count else numpy.zeros((0, 3))]
    for array, components in EVENT_ARRAYS:
        values = data.GetPointData().GetArray(array)
        columns.append(vtk_to_numpy(values).reshape(count, components).astype(float)
                       if values is not None else numpy.zeros((count, components)))
    return numpy.hstack(columns)


def all_traces():
    cases = traces()
    cases.update(placement_traces())
    return cases


# Each point's rank, from the rank itself: ParaView's own filters for it differ
# between versions (Process Id Scalars up to 5.13; 6.1's Process Ids wrote no
# array under pvbatch on 2 ranks).
RANK_SCRIPT = (
    "from vtkmodules.vtkCommonCore import vtkIntArray\n"
    "from vtkmodules.vtkParallelCore import vtkMultiProcessController\n"
    "out = self.GetOutput(); out.ShallowCopy(self.GetInput())\n"
    "c = vtkMultiProcessController.GetGlobalController()\n"
    "a = vtkIntArray(); a.SetName('ProcessId')\n"
    "a.SetNumberOfTuples(out.GetNumberOfPoints())\n"
    "a.Fill(c.GetLocalProcessId() if c else 0)\n"
    "out.GetPointData().AddArray(a)\n")


def process_ids(Input):
    return ProgrammableFilter(Input=Input, Script=RANK_SCRIPT)


process_array = "ProcessId"

result = {}
for name, (tracer, times) in all_traces().items():
    ids = process_ids(Input=tracer)
    steps = list(tracer.TimestepValues)
    # The offered time line: automatic ones come from the field's scale.
    result[name + "_times"] = numpy.array(steps)
    if times is None:
        times = [steps[2], steps[-1]]
    for k, t in enumerate(times):
        ids.UpdatePipeline(t)
        key = "%s_%d" % (name, k)
        if name.startswith("resumed"):
            # The steps this update took (read before the fetch updates again).
            tracer.UpdatePropertyInformation()
            result[key + "_steps"] = numpy.array([tracer.GetPropertyValue("StepsInLastUpdate")])
        data = servermanager.Fetch(ids)
        pd = data.GetPointData()
        element = vtk_to_numpy(pd.GetArray("ElementId")).astype(numpy.int64)
        particle = vtk_to_numpy(pd.GetArray("ParticleIndex")).astype(numpy.int64)
        # Trails repeat an element's particles once per pose, by Age.
        age = pd.GetArray("Age")
        age = vtk_to_numpy(age) if age is not None else numpy.zeros(len(element))
        order = numpy.lexsort((particle, age, element))
        result[key + "_points"] = vtk_to_numpy(data.GetPoints().GetData())[order].astype(float)
        result[key + "_element"] = element[order]
        result[key + "_particle"] = particle[order]
        result[key + "_velocity"] = vtk_to_numpy(pd.GetArray("Velocity"))[order].astype(float)
        result[key + "_process"] = vtk_to_numpy(pd.GetArray(process_array))[order].astype(int)
        result[key + "_cells"] = numpy.array([data.GetNumberOfCells()])
        for name_in, suffix in (("Age", "_age"), ("ElementSpin", "_spin"), ("SlipVelocity", "_slip"),
                                ("ElementFTLE", "_ftle"), ("ElementStretch", "_stretch")):
            if pd.GetArray(name_in) is not None:
                result[key + suffix] = vtk_to_numpy(pd.GetArray(name_in))[order].astype(float)
        if name == "ftle":
            # Process 0's FTLE map: the whole image (empty without a lattice
            # release), at t: Fetch's own update asks for no time.
            tracer.UpdatePipeline(t)
            image = servermanager.Fetch(tracer, 0, None, 1)
            ftle = image.GetPointData().GetArray("FTLE")
            result[key + "_map"] = (vtk_to_numpy(ftle).astype(float) if ftle is not None
                                    else numpy.zeros(0))
        if name in EVENT_CASES:
            result[key + "_events"] = interactions(tracer, t)
        per_process = data.GetFieldData().GetArray("ElementsPerProcess")
        if per_process is not None:
            result[key + "_per_process"] = vtk_to_numpy(per_process).astype(int)
        print("%s t=%g: %d points" % (name, t, data.GetNumberOfPoints()))

if args.render:
    # The Bound Particles display with remote rendering on (threshold 0) and
    # off, asking for the GPU engine: where the processes that trace are not
    # the one that draws, the CPU engine's particles are drawn instead.
    os.makedirs(args.render, exist_ok=True)
    crosses = traces()["crosses"][0]
    crosses.Engine = "GPU"
    view = CreateRenderView()
    view.ViewSize = [320, 240]
    view.OrientationAxesVisibility = 0
    display = Show(crosses, view)
    display.SetRepresentationType("Bound Particles")
    view.ViewTime = 1.0
    ResetCamera(view)
    for threshold, label in ((0.0, "remote"), (1e6, "local")):
        view.RemoteRenderThreshold = threshold
        Render(view)
        SaveScreenshot(os.path.join(args.render, label + ".png"), view, ImageResolution=[320, 240])
    Delete(display)
    Delete(view)
    del view

result["periodic_extents"] = periodic_extents()
result["far_offset"] = numpy.array(FAR)  # test_parallel.py: check_far_moved
numpy.savez(args.output, **result)
print("wrote", args.output)
