"""A small simulation that hands its flow to Catalyst one time step at a time.

The flow is the double gyre (an analytic unsteady flow on a uniform grid),
advanced in time by the "solver" loop below. At each step the grid goes to
Catalyst through `paraview.catalyst.bridge`, where the analysis script
(`trace_elements.py`) traces bound particles through it with the Bound
Particle Tracer. Run it with pvpython (or pvbatch):

    pvpython double_gyre_sim.py --plugin /path/to/BoundParticles.so --steps 50 --out out/

With `--write-steps DIR` it also writes every step it hands over to DIR
(`flow.pvd`), so that the same steps can be traced post hoc.
"""
import argparse
import math
import os

import numpy
from paraview.catalyst import bridge
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--steps", type=int, default=50)
parser.add_argument("--dt", type=float, default=0.2)
parser.add_argument("--every", type=int, default=10, help="write elements every N steps")
parser.add_argument("--out", default="insitu-out")
parser.add_argument("--write-steps", default="")
args = parser.parse_args()

DIMS = (64, 32, 2)
BOUNDS = (0.0, 2.0, 0.0, 1.0, 0.0, 0.05)


def double_gyre(t):
    """The double gyre's velocity on the grid at time t (A = 0.1, eps = 0.25, omega = pi/5)."""
    a, eps, omega = 0.1, 0.25, math.pi / 5.0
    x = numpy.linspace(BOUNDS[0], BOUNDS[1], DIMS[0])
    y = numpy.linspace(BOUNDS[2], BOUNDS[3], DIMS[1])
    xx, yy = numpy.meshgrid(x, y, indexing="xy")
    at = eps * math.sin(omega * t)
    bt = 1.0 - 2.0 * eps * math.sin(omega * t)
    f = at * xx * xx + bt * xx
    dfdx = 2.0 * at * xx + bt
    u = -math.pi * a * numpy.sin(math.pi * f) * numpy.cos(math.pi * yy)
    v = math.pi * a * numpy.cos(math.pi * f) * numpy.sin(math.pi * yy) * dfdx
    layer = numpy.stack([u, v, numpy.zeros_like(u)], axis=-1).reshape(-1, 3)
    return numpy.concatenate([layer] * DIMS[2])


def grid_at(t):
    image = vtkImageData()
    image.SetDimensions(*DIMS)
    image.SetOrigin(BOUNDS[0], BOUNDS[2], BOUNDS[4])
    image.SetSpacing(*[(BOUNDS[2 * a + 1] - BOUNDS[2 * a]) / (DIMS[a] - 1) for a in range(3)])
    velocity = numpy_to_vtk(numpy.ascontiguousarray(double_gyre(t), dtype=numpy.float32), deep=1)
    velocity.SetName("velocity")
    image.GetPointData().AddArray(velocity)
    return image


os.makedirs(args.out, exist_ok=True)
os.environ["BOUNDPARTICLES_PLUGIN"] = args.plugin
os.environ["BOUNDPARTICLES_INSITU_OUT"] = os.path.abspath(args.out)
os.environ["BOUNDPARTICLES_INSITU_EVERY"] = str(args.every)
os.environ["BOUNDPARTICLES_INSITU_LAST"] = str(args.steps - 1)
bridge.initialize()
bridge.add_pipeline(os.path.join(os.path.dirname(os.path.abspath(__file__)), "trace_elements.py"), 2)
written = []
for step in range(args.steps):
    t = step * args.dt
    grid = grid_at(t)  # the solver's state at this step
    bridge.coprocess(t, step, grid, name="input", wholeExtent=[0, DIMS[0] - 1, 0, DIMS[1] - 1, 0, DIMS[2] - 1])
    if args.write_steps:
        from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
        os.makedirs(args.write_steps, exist_ok=True)
        writer = vtkXMLImageDataWriter()
        writer.SetInputData(grid)
        name = "flow_%04d.vti" % step
        writer.SetFileName(os.path.join(args.write_steps, name))
        writer.Write()
        written.append((t, name))
bridge.finalize()
if args.write_steps:
    with open(os.path.join(args.write_steps, "flow.pvd"), "w") as pvd:
        pvd.write('<VTKFile type="Collection" version="0.1"><Collection>\n')
        for t, name in written:
            pvd.write('<DataSet timestep="%.17g" file="%s"/>\n' % (t, name))
        pvd.write("</Collection></VTKFile>\n")
