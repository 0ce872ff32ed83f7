# Run from the GUI's Python shell by anchor.xml, after Anchor = Centre was
# picked in the panel and applied: checks that every element's centre stays
# where it was released over the first steps of the time line, then sets
# Anchor = None and checks that the elements drift with the shear layer.
# Only when both hold does it set Coloring Axis to X, which anchor.xml checks.
import gui_check
from paraview import servermanager
from paraview.simple import FindSource
from vtkmodules.util.numpy_support import vtk_to_numpy

tracer = FindSource("BoundParticleTracer1")
times = list(tracer.TimestepValues)


def centres(t):
    tracer.UpdatePipeline(t)
    data = servermanager.Fetch(tracer)
    points = vtk_to_numpy(data.GetPoints().GetData())
    return points.reshape(tracer.NumberOfElements, -1, 3).mean(axis=1)


def moved():
    first = centres(times[0])
    return max(float(abs(centres(t) - first).max()) for t in times[1:4])


def check():
    anchored = tracer.Anchor == "Centre"  # now: the property reads live
    held = moved()
    tracer.Anchor = "None"
    drift = moved()
    found = {"anchored at centres": anchored, "anchored centres held": held < 1e-5,
             "free centres drift": drift > 1e-3}
    if gui_check.passed("check_anchor", found, {"anchored move": held, "free drift": drift}):
        tracer.ColoringAxis = "X"


gui_check.run("check_anchor", check)
