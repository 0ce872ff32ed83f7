# Run from the GUI's Python shell by walls.xml, after Periodic's x field was
# set to 1 and Boundary to Slip in the panel and applied to check_walls.py's
# tracer (a uniform flow (1, 0.5, 0) on [-1, 1]^3, elements released near the
# centre): at t = 2 every element has travelled one period (2) along x, so
# each particle is back near its start in x, while the Slip side y = 1 holds
# them; every particle finite and in the field, none released again. Without
# Periodic they would all lie on the side x = 1. Only then does it set
# Coloring Axis to Y, which walls.xml checks.
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
    found = {"Periodic x": list(tracer.Periodic) == [1, 0, 0],
             "Slip": tracer.Boundary == "Slip",
             "80 particles": len(points) == 80,
             "every particle finite": bool(np.all(np.isfinite(points))),
             "every particle in the field": float(np.abs(points).max()) <= 1.0 + 1e-6,
             "none released again": bool(np.allclose(left, 98.0, atol=1e-3)),
             "back near the start in x": float(np.abs(points[:, 0]).max()) < 0.5,
             "held by the side y = 1": float(points[:, 1].max()) > 0.95}
    if gui_check.passed("check_periodic", found, {"x from": float(points[:, 0].min()),
                                                  "x to": float(points[:, 0].max()),
                                                  "largest y": float(points[:, 1].max())}):
        tracer.ColoringAxis = "Y"


gui_check.run("check_periodic", check)
