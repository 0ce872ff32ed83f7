"""The Bound Particles display (GPU engine) coloured by ElementStretch and
ElementFTLE, against the CPU output drawn as Surface over the same trace.

The double gyre traced to t = 6 with spring-free crosses (Restoration
Iterations 0) of lifetimes drawn in [2.5, 9]: the elements stretch along the
gyres' manifolds, and those released again (new generations, younger) have
their own ages, so ElementFTLE = ln(largest stretch) / age exercises the
lifetime draw as well as the fit. For each colouring (ElementStretch's
largest and smallest stretch and its magnitude, ElementFTLE) over the CPU
output's 5th to 95th percentile, the display's picture matches the CPU
Surface's within the tolerance of test_rotation.py's colour comparisons,
shows the elements, and differs from the same display drawn solid (a
colouring that read a constant would be caught by the first check, one that
drew nothing by the others).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments("--output")
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)
# As test_rotation.py's GPU display against the CPU Surface (llvmpipe).
CPU_MEAN, CPU_PIXELS = 0.5, 0.002
T = 6.0

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[129, 65, 2],
                    Bounds=[0.0, 2.0, 0.0, 1.0, -0.01, 0.01],
                    NumberOfTimeSteps=int(round(T / 0.5)) + 1)
flow.UpdatePipeline(0.0)


def gyre_tracer(engine):
    t = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                            ElementShape="Cross", RestorationIterations=0,
                            NumberOfElements=150, ElementSize=0.06,
                            EmitterCenter=[1.0, 0.5, 0.0], EmitterSize=[1.8, 0.8, 0.0],
                            ReleaseOrientation="Fixed", Integrator="Runge-Kutta 4",
                            StepSizeUnit="Time", StepSize=0.05, Duration=T,
                            LifetimeRange=[2.5, 9.0], MinimumReleaseSpeed=0.0, Seed=3,
                            Engine=engine)
    t.OutputArrays = ["ElementStretch", "ElementFTLE", "ElementId", "Normals"]
    return t


def picture(source, representation, name, color, component, scalar_range):
    """The gyres from above, the elements coloured by `color` (its
    `component`, -1 the magnitude, None a scalar) or solid (`color` None)."""
    view = CreateRenderView(ViewSize=[400, 220])
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.15]
    view.CameraPosition = [1.0, 0.5, 2.6]
    view.CameraFocalPoint = [1.0, 0.5, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30
    view.ViewTime = T
    shown = Show(source, view)
    shown.SetRepresentationType(representation)
    if color:
        ColorBy(shown, ("POINTS", color))
        lut = GetColorTransferFunction(color)
        lut.ApplyPreset("Cool to Warm", True)
        if component is not None:
            lut.VectorMode = "Magnitude" if component < 0 else "Component"
            lut.VectorComponent = max(component, 0)
        lut.RescaleTransferFunction(*scalar_range)
    else:
        ColorBy(shown, ("POINTS", None))
        shown.DiffuseColor = [0.9, 0.85, 0.7]
    Render(view)
    path = os.path.join(args.output, name + ".png")
    SaveScreenshot(path, view)
    Delete(shown)
    Delete(view)
    return path


cpu, gpu = gyre_tracer("CPU"), gyre_tracer("GPU")
cpu.UpdatePipeline(T)
data = servermanager.Fetch(cpu)
stretch = vtk_to_numpy(data.GetPointData().GetArray("ElementStretch")).astype(np.float64)
ftle = vtk_to_numpy(data.GetPointData().GetArray("ElementFTLE")).astype(np.float64)
ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
print("CPU: largest stretch %.3f to %.3f, smallest %.3f to %.3f, FTLE %.4f to %.4f" %
      (stretch[:, 0].min(), stretch[:, 0].max(), stretch[:, 1].min(), stretch[:, 1].max(),
       ftle.min(), ftle.max()))
# The trace must make the colourings vary, or the comparison proves nothing.
bptest.check(np.percentile(stretch[:, 0], 95) > 1.5 * np.percentile(stretch[:, 0], 5),
             "the largest stretch varies")
bptest.check(np.percentile(ftle, 95) > 2.0 * max(np.percentile(ftle, 5), 1e-3),
             "ElementFTLE varies")
# Some elements were released again: their age is not t.
young = np.abs(np.log(np.maximum(stretch[:, 0], 1e-6)) / T - ftle) > 1e-3
print("elements younger than the trace: %d of %d" % (len(np.unique(ids[young])),
                                                     len(np.unique(ids))))
bptest.check(young.any(), "some elements are of a later generation")


def spread(values):
    lo, hi = np.percentile(values, 5), np.percentile(values, 95)
    return (float(lo), float(hi if hi > lo else lo + 1.0))


solid = picture(gpu, "Bound Particles", "Solid_BoundParticles", None, None, None)
for color, component, values, name in (
        ("ElementStretch", 0, stretch[:, 0], "StretchLargest"),
        ("ElementStretch", 1, stretch[:, 1], "StretchSmallest"),
        ("ElementStretch", -1, np.hypot(stretch[:, 0], stretch[:, 1]), "StretchMagnitude"),
        ("ElementFTLE", None, ftle, "FTLE")):
    scalar_range = spread(values)
    cpu_image = picture(cpu, "Surface", name + "_Surface", color, component, scalar_range)
    gpu_image = picture(gpu, "Bound Particles", name + "_BoundParticles", color, component,
                        scalar_range)
    mean, pixels = bptest.image_difference(cpu_image, gpu_image)
    print("%s over [%.4g, %.4g]: GPU vs CPU mean %.3f, pixels %.4f" %
          (name, scalar_range[0], scalar_range[1], mean, pixels))
    bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
                 "%s: GPU vs CPU differ: mean %.3f, pixels %.4f" % (name, mean, pixels))
    covered = bptest.covered_fraction(gpu_image)
    bptest.check(covered > 0.005, "%s: the picture shows elements (%.4f)" % (name, covered))
    mean_solid, pixels_solid = bptest.image_difference(solid, gpu_image)
    print("%s: against the solid display mean %.3f, pixels %.4f" % (name, mean_solid,
                                                                     pixels_solid))
    bptest.check(pixels_solid > 10 * CPU_PIXELS,
                 "%s: the display is coloured, not solid (pixels %.4f)" % (name, pixels_solid))

bptest.finish()
