"""Preferential concentration: heavy particles leave the double gyre's eddies.

Two copies of the double gyre, each seeded evenly with 8,000 points: above,
massless tracers (Inertia = None), which keep filling the eddies' cores;
below, heavy particles (Inertia = Maxey-Riley, Response Time 0.5, Density
Ratio 1000), which the eddies fling out towards the strain between them.
Testing/Core/TestInertia.cpp measures the share left in the cores.

    pvpython demo/heavy_particles.py --plugin BoundParticles.so --output docs
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import dark_view, look_down, picture_arguments, save_and_close  # noqa: E402

TIME = 20.0


def gyre_tracer(y0, inertia):
    """The double gyre over [0, 2] x [y0, y0 + 1] and its tracer."""
    flow = AnalyticFlow(Flow="Double Gyre", Resolution=[128, 64, 1],
                        Bounds=[0, 2, y0, y0 + 1, 0, 0], NumberOfTimeSteps=41)
    flow.UpdatePipeline()
    tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                 ElementShape="Point", NumberOfElements=8000,
                                 EmitterCenter=[1.0, y0 + 0.5, 0.0], EmitterSize=[2.0, 1.0, 0.0],
                                 Integrator="Runge-Kutta 2", StepSizeUnit="Time", StepSize=0.05,
                                 FramesPerInputStep=1, LifetimeRange=[100, 100],
                                 MinimumReleaseSpeed=0.0, Inertia=inertia, ResponseTime=0.5,
                                 DensityRatio=1000, Seed=2)
    return flow, tracer


def main():
    args = picture_arguments(__doc__)
    LoadPlugin(args.plugin, ns=globals())
    view = dark_view(TIME)
    for y0, inertia, colour in ((1.15, "None", [0.85, 0.88, 0.95]),
                                (0.0, "Maxey-Riley", [1.0, 0.6, 0.2])):
        flow, tracer = gyre_tracer(y0, inertia)
        Show(flow, view).SetRepresentationType("Outline")
        display = Show(tracer, view)
        ColorBy(display, None)
        display.AmbientColor = display.DiffuseColor = colour
        display.PointSize = 3.0
    look_down(view, 1.0, 1.075, 1.15)
    save_and_close(view, os.path.join(args.output, "heavy-particles.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
