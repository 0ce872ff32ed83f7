"""Motion trails (thesis §4.3's "portray the motion in still images"):
paddlewheels in two rows across the shear layer, each with its last poses
fading behind it, so one still picture shows the upper row turning one way
and the lower row the other, at half the local vorticity.

    pvpython demo/trails.py --plugin BoundParticles.so --output docs
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import apply_preset, dark_view, picture_arguments, save_and_close  # noqa: E402

TIME = 1.6


def seed_column(z_values):
    """A seed point at x = -0.9, y = 0 for each height in `z_values`."""
    points = []
    for z in z_values:
        points += [-0.9, 0.0, z]
    return PolyLineSource(Points=points)


def trails_scene(engine="CPU"):
    """The shear layer and a tracer of 4 paddlewheels at heights 0.8, 0.5,
    -0.5 and -0.8, their axes along y, with trails (8 poses, every 5 steps
    of 0.04): they turn about y at half the vorticity du/dz = -2z, so the
    upper two turn against the lower two."""
    flow = AnalyticFlow(Flow="Shear Layer", Resolution=[48, 48, 48])
    flow.UpdatePipeline()
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                 ElementShape="Paddlewheel", NumberOfElements=4,
                                 ElementSize=0.2, ReleaseOrientation="Fixed",
                                 ElementRotation=[90.0, 0.0, 0.0],
                                 Integrator="Runge-Kutta 4", RestorationIterations=4,
                                 StepSizeUnit="Time", StepSize=0.04, Duration=TIME,
                                 NumberOfTimeSteps=41, LifetimeRange=[100, 100],
                                 Trails=1, TrailLength=8, TrailSpacing=5, Engine=engine)
    tracer.SeedSource = seed_column([0.8, 0.5, -0.5, -0.8])
    return flow, tracer


def show_trails(tracer, view, representation="Surface"):
    """Coloured by Age, the trails' older poses mapped more transparent."""
    display = Show(tracer, view)
    display.SetRepresentationType(representation)
    ColorBy(display, ("POINTS", "Age"))
    lut = GetColorTransferFunction("Age")
    apply_preset(lut, "Viridis (matplotlib)")
    lut.InvertTransferFunction()  # the element itself bright, its past fading to dark
    lut.EnableOpacityMapping = 1
    pwf = GetOpacityTransferFunction("Age")
    span = 8 * 5 * 0.04
    lut.RescaleTransferFunction(0.0, span)
    pwf.Points = [0.0, 1.0, 0.5, 0.0, span, 0.08, 0.5, 0.0]
    return display


def place_camera(view):
    """Nearly along the wheels' axes, so their blades show as turning crosses."""
    view.CameraPosition = [-0.8, -5.2, 1.3]
    view.CameraFocalPoint = [0.2, 0.0, -0.05]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0


def main():
    args = picture_arguments(__doc__)
    LoadPlugin(args.plugin, ns=globals())
    flow, tracer = trails_scene()
    view = dark_view(TIME)
    view.EnableRenderOnInteraction = 0
    Show(flow, view).SetRepresentationType("Outline")
    show_trails(tracer, view)
    place_camera(view)
    save_and_close(view, os.path.join(args.output, "trails.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
