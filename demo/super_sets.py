"""Super sets (thesis §5.1): a sheet of points linked into a cloth and a ring
of linked crosses, released together into the built-in ABC flow.

    pvpython demo/super_sets.py --plugin BoundParticles.so --output docs
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import picture_arguments, save_tracers_picture  # noqa: E402


def main():
    args = picture_arguments(__doc__)
    LoadPlugin(args.plugin, ns=globals())

    flow = AnalyticFlow(Flow="ABC", Resolution=[40, 40, 40])
    flow.UpdatePipeline()
    # A 32 x 20 cloth of points: only the links hold it together.
    cloth = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                ElementShape="Point", NumberOfElements=640,
                                Linking="Sheet", LatticeWidth=32, EmitterCenter=[-0.2, 0.1, 0.3],
                                EmitterSize=[1.2, 0.8, 0.0], Integrator="Runge-Kutta 4",
                                RestorationIterations=8, LifetimeRange=[100, 100])
    # A necklace: a ring of 40 crosses linked particle to particle.
    ring = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                               ElementShape="Cross", NumberOfElements=40,
                               Linking="Ring", ElementSize=0.12, EmitterCenter=[0.4, -0.3, -0.3],
                               EmitterSize=[1.0, 1.0, 0.0], ReleaseOrientation="Fixed",
                               Integrator="Runge-Kutta 4", RestorationIterations=4,
                               LifetimeRange=[100, 100])
    time = 1.0
    save_tracers_picture(flow, ((cloth, "Force", "Viridis (matplotlib)"),
                                (ring, "Speed", "Cool to Warm")), time, [4.4, -4.1, 3.4],
                         os.path.join(args.output, "super-sets.png"), line_width=2.0)
    return 0


if __name__ == "__main__":
    sys.exit(main())
