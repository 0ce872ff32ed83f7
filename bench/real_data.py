"""What a user sees on the shared real data with the tracer's defaults.

For each data set in the data folder: a Bound Particle Tracer with every
property at its default (the Vectors are the reader's active vectors, but
on gfs_wind10m its velocity_deg_per_hour, whose units fit its grid), traced
to the middle of the offered time range. Prints one row per data set:
- steps/frame: the most engine steps one offered frame needs (the largest
  gap between offered times over the resolved time step);
- moving: the share of elements whose particles' mean speed is at least 1%
  of the field's top speed at that time;
- masked: the share of element centres whose nearest grid point is outside
  the domain (vtkValidPointMask 0, or a non-finite vector);
- time values, top speed, and the messages the tracer printed.
Targets (issue 17): steps/frame <= 20, moving >= 80%, masked <= 5%; with
--check a miss fails the run (ctest python.RealDataDefaults). With
--pictures DIR it also writes one picture per data set there.

    with-display.sh pvpython bench/real_data.py --plugin BoundParticles.so --data ../shared/data
"""
import argparse
import math
import os
import sys

import numpy
import paraview.simple
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from messages import CapturedMessages  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--pictures", help="write <data set>.png here")
parser.add_argument("--check", action="store_true",
                    help="exit 1 when a data set misses a target (the ctest python.RealDataDefaults)")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())

DATA_SETS = ["combustor.vti", "office.vti", "carotid.vti", "nek_eddy.pvd", "gfs_wind10m.pvd"]


def input_at(reader, time, vectors):
    """The reader's image at `time`: (its point array `vectors` as an N x 3
    array, mask or None, image)."""
    reader.UpdatePipeline(time)
    image = servermanager.Fetch(reader)
    points = image.GetPointData()
    velocity = vtk_to_numpy(points.GetArray(vectors)).astype(float)
    mask = points.GetArray("vtkValidPointMask")
    return velocity, None if mask is None else vtk_to_numpy(mask), image


def outside_points(velocity, mask):
    """True where a grid point is outside the domain."""
    outside = ~numpy.isfinite(velocity).all(axis=1)
    if mask is not None:
        outside |= mask == 0
    return outside


def nearest_points(image, xyz):
    """The point id nearest each position (clamped to the grid)."""
    dims = image.GetDimensions()
    origin, spacing = image.GetOrigin(), image.GetSpacing()
    index = [numpy.clip(numpy.rint((xyz[:, a] - origin[a]) / spacing[a]), 0, dims[a] - 1)
             .astype(int) for a in range(3)]
    return index[0] + dims[0] * (index[1] + dims[1] * index[2])


def measure(name):
    reader = OpenDataFile(os.path.join(args.data, name))
    reader.UpdatePipeline()
    tracer = BoundParticleTracer(Input=reader)
    times = list(tracer.TimestepValues)
    middle = times[len(times) // 2]
    messages = []
    with CapturedMessages(messages):
        tracer.UpdatePipeline(middle)
    tracer.UpdatePropertyInformation()
    dt = tracer.GetPropertyValue("ResolvedTimeStep")
    gaps = numpy.diff(times) if len(times) > 1 else numpy.array([0.0])
    steps_per_frame = int(math.ceil(gaps.max() / dt - 1e-9)) if dt > 0 else float("nan")

    output = servermanager.Fetch(tracer)
    elements = tracer.NumberOfElements
    vectors = tracer.Vectors[1]
    xyz = vtk_to_numpy(output.GetPoints().GetData()).astype(float).reshape(elements, -1, 3)
    speed = vtk_to_numpy(output.GetPointData().GetArray("Speed")).reshape(elements, -1)
    velocity, mask, image = input_at(reader, middle, vectors)
    outside = outside_points(velocity, mask)
    top = numpy.linalg.norm(velocity[~outside], axis=1).max()
    moving = (speed.mean(axis=1) >= 0.01 * top).mean()
    masked = outside[nearest_points(image, xyz.mean(axis=1))].mean()
    if args.pictures:
        picture(reader, tracer, middle, os.path.join(args.pictures, name.split(".")[0] + ".png"))
    Delete(tracer)
    Delete(reader)
    return dict(name=name, frames=len(times), steps=steps_per_frame, moving=moving,
                masked=masked, top=top, messages=messages, vectors=vectors)


def picture(reader, tracer, time, path):
    view = CreateRenderView()
    view.ViewSize = [800, 600]
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    Show(reader, view, Representation="Outline")
    display = Show(tracer, view)
    ColorBy(display, ("POINTS", "Speed"))
    display.RescaleTransferFunctionToDataRange(True, False)
    view.ResetCamera()
    Render(view)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    SaveScreenshot(path, view)
    Delete(view)


rows = [measure(name) for name in DATA_SETS]
print("%-16s %-22s %7s %11s %7s %7s %10s  %s" % (
    "data", "vectors", "frames", "steps/frame", "moving", "masked", "top speed", "messages"))
for r in rows:
    print("%-16s %-22s %7d %11s %6.1f%% %6.1f%% %10.4g  %s" % (
        r["name"], r["vectors"], r["frames"], r["steps"], 100 * r["moving"], 100 * r["masked"],
        r["top"],
        " | ".join(m[:100] for m in r["messages"]) or "-"))
print("targets: steps/frame <= 20, moving >= 80%, masked <= 5%")
missed = [r["name"] for r in rows
          if not (r["steps"] <= 20 and r["moving"] >= 0.8 and r["masked"] <= 0.05)]
if args.check and missed:
    print("FAILED: targets missed on %s" % ", ".join(missed))
    raise SystemExit(1)
