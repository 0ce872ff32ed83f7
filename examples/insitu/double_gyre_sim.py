"""A small simulation that hands its flow to Catalyst one time step at a time.

The flow is the double gyre (an analytic unsteady flow on a uniform grid),
advanced in time by the "solver" loop below. At each step the grid goes to
Catalyst through `paraview.catalyst.bridge`, where the analysis script
(`trace_elements.py`) traces bound particles through it with the Bound
Particle Tracer. Run it with pvpython (or pvbatch):

    pvpython double_gyre_sim.py --plugin /path/to/BoundParticles.so --steps 50 --out out/

Under MPI (`mpiexec -n R pvbatch --symmetric double_gyre_sim.py ...`) each
process computes and hands over only its piece of the grid: a slab along x
with one ghost layer of points on each side, as a finite-difference solver
would hold it; the tracer gathers what its own blocks need from the pieces.

With `--write-steps DIR` it also writes every step it hands over to DIR
(`flow.pvd` over `flow_NNNN.pvti`, over a `flow_NNNN_R.vti` piece per
process), so that the same steps can be traced post hoc.

Checkpoint and restart: with `--checkpoint-every K` the solver writes its
checkpoint every K steps (`checkpoint_NNNN.txt`: the step and its time; the
flow is analytic, so that is all the solver's state) and the analysis script
writes the trace's state at the same step (`state_NNNN.vtp`, `.pvtp` under
MPI: the tracer's State output). `--restart-from N` starts the solver from
its checkpoint N (in `--checkpoints DIR`, by default `--out`) and the script
sets the tracer's Initial State File to the state saved there: the trace goes
on as if the run had never stopped (the CPU engine; the GPU display cannot
save its state).
"""
import argparse
import math
import os

import numpy
from paraview.catalyst import bridge
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--steps", type=int, default=50)
parser.add_argument("--dt", type=float, default=0.2)
parser.add_argument("--every", type=int, default=10, help="write elements every N steps")
parser.add_argument("--out", default="insitu-out")
parser.add_argument("--write-steps", default="")
parser.add_argument("--engine", default="CPU", choices=["CPU", "GPU", "Automatic"],
                    help="the tracer's engine; GPU draws the elements with the GPU engine")
parser.add_argument("--checkpoint-every", type=int, default=0,
                    help="write a checkpoint (the solver's and the trace's state) every K steps")
parser.add_argument("--restart-from", type=int, default=-1,
                    help="start from the checkpoint written at step N")
parser.add_argument("--checkpoints", default="", help="where checkpoints are written and read "
                    "(default: --out)")
args = parser.parse_args()
CHECKPOINTS = os.path.abspath(args.checkpoints or args.out)


def checkpoint_name(step):
    return os.path.join(CHECKPOINTS, "checkpoint_%04d.txt" % step)


def write_checkpoint(step, t):
    """The solver's state at this step (the flow is analytic: its step and time)."""
    with open(checkpoint_name(step), "w") as checkpoint:
        checkpoint.write("%d %r\n" % (step, t))


def read_checkpoint(step):
    with open(checkpoint_name(step)) as checkpoint:
        saved_step, t = checkpoint.read().split()
    return int(saved_step), float(t)

DIMS = (64, 32, 2)
BOUNDS = (0.0, 2.0, 0.0, 1.0, 0.0, 0.05)


GHOST_LAYERS = 1  # points each process holds beyond its own slab


def piece_extent(rank, ranks):
    """This process's piece of the whole point extent: a slab along x of the
    cells (split evenly), with GHOST_LAYERS more points where the grid goes on."""
    cells = DIMS[0] - 1
    first, last = cells * rank // ranks, cells * (rank + 1) // ranks
    return [max(0, first - GHOST_LAYERS), min(DIMS[0] - 1, last + GHOST_LAYERS),
            0, DIMS[1] - 1, 0, DIMS[2] - 1]


def spacing(axis):
    return (BOUNDS[2 * axis + 1] - BOUNDS[2 * axis]) / (DIMS[axis] - 1)


def double_gyre(t, extent):
    """The double gyre's velocity on the piece at time t (A = 0.1, eps = 0.25, omega = pi/5)."""
    a, eps, omega = 0.1, 0.25, math.pi / 5.0
    x = BOUNDS[0] + spacing(0) * numpy.arange(extent[0], extent[1] + 1)
    y = BOUNDS[2] + spacing(1) * numpy.arange(extent[2], extent[3] + 1)
    xx, yy = numpy.meshgrid(x, y, indexing="xy")
    at = eps * math.sin(omega * t)
    bt = 1.0 - 2.0 * eps * math.sin(omega * t)
    f = at * xx * xx + bt * xx
    dfdx = 2.0 * at * xx + bt
    u = -math.pi * a * numpy.sin(math.pi * f) * numpy.cos(math.pi * yy)
    v = math.pi * a * numpy.cos(math.pi * f) * numpy.sin(math.pi * yy) * dfdx
    layer = numpy.stack([u, v, numpy.zeros_like(u)], axis=-1).reshape(-1, 3)
    return numpy.concatenate([layer] * (extent[5] - extent[4] + 1))


def grid_at(t, extent):
    image = vtkImageData()
    image.SetExtent(*extent)
    image.SetOrigin(BOUNDS[0], BOUNDS[2], BOUNDS[4])
    image.SetSpacing(*[spacing(a) for a in range(3)])
    velocity = numpy_to_vtk(numpy.ascontiguousarray(double_gyre(t, extent), dtype=numpy.float32), deep=1)
    velocity.SetName("velocity")
    image.GetPointData().AddArray(velocity)
    return image


def write_step(folder, grid, step, rank, ranks):
    """Writes this process's piece as DIR/flow_NNNN_R.vti and, on process 0,
    DIR/flow_NNNN.pvti over every process's piece; returns the .pvti's name."""
    os.makedirs(folder, exist_ok=True)
    name = "flow_%04d" % step
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(grid)
    writer.SetFileName(os.path.join(folder, "%s_%d.vti" % (name, rank)))
    writer.Write()
    if rank == 0:
        with open(os.path.join(folder, name + ".pvti"), "w") as pvti:
            pvti.write('<VTKFile type="PImageData" version="0.1"><PImageData WholeExtent="%s" '
                       'GhostLevel="0" Origin="%r %r %r" Spacing="%r %r %r">\n'
                       % (" ".join(str(e) for e in [0, DIMS[0] - 1, 0, DIMS[1] - 1, 0, DIMS[2] - 1]),
                          BOUNDS[0], BOUNDS[2], BOUNDS[4], spacing(0), spacing(1), spacing(2)))
            pvti.write('<PPointData><PDataArray type="Float32" Name="velocity" NumberOfComponents="3"/>'
                       '</PPointData>\n')
            for piece in range(ranks):
                pvti.write('<Piece Extent="%s" Source="%s_%d.vti"/>\n'
                           % (" ".join(str(e) for e in piece_extent(piece, ranks)), name, piece))
            pvti.write("</PImageData></VTKFile>\n")
    return name + ".pvti"


os.makedirs(args.out, exist_ok=True)
os.environ["BOUNDPARTICLES_PLUGIN"] = args.plugin
os.environ["BOUNDPARTICLES_INSITU_OUT"] = os.path.abspath(args.out)
os.environ["BOUNDPARTICLES_INSITU_EVERY"] = str(args.every)
os.environ["BOUNDPARTICLES_INSITU_LAST"] = str(args.steps - 1)
os.environ["BOUNDPARTICLES_INSITU_ENGINE"] = args.engine
os.environ["BOUNDPARTICLES_INSITU_CHECKPOINT_EVERY"] = str(args.checkpoint_every)
os.environ["BOUNDPARTICLES_INSITU_CHECKPOINTS"] = CHECKPOINTS
os.environ["BOUNDPARTICLES_INSITU_RESTART"] = str(args.restart_from)
os.makedirs(CHECKPOINTS, exist_ok=True)
first = 0
if args.restart_from >= 0:
    first, _ = read_checkpoint(args.restart_from)  # the solver goes on from its state there
bridge.initialize()
bridge.add_pipeline(os.path.join(os.path.dirname(os.path.abspath(__file__)), "trace_elements.py"), 2)
controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = (controller.GetLocalProcessId(), controller.GetNumberOfProcesses()) if controller else (0, 1)
extent = piece_extent(rank, ranks)
written = []
for step in range(first, args.steps):
    t = step * args.dt
    grid = grid_at(t, extent)  # the solver's state at this step: this process's piece
    # The restart step is handed first: the trace goes on from its state there.
    bridge.coprocess(t, step, grid, name="input", wholeExtent=[0, DIMS[0] - 1, 0, DIMS[1] - 1, 0, DIMS[2] - 1])
    if args.checkpoint_every > 0 and step % args.checkpoint_every == 0 and step > first and rank == 0:
        write_checkpoint(step, t)
    if args.write_steps:
        written.append((t, write_step(args.write_steps, grid, step, rank, ranks)))
bridge.finalize()
if args.write_steps and rank == 0:
    with open(os.path.join(args.write_steps, "flow.pvd"), "w") as pvd:
        pvd.write('<VTKFile type="Collection" version="0.1"><Collection>\n')
        for t, name in written:
            pvd.write('<DataSet timestep="%.17g" file="%s"/>\n' % (t, name))
        pvd.write("</Collection></VTKFile>\n")
