"""Traces bound particles through the built-in hurricane-like flow and writes
a picture and the element data.

Run with pvpython (under xvfb-run on a machine without a display):
    pvpython demo/demo.py --plugin BoundParticles.so --output demo-output
"""
import argparse
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import dark_view  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--plugin", required=True, help="path of BoundParticles.so")
    parser.add_argument("--output", required=True, help="folder for the image and data")
    parser.add_argument("--time", type=float, default=2.0, help="simulation time to show")
    parser.add_argument("--elements", type=int, default=1200)
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    LoadPlugin(args.plugin, ns=globals())
    flow = AnalyticFlow(Flow="Hurricane", Resolution=[48, 48, 24], Bounds=[-1, 1, -1, 1, 0, 0.6])
    flow.UpdatePipeline()
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                 ElementShape="Strip16",
                                 NumberOfElements=args.elements, Seed=3)
    # Strips start upright in a slab around mid-height, so their folding and
    # turning show the vortex's shear; an element's height at release colours it.
    tracer.ElementSize = 0.18
    tracer.EmitterCenter = [0.0, 0.0, 0.3]
    tracer.EmitterSize = [1.6, 1.6, 0.3]
    tracer.ReleaseOrientation = "Fixed"
    tracer.ElementRotation = [90, 0, 0]
    tracer.Integrator = "Runge-Kutta 4"
    tracer.ResetWhen = "Any Particle Leaves"
    # A ten-second time line with lives of 5-10 s: at --time every strip is
    # still the one released at the start, so its colour is its release height.
    tracer.Duration = 10.0
    tracer.LifetimeRange = [5.0, 10.0]
    tracer.UpdatePipeline(args.time)

    view = dark_view(args.time)

    outline = Show(flow, view)
    outline.SetRepresentationType("Outline")
    outline.AmbientColor = outline.DiffuseColor = [0.6, 0.6, 0.65]

    display = Show(tracer, view)
    ColorBy(display, ("POINTS", "Layer"))
    lut = GetColorTransferFunction("Layer")
    lut.ApplyPreset("Turbo", True)
    display.Specular = 0.3
    bar = GetScalarBar(lut, view)
    bar.Title = "release height"
    bar.ComponentTitle = ""
    display.SetScalarBarVisibility(view, True)

    Render(view)  # the first render resets the camera; place it afterwards
    view.CameraPosition = [2.1, -2.35, 1.75]
    view.CameraFocalPoint = [0.0, 0.0, 0.2]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30
    Render(view)

    image = os.path.join(args.output, "bound-particles.png")
    data = os.path.join(args.output, "bound-particles.vtp")
    SaveScreenshot(image, view, ImageResolution=[1280, 720])
    SaveData(data, proxy=tracer)
    points = tracer.GetDataInformation().GetNumberOfPoints()
    print("demo: traced %d elements (%d particles) to t = %g" % (args.elements, points, args.time))
    print("demo: wrote %s" % image)
    print("demo: wrote %s" % data)

    # The same trace on the GPU engine: stepped and drawn in the render
    # window by the Bound Particles representation.
    lut.AutomaticRescaleRangeMode = "Never"
    tracer.Engine = "GPU"
    display.SetRepresentationType("Bound Particles")
    Render(view)
    gpu_image = os.path.join(args.output, "bound-particles-gpu.png")
    SaveScreenshot(gpu_image, view, ImageResolution=[1280, 720])
    print("demo: wrote %s (GPU engine)" % gpu_image)

    # Views must go before the interpreter exits, or pvpython may crash on exit.
    Delete(view)
    del view
    return 0


if __name__ == "__main__":
    sys.exit(main())
