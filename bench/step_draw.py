"""The GPU engine's step plus draw in ParaView: frames per second of Play.

A Bound Particles display of a tracer on the GPU engine (Engine = GPU), in an
offscreen render window, advanced one engine step per frame and rendered:
what a frame of Play costs when nothing but the GPU works. The path is the
engine's own choice, or BOUNDPARTICLES_GPU_PATH's (bench/real_gpu.sh runs it
once per path). Prints the render window's OpenGL renderer, so a run that
fell back to a software renderer says so.

    pvpython --force-offscreen-rendering bench/step_draw.py --plugin BoundParticles.so
"""
import argparse
import os
import statistics
import time

import paraview.simple
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--elements", type=int, default=65536, help="Strip16 elements (16 particles each)")
parser.add_argument("--frames", type=int, default=100)
parser.add_argument("--resolution", type=int, default=128)
parser.add_argument("--size", default="1920,1080")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()

res = args.resolution
warmup = 5
steps = warmup + args.frames + 2
flow = AnalyticFlow(Flow="Shear Layer", Resolution=[res, res, res])
flow.UpdatePipeline()
dt = 0.5 * (2.0 / (res - 1)) / 1.25  # half a cell at the shear layer's top speed
tracer = BoundParticleTracer(Input=flow, Vectors=["POINTS", "velocity"], ElementShape="Strip16",
                             NumberOfElements=args.elements, StepSizeUnit="Time", StepSize=dt,
                             ElementSize=0.02, Duration=dt * (steps - 1), NumberOfTimeSteps=steps,
                             Engine="GPU")
width, height = (int(v) for v in args.size.split(","))
view = CreateRenderView(ViewSize=[width, height])
view.OrientationAxesVisibility = 0
view.CameraPosition = [2.5, 2.0, 4.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
shown = Show(tracer, view)
shown.SetRepresentationType("Bound Particles")
ColorBy(shown, ("POINTS", "Force"))
times = list(tracer.TimestepValues)
view.ViewTime = times[0]
Render(view)

frames = []
for k in range(1, warmup + args.frames + 1):
    view.ViewTime = times[k]
    start = time.perf_counter()
    Render(view)
    frames.append(time.perf_counter() - start)
played = frames[warmup:]
wall = sum(played)
window = view.GetRenderWindow()
renderer = "?"
for line in window.ReportCapabilities().splitlines():
    if "renderer string" in line:
        renderer = line.split(":", 1)[1].strip()
particles = 16 * args.elements
print("step+draw: %d Strip16 (%d particles), %dx%d, GPU path %s, on %s" % (
    args.elements, particles, width, height,
    os.environ.get("BOUNDPARTICLES_GPU_PATH", "automatic"), renderer))
print("  %d frames: %.1f frames/s (median frame %.2f ms, slowest %.2f ms); %.3g particle-steps/s"
      % (len(played), len(played) / wall, 1e3 * statistics.median(played), 1e3 * max(played),
         particles * len(played) / wall), flush=True)
