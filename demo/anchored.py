"""Probes held in place (the thesis's closing Eulerian view): a lattice of
anchored paddlewheels across the shear layer, each turning where it was
released at half the local vorticity, with the last poses of each fading
behind it, and free strips drifting through them from a second tracer on
the same input.

    pvpython demo/anchored.py --plugin BoundParticles.so --output docs
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import apply_preset, dark_view, picture_arguments, save_and_close  # noqa: E402

TIME = 1.2


def anchored_scene(engine="CPU"):
    """The shear layer; a 7 x 5 lattice of anchored paddlewheels in the
    x-z plane y = 0, axes along y, with trails; and free strips facing the
    camera, carried through them by a second tracer on the same input."""
    flow = AnalyticFlow(Flow="Shear Layer", Resolution=[48, 48, 48])
    flow.UpdatePipeline()
    common = dict(Input=flow, Vectors=["POINTS", "velocity"], Integrator="Runge-Kutta 4",
                  RestorationIterations=4, StepSizeUnit="Time", StepSize=0.04,
                  Duration=TIME, NumberOfTimeSteps=31, LifetimeRange=[100, 100],
                  Engine=engine)
    probes = BoundParticleTracer(ElementShape="Paddlewheel", NumberOfElements=35,
                                 ElementSize=0.2, ReleaseOrientation="Fixed",
                                 ElementRotation=[90.0, 0.0, 0.0], ReleasePattern="Lattice",
                                 EmitterCenter=[0.0, 0.0, 0.0], EmitterSize=[1.75, 0.0, 1.25],
                                 Anchor="Centre", Trails=1, TrailLength=6, TrailSpacing=4,
                                 OutputArrays=["ElementSpin"], **common)
    drifters = BoundParticleTracer(ElementShape="Strip8", NumberOfElements=60,
                                   ElementSize=0.15, ReleaseOrientation="Fixed",
                                   ElementRotation=[90.0, 0.0, 0.0],
                                   EmitterCenter=[-0.6, 0.0, 0.0],
                                   EmitterSize=[0.6, 0.6, 1.6], Seed=3, **common)
    return flow, probes, drifters


def show_probes(probes, view):
    """Coloured by the spin about y: blue one way, red the other, grey still
    (the trails' past poses fan out behind each wheel as it turns)."""
    display = Show(probes, view)
    ColorBy(display, ("POINTS", "ElementSpin", "Y"))
    lut = GetColorTransferFunction("ElementSpin")
    apply_preset(lut, "Cool to Warm")
    lut.VectorMode = "Component"
    lut.VectorComponent = 1
    lut.RescaleTransferFunction(-0.6, 0.6)
    display.Specular = 0.3
    return display


def main():
    args = picture_arguments(__doc__)
    LoadPlugin(args.plugin, ns=globals())
    flow, probes, drifters = anchored_scene()
    view = dark_view(TIME)
    view.EnableRenderOnInteraction = 0
    Show(flow, view).SetRepresentationType("Outline")
    show_probes(probes, view)
    free = Show(drifters, view)
    free.AmbientColor = free.DiffuseColor = [0.85, 0.85, 0.8]
    ColorBy(free, None)
    free.Opacity = 0.6
    view.CameraPosition = [0.0, -5.0, 0.4]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    save_and_close(view, os.path.join(args.output, "anchored.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
