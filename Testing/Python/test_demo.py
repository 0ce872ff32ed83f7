"""The README's main job writes a picture worth looking at and the element data."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402

args = bptest.arguments("--demo", "--output", "--pvpython")
run = subprocess.run([args.pvpython, args.demo, "--plugin", args.plugin, "--output", args.output],
                     capture_output=True, text=True)
print(run.stdout, run.stderr)
bptest.check(run.returncode == 0, "demo exited with %d" % run.returncode)

png = os.path.join(args.output, "bound-particles.png")
reader = vtkPNGReader()
reader.SetFileName(png)
reader.Update()
image = reader.GetOutput()
bptest.check(image.GetDimensions()[:2] == (1280, 720), "image size %s" % (image.GetDimensions(),))
pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(float)
background = pixels[0]
drawn = (abs(pixels - background).sum(axis=1) > 30).mean()
bptest.check(0.05 < drawn < 0.9, "elements cover %.1f%% of the picture" % (100 * drawn))
bptest.check(pixels.std(axis=0).max() > 20, "the picture has colour")

# The same trace on the GPU engine looks the same.
gpu_png = os.path.join(args.output, "bound-particles-gpu.png")
bptest.check(os.path.exists(gpu_png), "the demo writes a GPU image")
if os.path.exists(gpu_png):
    difference = bptest.image_difference(png, gpu_png)
    bptest.check(difference is not None and difference[0] < 2.0 and difference[1] < 0.01,
                 "GPU and CPU demo images differ: %s" % (difference,))

vtp = vtkXMLPolyDataReader()
vtp.SetFileName(os.path.join(args.output, "bound-particles.vtp"))
vtp.Update()
data = vtp.GetOutput()
bptest.check(data.GetNumberOfPoints() == 1200 * 16, "%d points" % data.GetNumberOfPoints())
bptest.check(data.GetPointData().GetArray("Layer") is not None, "the data has the Layer array")
bptest.finish()
