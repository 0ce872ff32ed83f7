"""Frames per second of the Bound Particles display inside ParaView.

One simulation step per frame (the thesis' Table 4.1 setting): the time
steps are one step apart, and each frame advances the view by one of them.
The GPU engine (Engine = GPU: the step and the drawing in the render window)
and the CPU engine (Engine = CPU: the step in the filter, the polydata drawn)
run side by side in one process on the same trace; the table gives the median
frame time over the frames after a warm-up. The GPU row includes the CPU
engine's step as well: ParaView's axes-grid decoration of the display reads
the tracer's output every frame, and every consumer other than the Bound
Particles display gets the CPU result.

    with-display.sh pvpython bench/paraview_fps.py --plugin BoundParticles.so
"""
import argparse
import statistics
import time

import paraview.simple
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--counts", default="4096,65536")
parser.add_argument("--frames", type=int, default=30)
parser.add_argument("--resolution", type=int, default=128)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()

res = args.resolution
flow = AnalyticFlow(Flow="Shear Layer", Resolution=[res, res, res])
flow.UpdatePipeline()
cell = 2.0 / (res - 1)
dt = 0.5 * cell / 1.25  # half a cell at the shear layer's top speed
frames = args.frames
warmup = 5

info = None
print("Bound Particles display, %d^3 shear layer, Strip16, Euler, 1 averaged-Jacobi "
      "iteration, one step per frame, 1024x768; median of %d frames" % (res, frames))
print("%-8s %9s %10s %12s %12s" % ("engine", "elements", "particles", "ms/frame", "frames/s"))
for count in [int(c) for c in args.counts.split(",")]:
    for engine in ["GPU", "CPU"]:
        tracer = BoundParticleTracer(Input=flow, ElementShape="Strip16", NumberOfElements=count,
                                     StepSizeUnit="Time", StepSize=dt, ElementSize=0.04,
                                     Duration=dt * (frames + warmup + 1),
                                     NumberOfTimeSteps=frames + warmup + 2, Engine=engine)
        view = CreateRenderView(ViewSize=[1024, 768])
        view.OrientationAxesVisibility = 0
        view.CameraPosition = [2.5, 2.0, 4.0]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        shown = Show(tracer, view)
        shown.SetRepresentationType("Bound Particles")
        ColorBy(shown, ("POINTS", "Force"))
        times = list(tracer.TimestepValues)
        taken = []
        for k in range(frames + warmup):
            view.ViewTime = times[k + 1]
            start = time.perf_counter()
            Render(view)
            taken.append(time.perf_counter() - start)
        frame = statistics.median(taken[warmup:])
        if info is None:
            info = view.GetRenderWindow().ReportCapabilities().splitlines()
            print("; ".join(line.strip() for line in info if "renderer string" in line.lower()))
        print("%-8s %9d %10d %12.1f %12.1f" % (engine, count, count * 16, 1e3 * frame,
                                               1.0 / frame))
        Delete(view)
        del view
        Delete(tracer)
        del tracer
