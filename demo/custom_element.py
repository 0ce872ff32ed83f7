"""Any ParaView source is an element editor: cloth patches (a Plane source)
and blobs (a Sphere) traced through the built-in ABC flow.

    pvpython demo/custom_element.py --plugin BoundParticles.so --output docs
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
    # A 6 x 6 cloth patch whose springs follow its edges only, so it folds.
    cloth = Plane(XResolution=6, YResolution=6)
    patches = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                  ElementTemplate=cloth, TemplateSprings="Edges",
                                  NumberOfElements=60, ElementSize=0.35, Seed=2,
                                  Integrator="Runge-Kutta 4", RestorationIterations=4)
    # Rigid blobs: every pair of a coarse sphere's points is a spring.
    blob = Sphere(ThetaResolution=10, PhiResolution=8)
    blobs = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"],
                                ElementTemplate=blob, TemplateSprings="All Pairs",
                                NumberOfElements=40, ElementSize=0.15, Seed=5,
                                Integrator="Runge-Kutta 4")
    time = 1.5
    save_tracers_picture(flow, ((patches, "Force", "Viridis (matplotlib)"),
                                (blobs, "Speed", "Cool to Warm")), time, [3.1, -2.9, 2.4],
                         os.path.join(args.output, "custom-elements.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
