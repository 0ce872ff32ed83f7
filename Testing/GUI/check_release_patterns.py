# Run from the GUI's Python shell by release_patterns.xml after the panel set
# Release Pattern, Lattice Spacing or Release Weights and applied. When the
# tracer holds what was chosen and its elements start where that says, sets
# the Coloring Axis (X after the lattice, Y after the weights), which
# release_patterns.xml then checks.
import numpy

from paraview import servermanager
from paraview.simple import FindSource
from vtkmodules.util.numpy_support import vtk_to_numpy

tracer = FindSource("BoundParticleTracer1")
tracer.UpdatePipeline(tracer.TimestepValues[0])
data = servermanager.Fetch(tracer)
points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
points = points[numpy.argsort(ids, kind="stable")]
if tracer.ReleasePattern == "Lattice" and tracer.LatticeSpacing == 0.5 and len(points) == 32:
    # 8 x 4 cells of 0.5 on the 4 x 2 slice, points at their centres, x fastest.
    i = numpy.arange(32)
    expected = numpy.stack([0.25 + 0.5 * (i % 8), 0.25 + 0.5 * (i // 8), numpy.full(32, 0.25)],
                           axis=1)
    if abs(points - expected).max() < 1e-5:
        tracer.ColoringAxis = 0
elif (tracer.ReleasePattern == "Random" and tracer.ReleaseWeights[1] == "w"
      and len(points) == 20000):
    # Bin b of [0.4 b, 0.4 (b + 1)] takes (2 b + 1) / 100 of the releases.
    counts = numpy.histogram(points[:, 0], bins=10, range=(0.0, 4.0))[0]
    expected = numpy.array([(2 * b + 1) / 100.0 for b in range(10)]) * len(points)
    chi = float(((counts - expected) ** 2 / expected).sum())
    if chi < 27.9:  # 9 degrees of freedom, 99.9%
        tracer.ColoringAxis = 1
