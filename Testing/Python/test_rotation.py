"""Seeing rotation in the tracer's output: each element's pose and spin as
data, and motion trails, as pvpython users meet them.

- Orientation, ElementSpin and SpinVorticityRatio are off by default
  (the CPU engine then fits no poses); ticked, they are per element (the same
  on each of its particles), unit quaternions, and the paddlewheels of the
  shear layer spin about y at half the local vorticity -du/dz: the ratio
  reads 1, and the spin's sign follows the height.
- Trails: the output gains each element's past poses as cells whose points
  carry Age, up to Trail Length poses Trail Spacing steps apart, none of
  another generation; the Surface picture of demo/trails.py (Age mapped to
  colour and opacity) matches its baseline and differs from the picture
  without trails.
- The Bound Particles display (GPU engine) draws the same trails from the
  engine's ring: its picture of demo/trails.py is close to the CPU Surface
  picture, covers the trails' region, differs from its picture without
  trails, and matches its own baseline; with the colour map opaque the
  display fades the trails itself. Coloured by ElementSpin's Y component, it
  matches the CPU output drawn as Surface.
--update-baselines writes the baselines instead.
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
import picture  # noqa: E402
import trails  # noqa: E402

args = bptest.arguments("--baselines", "--output", "--update-baselines")
LoadPlugin(args.plugin, ns=globals())
LoadPlugin(args.plugin, ns=trails.__dict__)
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)
BASE_MEAN, BASE_PIXELS = 1.0, 0.005
# The GPU display against the CPU output drawn as Surface, as test_representation.py,
# trails included: with the colour map mapping opacity, the display fades them
# by the same map (measured on llvmpipe: mean 0.004, no pixel off by more
# than 32), so the colour tolerance holds; a pose missing or misplaced moves
# about as many pixels as the trails cover (without trails: 0.005).
CPU_MEAN, CPU_PIXELS = 0.5, 0.002
# The display's own fade, 1 - age / (span + interval), against the demo's
# opacity map, 1 - 0.575 age: alike by design (measured: mean 0.01, no pixel
# off by more than 32). Trails drawn opaque would move most of the pixels
# the trails cover; a tenth of them is allowed.
FADE_PIXELS = 0.0005


# --- Pose arrays ------------------------------------------------------------
flow = AnalyticFlow(Flow="Shear Layer", Resolution=[32, 32, 32])
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                             ElementShape="Paddlewheel", NumberOfElements=200, ElementSize=0.15,
                             EmitterCenter=[0, 0, 0], EmitterSize=[1.0, 1.0, 1.4],
                             Integrator="Runge-Kutta 4", RestorationIterations=4,
                             StepSizeUnit="Time", StepSize=0.02, Duration=1.0,
                             LifetimeRange=[100, 100], Seed=5)
data = bptest.fetch(tracer, 0.5)
for name in ("Orientation", "ElementSpin", "SpinVorticityRatio"):
    bptest.check(bptest.point_array(data, name) is None, "%s is off by default" % name)
tracer.OutputArrays = ["Orientation", "ElementSpin", "SpinVorticityRatio", "ElementId",
                       "Vorticity"]
data = bptest.fetch(tracer, 0.5)
q, spin = bptest.point_array(data, "Orientation"), bptest.point_array(data, "ElementSpin")
ratio, ids = bptest.point_array(data, "SpinVorticityRatio"), bptest.point_array(data, "ElementId")
points = vtk_to_numpy(data.GetPoints().GetData())
bptest.check(q is not None and q.shape[1] == 4, "Orientation has 4 components")
bptest.check(spin is not None and spin.shape[1] == 3, "ElementSpin has 3 components")
if q is not None and spin is not None and ratio is not None:
    bptest.check(np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-5), "unit quaternions")
    n = 8  # particles of a paddlewheel
    for values, name in ((q, "Orientation"), (spin, "ElementSpin"), (ratio, "ratio")):
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
data = bptest.fetch(trailed, trails.TIME)
age = bptest.point_array(data, "Age")
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
    ids = bptest.point_array(data, "ElementId")
    pts = vtk_to_numpy(data.GetPoints().GetData())
    now = pts[:n * E].reshape(E, n, 3).mean(axis=1)
    behind = all(pts[n * E + n * j: n * E + n * (j + 1)].mean(axis=0)[0] <
                 now[int(ids[n * E + n * j])][0] for j in range(poses))
    bptest.check(behind, "every trail pose lies upstream of its element")
bptest.check(np.all(np.isfinite(vtk_to_numpy(data.GetPoints().GetData()))), "finite points")

# Trails off: the elements alone, no Age.
trailed.Trails = 0
plain = bptest.fetch(trailed, trails.TIME)
bptest.check(plain.GetNumberOfPoints() == n * E and bptest.point_array(plain, "Age") is None,
             "without trails: %d points, Age %s" %
             (plain.GetNumberOfPoints(), bptest.point_array(plain, "Age") is not None))


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
bptest.check_baseline(with_trails, args.baselines, "Trails_Surface", args.update_baselines,
                      BASE_MEAN, BASE_PIXELS)


def keep_baseline(image, name):
    bptest.check_baseline(image, args.baselines, name, args.update_baselines, BASE_MEAN,
                          BASE_PIXELS)


# --- Trails in the Bound Particles display ------------------------------------
flow_g, gpu_trailed = trails.trails_scene(engine="GPU")


def display_trails_picture(path, with_trails, opacity_mapping=True, cpu=False):
    """demo/trails.py's picture of the GPU trace (or the CPU one) in the Bound
    Particles display."""
    flow, tracer = (flow_t, trailed) if cpu else (flow_g, gpu_trailed)
    tracer.Trails = 1 if with_trails else 0
    view = picture.dark_view(trails.TIME, (480, 270))
    view.EnableRenderOnInteraction = 0
    Show(flow, view).SetRepresentationType("Outline")
    display = trails.show_trails(tracer, view, "Bound Particles")
    lut = GetColorTransferFunction("Age")
    lut.EnableOpacityMapping = 1 if opacity_mapping else 0
    trails.place_camera(view)
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[480, 270])
    lut.EnableOpacityMapping = 1
    Delete(display)
    Delete(view)


def pixels_of(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(np.int32)
    return values.reshape(height, width, 3)


gpu_with = os.path.join(args.output, "Trails_BoundParticles.png")
gpu_without = os.path.join(args.output, "Trails_BoundParticles_off.png")
gpu_own_fade = os.path.join(args.output, "Trails_BoundParticles_fade.png")
display_trails_picture(gpu_with, True)
display_trails_picture(gpu_without, False)
display_trails_picture(gpu_own_fade, True, opacity_mapping=False)
mean, pixels = bptest.image_difference(with_trails, gpu_with)
bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
             "GPU trails vs CPU Surface trails: mean %.3f, pixels %.4f" % (mean, pixels))
print("GPU vs CPU trails: mean %.3f, pixels %.4f" % (mean, pixels))
mean, pixels = bptest.image_difference(gpu_with, gpu_without)
bptest.check(pixels > 0.002, "the GPU display's trails show: %.4f of the pixels differ" % pixels)
# Where the CPU picture has trail poses and no element (it differs from the
# picture without trails), the GPU picture is not background either.
cpu_on, cpu_off, gpu_on = pixels_of(with_trails), pixels_of(without), pixels_of(gpu_with)
background = gpu_on[0, 0]
trail_region = np.abs(cpu_on - cpu_off).max(axis=2) > 32
covered = (np.abs(gpu_on - background).max(axis=2) > 8)[trail_region].mean()
bptest.check(trail_region.sum() > 0 and covered > 0.98,
             "the GPU display covers the trails' region (%d pixels): %.4f" %
             (trail_region.sum(), covered))
# The colour map opaque: the display's own fade keeps the trails translucent,
# close to the demo's opacity map.
mean, pixels = bptest.image_difference(gpu_own_fade, gpu_with)
bptest.check(mean <= CPU_MEAN and pixels <= FADE_PIXELS,
             "the display's own fade vs the colour map's: mean %.3f, pixels %.4f" %
             (mean, pixels))
mean, pixels = bptest.image_difference(gpu_own_fade, gpu_without)
bptest.check(pixels > 0.002, "the display's own fade shows the trails: %.4f" % pixels)
# The CPU engine in the same display fades its trails the same way, the
# colour map opaque or mapping opacity; a Surface display would not.
cpu_own_fade = os.path.join(args.output, "Trails_BoundParticles_cpu_fade.png")
cpu_mapped = os.path.join(args.output, "Trails_BoundParticles_cpu.png")
display_trails_picture(cpu_own_fade, True, opacity_mapping=False, cpu=True)
display_trails_picture(cpu_mapped, True, cpu=True)
mean, pixels = bptest.image_difference(cpu_own_fade, gpu_own_fade)
bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
             "the display's own fade, CPU vs GPU engine: mean %.3f, pixels %.4f" % (mean, pixels))
print("own fade, CPU vs GPU engine: mean %.3f, pixels %.4f" % (mean, pixels))
mean, pixels = bptest.image_difference(cpu_mapped, with_trails)
bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
             "CPU display vs CPU Surface, opacity mapped: mean %.3f, pixels %.4f" % (mean, pixels))
# Output Arrays cut to what is drawn (no Age): the trails still fade (Age
# comes with Trails), the same picture as with Age ticked.
def solid_trails_picture(path, arrays):
    trailed.OutputArrays = arrays
    trailed.Trails = 1
    view = picture.dark_view(trails.TIME, (480, 270))
    view.EnableRenderOnInteraction = 0
    display = Show(trailed, view)
    display.SetRepresentationType("Bound Particles")
    ColorBy(display, ("POINTS", None))
    trails.place_camera(view)
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[480, 270])
    Delete(display)
    Delete(view)


kept_arrays = list(trailed.OutputArrays)
trailed.OutputArrays = ["Normals"]
trailed.UpdatePipeline(trails.TIME)
bptest.check(servermanager.Fetch(trailed).GetPointData().GetArray("Age") is not None,
             "Age comes with Trails whatever Output Arrays holds")
cut = os.path.join(args.output, "Trails_BoundParticles_cpu_cut.png")
ticked = os.path.join(args.output, "Trails_BoundParticles_cpu_age.png")
solid_trails_picture(cut, ["Normals"])
solid_trails_picture(ticked, ["Normals", "Age"])
mean, pixels = bptest.image_difference(cut, ticked)
bptest.check(mean < 0.01 and pixels == 0.0,
             "without Age ticked the CPU trails fade as with it: mean %.3f, pixels %.4f" %
             (mean, pixels))
trailed.OutputArrays = kept_arrays
keep_baseline(gpu_with, "Trails_BoundParticles")
Delete(gpu_trailed)
Delete(flow_g)


# --- Colouring the display by spin --------------------------------------------
def spin_picture(source, representation, name, color, component, scalar_range):
    """The shear layer's paddlewheels coloured by `color` (its `component`, or
    None for a scalar), in the camera and colours test_representation.py uses."""
    view = bptest.element_view((320, 240))
    view.ViewTime = 0.5
    shown = Show(source, view)
    shown.SetRepresentationType(representation)
    ColorBy(shown, ("POINTS", color))
    lut = GetColorTransferFunction(color)
    lut.ApplyPreset("Cool to Warm", True)
    if component is not None:
        lut.VectorMode = "Component"
        lut.VectorComponent = component
    lut.RescaleTransferFunction(*scalar_range)
    shown.Specular = 0.3
    Render(view)
    path = os.path.join(args.output, name + ".png")
    SaveScreenshot(path, view)
    Delete(shown)
    Delete(view)
    return path


def spin_tracer(engine):
    t = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                            ElementShape="Paddlewheel", NumberOfElements=60, ElementSize=0.15,
                            EmitterCenter=[0, 0, 0], EmitterSize=[1.0, 1.0, 1.4],
                            Integrator="Runge-Kutta 4", RestorationIterations=4,
                            StepSizeUnit="Time", StepSize=0.02, Duration=1.0,
                            LifetimeRange=[100, 100], Seed=5, Engine=engine)
    t.OutputArrays = ["Orientation", "ElementSpin", "SpinVorticityRatio", "Normals"]
    return t


cpu_spin, gpu_spin = spin_tracer("CPU"), spin_tracer("GPU")
# Spin about y is -z here; the ratio reads about 1; the pose's w is the cosine
# of half the turn from the template (the wheels start randomly oriented).
for color, component, scalar_range, name in (
        ("ElementSpin", 1, (-0.7, 0.7), "Spin"),
        ("SpinVorticityRatio", None, (0.0, 2.0), "SpinRatio"),
        ("Orientation", 3, (-1.0, 1.0), "OrientationW")):
    cpu_image = spin_picture(cpu_spin, "Surface", name + "_Surface", color, component,
                             scalar_range)
    gpu_image = spin_picture(gpu_spin, "Bound Particles", name + "_BoundParticles", color,
                             component, scalar_range)
    mean, pixels = bptest.image_difference(cpu_image, gpu_image)
    bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
                 "%s: GPU vs CPU differ: mean %.3f, pixels %.4f" % (name, mean, pixels))
    bptest.check(bptest.covered_fraction(gpu_image) > 0.005,
                 "%s: the picture shows elements (%.4f)" %
                 (name, bptest.covered_fraction(gpu_image)))
    print("%s: GPU vs CPU mean %.3f, pixels %.4f" % (name, mean, pixels))

bptest.finish()
