# Run from the GUI's Python shell by release_patterns.xml after the panel set
# Release Pattern, Lattice Spacing or Release Weights and applied. When the
# tracer holds what was chosen and its elements start where that says, sets
# the Coloring Axis (X after the lattice, Y after the weights), which
# release_patterns.xml then checks.
import numpy

import gui_check
from paraview import servermanager
from paraview.simple import FindSource
from vtkmodules.util.numpy_support import vtk_to_numpy

tracer = FindSource("BoundParticleTracer1")
tracer.UpdatePipeline(tracer.TimestepValues[0])
data = servermanager.Fetch(tracer)
points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
points = points[numpy.argsort(ids, kind="stable")]
seen = {"pattern": tracer.ReleasePattern, "points": len(points)}
if tracer.ReleasePattern == "Lattice":
    found = {"spacing 0.5": tracer.LatticeSpacing == 0.5, "32 points": len(points) == 32}
    if len(points) == 32:
        # 8 x 4 cells of 0.5 on the 4 x 2 slice, points at their centres, x fastest.
        i = numpy.arange(32)
        expected = numpy.stack([0.25 + 0.5 * (i % 8), 0.25 + 0.5 * (i // 8),
                                numpy.full(32, 0.25)], axis=1)
        seen["largest offset"] = abs(points - expected).max()
        found["at the cell centres"] = seen["largest offset"] < 1e-5
    axis = 0
else:
    found = {"weighted by w": tracer.ReleaseWeights[1] == "w",
             "20000 points": len(points) == 20000}
    # Bin b of [0.4 b, 0.4 (b + 1)] takes (2 b + 1) / 100 of the releases.
    counts = numpy.histogram(points[:, 0], bins=10, range=(0.0, 4.0))[0]
    expected = numpy.array([(2 * b + 1) / 100.0 for b in range(10)]) * len(points)
    seen["chi-square"] = float(((counts - expected) ** 2 / expected).sum())
    found["spread as the weights"] = seen["chi-square"] < 27.9  # 9 degrees of freedom, 99.9%
    axis = 1
if gui_check.passed("check_release_patterns", found, seen):
    tracer.ColoringAxis = axis
