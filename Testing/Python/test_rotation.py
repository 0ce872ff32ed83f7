"""Seeing rotation in the tracer's output: each element's pose and spin as
data, and motion trails, as pvpython users meet them.

- ElementOrientation, ElementSpin and SpinVorticityRatio are off by default
  (the CPU engine then fits no poses); ticked, they are per element (the same
  on each of its particles), unit quaternions, and the paddlewheels of the
  shear layer spin about y at half the local vorticity -du/dz: the ratio
  reads 1, and the spin's sign follows the height.
- Trails: the output gains each element's past poses as cells whose points
  carry Age, up to Trail Length poses Trail Spacing steps apart, none of
  another generation; the Surface picture of demo/trails.py (Age mapped to
  colour and opacity) matches its baseline and differs from the picture
  without trails. --update-baselines writes the baseline instead.
"""
import os
import shutil
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
import picture  # noqa: E402
import trails  # noqa: E402

args = bptest.arguments("--baselines", "--output", "--update-baselines")
LoadPlugin(args.plugin, ns=globals())
LoadPlugin(args.plugin, ns=trails.__dict__)
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)
BASE_MEAN, BASE_PIXELS = 1.0, 0.005


def fetch(proxy, time):
    proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def array(data, name):
    a = data.GetPointData().GetArray(name)
    return None if a is None else vtk_to_numpy(a)


# --- Pose arrays ------------------------------------------------------------
flow = AnalyticFlow(Flow="Shear Layer", Resolution=[32, 32, 32])
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                             ElementShape="Paddlewheel", NumberOfElements=200, ElementSize=0.15,
                             EmitterCenter=[0, 0, 0], EmitterSize=[1.0, 1.0, 1.4],
                             Integrator="Runge-Kutta 4", RestorationIterations=4,
                             StepSizeUnit="Time", StepSize=0.02, Duration=1.0,
                             LifetimeRange=[100, 100], Seed=5)
data = fetch(tracer, 0.5)
for name in ("ElementOrientation", "ElementSpin", "SpinVorticityRatio"):
    bptest.check(array(data, name) is None, "%s is off by default" % name)
tracer.OutputArrays = ["ElementOrientation", "ElementSpin", "SpinVorticityRatio", "ElementId",
                       "Vorticity"]
data = fetch(tracer, 0.5)
q, spin = array(data, "ElementOrientation"), array(data, "ElementSpin")
ratio, ids = array(data, "SpinVorticityRatio"), array(data, "ElementId")
points = vtk_to_numpy(data.GetPoints().GetData())
bptest.check(q is not None and q.shape[1] == 4, "ElementOrientation has 4 components")
bptest.check(spin is not None and spin.shape[1] == 3, "ElementSpin has 3 components")
if q is not None and spin is not None and ratio is not None:
    bptest.check(np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-5), "unit quaternions")
    n = 8  # particles of a paddlewheel
    for values, name in ((q, "ElementOrientation"), (spin, "ElementSpin"), (ratio, "ratio")):
        per = values.reshape(len(values) // n, n, -1)
        bptest.check(np.all(per == per[:, :1]), "%s is the same on every particle" % name)
    centers = points.reshape(-1, n, 3).mean(axis=1)
    s = spin[::n]
    r = ratio[::n]
    z = centers[:, 2]
    # du/dz = -2z: the vorticity is (0, -2z, 0), a paddlewheel spins at (0, -z, 0).
    strong = np.abs(z) > 0.3
    expected = -z[strong]
    bptest.check(np.median(np.abs(s[strong, 1] - expected) / np.abs(expected)) < 0.1,
                 "spin about y is half the vorticity: median relative error %.3f" %
                 np.median(np.abs(s[strong, 1] - expected) / np.abs(expected)))
    bptest.check(np.median(np.abs(s[strong][:, [0, 2]])) < 0.05 * np.median(np.abs(expected)),
                 "no spin about x or z")
    bptest.check(abs(np.median(r[strong]) - 1.0) < 0.1,
                 "SpinVorticityRatio reads 1: median %.3f" % np.median(r[strong]))
Delete(tracer)

# --- Trails -------------------------------------------------------------------
flow_t, trailed = trails.trails_scene()
spacing, length = trailed.TrailSpacing, trailed.TrailLength
trailed.OutputArrays = ["Age", "ElementId", "Force", "Normals"]
data = fetch(trailed, trails.TIME)
age = array(data, "Age")
n, E = 8, 4
bptest.check(age is not None, "Age is in the output with Trails on")
if age is not None:
    poses = (len(age) - n * E) // n
    dt = 0.04
    bptest.check(poses == length * E, "every element shows %d poses: %d" % (length, poses))
    bptest.check(np.all(age[:n * E] == 0), "Age is 0 on the elements")
    expected = sorted(set(np.round(dt * spacing * np.arange(1, length + 1), 6)))
    got = sorted(set(np.round(age[n * E:].astype(float), 6)))
    bptest.check(np.allclose(got, expected, atol=1e-4), "trail ages %s, expected %s" %
                 (got, expected))
    bptest.check(data.GetNumberOfCells() == (1 + length) * E * 4,
                 "4 cells a pose: %d" % data.GetNumberOfCells())
    # A trail pose is its element's: same id, and it lies behind the element (the flow is +x).
    ids = array(data, "ElementId")
    pts = vtk_to_numpy(data.GetPoints().GetData())
    now = pts[:n * E].reshape(E, n, 3).mean(axis=1)
    behind = all(pts[n * E + n * j: n * E + n * (j + 1)].mean(axis=0)[0] <
                 now[int(ids[n * E + n * j])][0] for j in range(poses))
    bptest.check(behind, "every trail pose lies upstream of its element")
bptest.check(np.all(np.isfinite(vtk_to_numpy(data.GetPoints().GetData()))), "finite points")

# Trails off: the elements alone, no Age.
trailed.Trails = 0
plain = fetch(trailed, trails.TIME)
bptest.check(plain.GetNumberOfPoints() == n * E and array(plain, "Age") is None,
             "without trails: %d points, Age %s" %
             (plain.GetNumberOfPoints(), array(plain, "Age") is not None))


def trails_picture(path, with_trails):
    trailed.Trails = 1 if with_trails else 0
    view = picture.dark_view(trails.TIME, (480, 270))
    Show(flow_t, view).SetRepresentationType("Outline")
    trails.show_trails(trailed, view)
    trails.place_camera(view)
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[480, 270])
    Delete(view)


with_trails = os.path.join(args.output, "Trails_Surface.png")
without = os.path.join(args.output, "Trails_Surface_off.png")
trails_picture(with_trails, True)
trails_picture(without, False)
mean, pixels = bptest.image_difference(with_trails, without)
bptest.check(pixels > 0.002, "the trails show: %.4f of the pixels differ" % pixels)
baseline = os.path.join(args.baselines, "Trails_Surface.png")
if args.update_baselines:
    shutil.copyfile(with_trails, baseline)
elif not os.path.exists(baseline):
    bptest.check(False, "no baseline %s (the image is %s)" % (baseline, with_trails))
else:
    mean, pixels = bptest.image_difference(baseline, with_trails)
    bptest.check(mean <= BASE_MEAN and pixels <= BASE_PIXELS,
                 "trails differ from the baseline: mean %.3f, pixels %.4f" % (mean, pixels))

bptest.finish()
