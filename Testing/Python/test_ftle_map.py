"""ElementStretch, ElementFTLE and the FTLE map, against an FTLE computed
independently (demo/ftle_map.py holds both the scene and the reference).

- ElementStretch and ElementFTLE are off by default; ticked, they are per
  element (the same on each of its particles), finite, the stretches ordered
  and positive, and ElementFTLE = ln(largest stretch) / age.
- The double gyre (A 0.1, epsilon 0.25, period 10) traced to T = 10 with
  spring-free crosses released on a lattice: their ElementFTLE, at the points
  they were released from, against numpy's finite differences of the flow map
  (RK4 through the same sampled field): correlation > 0.95, the ridges (top
  10%) shared > 90%, median relative difference < 2% where the FTLE exceeds
  a third of its largest. Against the analytic formula itself (not its
  samples) the same ridges, more loosely.
- The tracer's second output: with Release Pattern = Lattice the FTLE map,
  an image at the lattice over the emitter box, compared the same way;
  otherwise an empty image, with no warning.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "demo"))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
import ftle_map  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())
LoadPlugin(args.plugin, ns=ftle_map.__dict__)
paraview.simple._DisableFirstRenderCameraReset()
COUNTS = (60, 30)


def report(label, stats):
    print("%s: %s" % (label, ", ".join("%s %.4g" % kv for kv in sorted(stats.items()))))


def check_maps(label, elements, reference, valid, tight=True):
    stats = ftle_map.compare(elements, reference, valid)
    report(label, stats)
    bptest.check(stats["points"] == len(valid), "%s: %d of %d points valid" %
                 (label, stats["points"], len(valid)))
    bptest.check(stats["correlation"] > (0.95 if tight else 0.9),
                 "%s: correlation %.3f" % (label, stats["correlation"]))
    bptest.check(stats["ridge_overlap"] > (0.9 if tight else 0.75),
                 "%s: ridges overlap %.3f" % (label, stats["ridge_overlap"]))
    bptest.check(stats["median_relative_error"] < (0.02 if tight else 0.1),
                 "%s: median relative difference %.4f" % (label, stats["median_relative_error"]))


# Off by default.
flow = AnalyticFlow(Flow="Shear Layer", Resolution=[12, 12, 12])
flow.UpdatePipeline()
plain = BoundParticleTracer(Input=flow, NumberOfElements=5)
bptest.check("ElementFTLE" not in list(plain.OutputArrays) and
             "ElementStretch" not in list(plain.OutputArrays),
             "ElementFTLE and ElementStretch are off by default: %s" % list(plain.OutputArrays))

# Seed points on the lattice: element e at point e, the map from port 0.
with bptest.CapturedMessages() as messages:
    gyre, tracer = ftle_map.gyre_scene(counts=COUNTS, lattice=False)
    points, elements, reference, valid, (field, times) = ftle_map.both_maps(gyre, tracer, COUNTS)
    data = servermanager.Fetch(tracer)
    empty = servermanager.Fetch(tracer, 0, None, 1)
bptest.check(not messages.messages, "no warnings: %s" % messages.messages[:3])
check_maps("seeded elements against numpy (sampled field)", elements, reference, valid)
analytic = ftle_map.reference_ftle(field, times, points, ftle_map.T, ftle_map.SIZE / 2,
                                   sample=ftle_map.analytic_velocity)
check_maps("seeded elements against numpy (analytic formula)", elements, analytic, valid,
           tight=False)
bptest.check(empty.GetNumberOfPoints() == 0,
             "without a lattice release the FTLE map is empty (%d points)" %
             empty.GetNumberOfPoints())

# Per element, consistent with each other.
pd = data.GetPointData()
ftle = vtk_to_numpy(pd.GetArray("ElementFTLE")).astype(np.float64)
stretch = vtk_to_numpy(pd.GetArray("ElementStretch")).astype(np.float64)
ids = vtk_to_numpy(pd.GetArray("ElementId"))
bptest.check(np.isfinite(ftle).all() and np.isfinite(stretch).all(), "finite values")
bptest.check((stretch[:, 0] >= stretch[:, 1]).all() and (stretch[:, 1] > 0).all(),
             "stretches ordered and positive")
same = all(np.ptp(ftle[ids == e]) == 0 and np.ptp(stretch[ids == e, 0]) == 0
           for e in np.unique(ids)[:50])
bptest.check(same, "one value per element on all its particles")
# Every element is of generation 0 (lifetime 20 > T): its age is T.
consistent = np.abs(np.log(stretch[:, 0]) / ftle_map.T - ftle).max()
print("ElementFTLE against ln(ElementStretch[0]) / T: largest difference %.3g" % consistent)
# (the age is the drawn lifetime less the remaining one, in float steps)
bptest.check(consistent < 1e-4, "ElementFTLE is ln(largest stretch) / age: off by %g" % consistent)
# A free cross in an incompressible 2D flow keeps its area: stretches multiply to 1.
area = np.abs(stretch[:, 0] * stretch[:, 1] - 1.0)
print("largest stretch * smallest stretch - 1: median %.3g" % np.median(area))
bptest.check(np.median(area) < 0.01, "area kept: median |s1 s2 - 1| %g" % np.median(area))

# The FTLE map of a Lattice release (port 1).
gyre2, lattice = ftle_map.gyre_scene(counts=COUNTS, lattice=True)
with bptest.CapturedMessages() as messages:
    points2, map_values, reference2, valid2, _ = ftle_map.both_maps(gyre2, lattice, COUNTS)
bptest.check(not messages.messages, "no warnings: %s" % messages.messages[:3])
image = servermanager.Fetch(lattice, 0, None, 1)
dims = image.GetDimensions()
print("FTLE map: dimensions %s, origin %s, spacing %s" %
      (dims, image.GetOrigin(), image.GetSpacing()))
bptest.check(tuple(dims) == (COUNTS[0], COUNTS[1], 1), "map dimensions %s" % (dims,))
bptest.check(np.allclose(points2, ftle_map.lattice_points(COUNTS), atol=1e-6),
             "the map's points are the lattice's, in world coordinates")
check_maps("FTLE map against numpy (sampled field)", map_values, reference2, valid2)
bptest.check(np.abs(map_values - elements).max() < 1e-4,
             "the map is the seeded elements' ElementFTLE (off by %g)" %
             np.abs(map_values - elements).max())

# The map through consumers, as the GUI meets it: its whole extent is the
# lattice's before any trace, so a filter or a view asks for its points.
T = ftle_map.T
map_port = OutputPort(lattice, 1)
bptest.check(lattice.GetDataInformation(1).GetExtent() == (0, COUNTS[0] - 1, 0, COUNTS[1] - 1,
                                                            0, 0),
             "the map's extent in its information: %s" %
             (lattice.GetDataInformation(1).GetExtent(),))
shrunk = Shrink(Input=map_port)
shrunk.UpdatePipeline(T)
cells = (COUNTS[0] - 1) * (COUNTS[1] - 1)
bptest.check(shrunk.GetDataInformation().GetNumberOfCells() == cells,
             "Shrink of the map has its %d cells: %d" %
             (cells, shrunk.GetDataInformation().GetNumberOfCells()))
contour = Contour(Input=map_port, ContourBy=["POINTS", "FTLE"],
                  Isosurfaces=[0.5 * float(map_values.max())])
contour.UpdatePipeline(T)
bptest.check(contour.GetDataInformation().GetNumberOfPoints() > 50,
             "a contour of the map's FTLE has points: %d" %
             contour.GetDataInformation().GetNumberOfPoints())
cut = Slice(Input=map_port)
cut.SliceType.Origin = [1.0, 0.5, 0.0]
cut.SliceType.Normal = [1.0, 0.0, 0.0]
cut.UpdatePipeline(T)
bptest.check(cut.GetDataInformation().GetNumberOfPoints() >= COUNTS[1] and
             "FTLE" in cut.PointData.keys(),
             "a slice across the map has a line of points with FTLE: %d" %
             cut.GetDataInformation().GetNumberOfPoints())
view = bptest.element_view((320, 200))
view.ViewTime = T
shown = Show(map_port, view)
shown.SetRepresentationType("Slice")
ColorBy(shown, ("POINTS", "FTLE"))
ResetCamera(view)
path = bptest.save_picture(view, os.environ.get("TMPDIR", "/tmp"), "ftle-map-shown")
covered = bptest.covered_fraction(path)
print("the map shown as a slice covers %.1f%% of the view" % (100 * covered))
bptest.check(covered > 0.1, "the map shown in a view draws: %.3f of the pixels" % covered)
map_time = map_port.GetDataInformation().DataInformation.GetTime()
bptest.check(map_time == T, "the map is stamped with the time shown (%s)" % map_time)

bptest.finish()
