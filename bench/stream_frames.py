"""Frame times of the Bound Particles display (GPU engine) while an unsteady
field's time steps go by, inside ParaView (issue 4).

Writes a raw series (.bpvol, float32, interleaved) of a moving double gyre,
opens it with the Raw Vector Volume Series reader, traces it on the GPU and
plays it frame by frame, several frames per data interval, one step per
frame. Two ways, side by side in one run:
  whole:    Stream Time Steps off and Read Ahead off: the frame that crosses
            into a new interval reads the next time step and uploads it whole;
  streamed: both on (the defaults): the reader reads the next file in the
            background, the tracer asks for it ahead of need in a frame that
            crosses nothing, and the display uploads it a slab per frame.
Prints the median and worst frame in the middle of an interval and the median
and worst frame that crosses a time step (ParaView gathers the reader's data
information whenever it reads, which is part of whichever frame reads).

    bash scripts/with-display.sh pvpython bench/stream_frames.py --plugin PATH
"""
import argparse
import json
import os
import shutil
import statistics
import tempfile
import time

import numpy
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--resolution", type=int, default=128)
parser.add_argument("--steps", type=int, default=7)
parser.add_argument("--frames-per-interval", type=int, default=6)
parser.add_argument("--elements", type=int, default=1024)
parser.add_argument("--folder", default=None)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

folder = args.folder or tempfile.mkdtemp(prefix="bp-stream-")
os.makedirs(folder, exist_ok=True)
n = args.resolution
x = numpy.linspace(0.0, 2.0, n, dtype=numpy.float32)
y = numpy.linspace(0.0, 1.0, n, dtype=numpy.float32)
zz, yy, xx = numpy.meshgrid(numpy.linspace(0.0, 1.0, n, dtype=numpy.float32), y, x,
                            indexing="ij")
files, times = [], []
for k in range(args.steps):
    t = 0.5 * k
    e = 0.25 * numpy.sin(0.6 * t)
    f = e * xx * xx + (1 - 2 * e) * xx
    v = numpy.empty(xx.shape + (3,), dtype="<f4")
    v[..., 0] = -numpy.pi * 0.1 * numpy.sin(numpy.pi * f) * numpy.cos(numpy.pi * yy)
    v[..., 1] = numpy.pi * 0.1 * numpy.cos(numpy.pi * f) * numpy.sin(numpy.pi * yy) * \
        (2 * e * xx + 1 - 2 * e)
    v[..., 2] = 0.02 * numpy.sin(numpy.pi * zz)
    name = "gyre_%03d.raw" % k
    v.tofile(os.path.join(folder, name))
    files.append(name)
    times.append(t)
descriptor = os.path.join(folder, "gyre.bpvol")
with open(descriptor, "w") as out:
    json.dump({"dimensions": [n, n, n], "origin": [0, 0, 0],
               "spacing": [2.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1)],
               "scalar_type": "float32", "byte_order": "little", "times": times,
               "files": files}, out)
megabytes = n ** 3 * 12 / 2 ** 20

paraview_simple = __import__("paraview.simple", fromlist=["_DisableFirstRenderCameraReset"])
paraview_simple._DisableFirstRenderCameraReset()
print("%d^3 field (%.0f MiB per time step, %d steps), %d Strip8 elements, %d frames per "
      "interval, one step per frame, 800x600" % (n, megabytes, args.steps, args.elements,
                                                  args.frames_per_interval))
print("%-10s %14s %18s %16s %18s" % ("uploads", "middle (ms)", "worst middle (ms)",
                                     "crossing (ms)", "worst cross (ms)"))
results = {}
for way in ("whole", "streamed"):
    streamed = way == "streamed"
    reader = OpenDataFile(descriptor)
    reader.ReadAhead = 1 if streamed else 0
    tracer = BoundParticleTracer(Input=reader, ElementShape="Strip8",
                                 NumberOfElements=args.elements, Seed=1, Engine="GPU")
    view = CreateRenderView(ViewSize=[800, 600])
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [1.0, -2.5, 2.0]
    view.CameraFocalPoint = [1.0, 0.5, 0.5]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    display = Show(tracer, view)
    display.SetRepresentationType("Bound Particles")
    display.StreamTimeSteps = 1 if streamed else 0
    frames = args.frames_per_interval
    middle, crossing = [], []
    for f in range((args.steps - 1) * frames + 1):
        view.ViewTime = 0.5 * f / frames
        start = time.perf_counter()
        Render(view)
        ms = 1e3 * (time.perf_counter() - start)
        if f <= frames:
            continue  # the first interval reads two time steps and compiles
        # Frame f = k * frames lands on time step k; the next one steps past it.
        (crossing if f % frames == 1 else middle).append(ms)
    print("%-10s %14.1f %18.1f %16.1f %18.1f" % (way, statistics.median(middle), max(middle),
                                                 statistics.median(crossing), max(crossing)))
    Delete(view)
    del view
    Delete(tracer)
    Delete(reader)
if not args.folder:
    shutil.rmtree(folder)
