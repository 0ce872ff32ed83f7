# Run from the GUI's Python shell by inertia.xml, after Inertia = Maxey-Riley,
# Response Time 0.05, Density Ratio 2.65 and Gravity 0 0 -4 were set in the
# panel and applied to a tracer on a uniform flow: checks the settings and
# that every particle's SlipVelocity at t = 0.5 is the terminal velocity
# tau (1 - beta) g within 1%. Only then does it set Coloring Axis to X, which
# inertia.xml checks.
import math

import gui_check
from paraview import servermanager
from paraview.simple import FindSource
from vtkmodules.util.numpy_support import vtk_to_numpy

tracer = FindSource("BoundParticleTracer1")


def check():
    tracer.UpdatePipeline(0.5)
    slip = vtk_to_numpy(servermanager.Fetch(tracer).GetPointData().GetArray("SlipVelocity"))
    beta = 3.0 / (1.0 + 2.0 * 2.65)
    terminal = 0.05 * (1.0 - beta) * -4.0 * (1.0 - math.exp(-0.5 / 0.05))
    worst = float(abs(slip[:, 2] - terminal).max())
    found = {"Maxey-Riley": tracer.Inertia == "Maxey-Riley",
             "Response Time 0.05": abs(tracer.ResponseTime - 0.05) < 1e-12,
             "Density Ratio 2.65": abs(tracer.DensityRatio - 2.65) < 1e-12,
             "Gravity 0 0 -4": list(tracer.Gravity) == [0, 0, -4],
             "20 particles": len(slip) == 20,
             "terminal velocity within 1%": worst < 0.01 * abs(terminal)}
    if gui_check.passed("check_inertia", found, {"slip off by": worst, "terminal": terminal}):
        tracer.ColoringAxis = "X"


gui_check.run("check_inertia", check)
