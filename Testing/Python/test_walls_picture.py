"""The walls picture (demo/walls.py, docs/walls.png) shows what the user
guide says it does: in the GFS 10 m wind with Boundary = Slip, about half of
the 150 strips lie flat on the grid's side at 179 E after 48 hours and have
slid north along it since they first lay there; with Stick the same strips
stay where they touched. The script's picture is written and shows them."""
import os
import subprocess
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "demo"))
import bptest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = bptest.arguments("--data", "--demo", "--pvpython")
import walls  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
LoadPlugin(args.plugin, ns=walls.__dict__)


def slides(boundary):
    """(latitudes of the strips lying flat on the wall at the end, how far
    north each of those lying there since 24 h or earlier has moved since
    it first lay there), with `boundary`."""
    wind, tracer = walls.wall_scene(args.data)
    tracer.Boundary = boundary
    wall = wind.GetDataInformation().GetBounds()[1]
    first = {}
    for time in tracer.TimestepValues:
        tracer.UpdatePipeline(time)
        xyz = vtk_to_numpy(servermanager.Fetch(tracer).GetPoints().GetData()).astype(float)
        xyz = xyz.reshape(tracer.NumberOfElements, -1, 3)
        lying = (numpy.abs(xyz[:, :, 0] - wall) < 1e-4).all(axis=1)
        for e in numpy.nonzero(lying)[0]:
            first.setdefault(e, (time, xyz[e, :, 1].mean()))
    latitudes = xyz[lying, :, 1].mean(axis=1)
    moved = [xyz[e, :, 1].mean() - first[e][1] for e in numpy.nonzero(lying)[0]
             if first[e][0] <= walls.TIME - 24.0]
    Delete(tracer)
    Delete(wind)
    return latitudes, numpy.array(moved)


latitudes, moved = slides("Slip")
print("Slip: %d strips lie on the wall at %.1f to %.1f; %d lying there since 24 h moved "
      "%.2f (median) to %.2f north" % (len(latitudes), latitudes.min(), latitudes.max(),
                                       len(moved), numpy.median(moved), moved.max()))
bptest.check(60 <= len(latitudes) <= 100, "Slip: %d of 150 strips on the wall" % len(latitudes))
bptest.check(latitudes.min() > -62 and latitudes.max() < -40,
             "Slip: the strips on the wall lie between 40 S and 62 S")
bptest.check(len(moved) >= 15 and numpy.median(moved) > 1.5 and moved.max() > 3.0,
             "Slip: the strips on the wall slid north along it")
latitudes, moved = slides("Stick")
print("Stick: %d strips lie on the wall; %d lying there since 24 h moved %.2f (median) to %.2f"
      % (len(latitudes), len(moved), numpy.median(moved) if len(moved) else 0,
         abs(moved).max() if len(moved) else 0))
bptest.check(len(moved) == 0 or abs(moved).max() < 0.5,
             "Stick: the strips on the wall stayed where they lay")

# The picture: written at 1280 x 720, the strips on the wall drawn orange.
output = bptest.scratch("walls-picture-")
run = subprocess.run([args.pvpython, args.demo, "--plugin", args.plugin, "--output", output,
                      "--data", args.data], capture_output=True, text=True)
print(run.stdout, run.stderr)
bptest.check(run.returncode == 0, "demo/walls.py exited with %d" % run.returncode)
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
reader = vtkPNGReader()
reader.SetFileName(os.path.join(output, "walls.png"))
reader.Update()
image = reader.GetOutput()
bptest.check(image.GetDimensions()[:2] == (1280, 720), "image size %s" % (image.GetDimensions(),))
if image.GetNumberOfPoints():
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    orange = ((rgb[:, 0] > 200) & (rgb[:, 1] > 100) & (rgb[:, 1] < 180) & (rgb[:, 2] < 90)).mean()
    print("orange: %.2f%% of the picture" % (100 * orange))
    bptest.check(orange > 0.005, "the strips on the wall cover %.2f%% of the picture" % (100 * orange))
bptest.finish()
