# Run from the GUI's Python shell by seeds.xml after a Seed Type was picked and
# set in the tracer's panel and applied. When the tracer holds what was typed
# and its elements start where those seeds are, sets the Coloring Axis (X
# after the Line, Y after the Point Cloud, Z after the Surface over a Plane
# connected as the Seed Source), which seeds.xml then checks.
import numpy

import gui_check
from paraview import servermanager
from paraview.simple import FindSource
from vtkmodules.util.numpy_support import vtk_to_numpy

tracer = FindSource("BoundParticleTracer1")
seeds = tracer.SeedType
tracer.UpdatePipeline(tracer.TimestepValues[0])
data = servermanager.Fetch(tracer)
points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
# At the start every element sits where it was released: its particles'
# mean is its seed point (releases take the seeds in order).
centres = numpy.array([points[ids == e].mean(axis=0) for e in range(50)])
kind = seeds.GetXMLLabel()
found = {"50 elements": len(numpy.unique(ids)) == 50}
if kind == "Line":
    found["line as typed"] = (list(seeds.Point1) == [-0.5, 0.0, 0.25]
                              and list(seeds.Point2) == [0.5, 0.0, 0.25]
                              and seeds.Resolution == 49)
    expected = numpy.linspace([-0.5, 0.0, 0.25], [0.5, 0.0, 0.25], 50)
    found["centres on the line's points"] = abs(centres - expected).max() < 1e-4
    axis = 0
elif kind == "Surface":
    # Over the Plane x = 0 (normal +x) across the shear layer, whose u_x =
    # 1.25 - z^2 is largest at mid-depth: 64% of the flux crosses |z| < 0.5.
    found["surface as typed"] = (seeds.NumberOfPoints == 500 and seeds.FlipNormals == 0
                                 and tracer.SeedSource.GetXMLName() == "PlaneSource")
    found["centres on the plane"] = (abs(centres[:, 0]).max() < 1e-4
                                     and abs(centres[:, 1]).max() <= 0.5 + 1e-4
                                     and abs(centres[:, 2]).max() <= 1.0 + 1e-4)
    # All 500 points, released by 500 elements (then 50 again): 64% (320, a
    # deviation of 11) in the middle half for the flux, 50% (250) for a
    # uniform spread; 285 parts them by 3 deviations each way.
    tracer.NumberOfElements = 500
    tracer.UpdatePipeline(tracer.TimestepValues[0])
    every = servermanager.Fetch(tracer)
    every_ids = vtk_to_numpy(every.GetPointData().GetArray("ElementId"))
    every_z = vtk_to_numpy(every.GetPoints().GetData()).astype(float)[:, 2]
    released = numpy.array([every_z[every_ids == e].mean() for e in numpy.unique(every_ids)])
    tracer.NumberOfElements = 50
    tracer.UpdatePipeline(tracer.TimestepValues[0])
    middle = int((abs(released) < 0.5).sum())
    found["more where the flux is higher (%d of %d)" % (middle, len(released))] = (
        len(released) == 500 and middle > 285)
    axis = 2
else:
    found["point cloud as typed"] = (kind == "Point Cloud"
                                     and list(seeds.Center) == [0.25, 0.0, 0.0]
                                     and seeds.Radius == 0.3 and seeds.NumberOfPoints == 60)
    distance = numpy.linalg.norm(centres - [0.25, 0.0, 0.0], axis=1)
    # Inside the sphere, spread through it (not all at its centre), and
    # every element at a point of its own.
    found["inside the sphere, spread"] = distance.max() <= 0.3 + 1e-4 and distance.max() > 0.15
    found["a point each"] = len(numpy.unique(centres.round(6), axis=0)) == 50
    axis = 1
if gui_check.passed("check_seed_types", found, {"seed type": kind}):
    tracer.ColoringAxis = axis
