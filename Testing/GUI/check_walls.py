# Run from the GUI's Python shell by walls.xml, after Boundary = Bounce and
# Restitution 0.5 were set in the panel and applied to a tracer whose
# uniform flow (1, 0.5, 0) carries every element into the side x = 1:
# checks the settings, that every particle at t = 2 is finite and in the
# field ([-1, 1]^3), that none was released again (each element's lifetime
# left is 98), and that the elements reached the wall. Only then does it set
# Coloring Axis to X, which walls.xml checks.
import gui_check
import numpy as np
from paraview import servermanager
from paraview.simple import FindSource
from vtkmodules.util.numpy_support import vtk_to_numpy

tracer = FindSource("BoundParticleTracer1")


def check():
    tracer.UpdatePipeline(2.0)
    data = servermanager.Fetch(tracer)
    points = vtk_to_numpy(data.GetPoints().GetData())
    left = vtk_to_numpy(data.GetPointData().GetArray("Lifetime"))
    found = {"Bounce": tracer.Boundary == "Bounce",
             "Restitution 0.5": abs(tracer.Restitution - 0.5) < 1e-12,
             "80 particles": len(points) == 80,
             "every particle finite": bool(np.all(np.isfinite(points))),
             "every particle in the field": float(np.abs(points).max()) <= 1.0 + 1e-6,
             "none released again": bool(np.allclose(left, 98.0, atol=1e-3)),
             "the wall reached": float(points[:, 0].max()) > 0.95}
    if gui_check.passed("check_walls", found, {"largest |x|": float(np.abs(points).max()),
                                               "lifetimes left": (float(left.min()),
                                                                  float(left.max()))}):
        tracer.ColoringAxis = "X"


gui_check.run("check_walls", check)
