"""Run by scripts/package-test.sh with the Debian package installed, in a new
login shell with nothing set by hand, by pvpython and by pvbatch: ParaView
loaded the installed plugin at start (no LoadPlugin), a trace runs, and the
GPU engine draws it through the Bound Particles display. Prints one line and
exits non-zero on the first failure."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403


def fail(message):
    print("installed plugin: FAILED: " + message)
    sys.exit(1)


if "BoundParticleTracer" not in globals():
    fail("BoundParticleTracer is not defined (PV_PLUGIN_CONFIG_FILE=%s)"
         % os.environ.get("PV_PLUGIN_CONFIG_FILE"))
from paraview import servermanager  # noqa: E402

info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager() \
    .GetLocalInformation()
plugin = [info.GetPluginFileName(i) for i in range(info.GetNumberOfPlugins())
          if info.GetPluginLoaded(i) and info.GetPluginFileName(i).endswith("/BoundParticles.so")]
if len(plugin) != 1 or not plugin[0].startswith("/usr/lib/"):
    fail("not the installed plugin alone: %s" % plugin)

flow = AnalyticFlow(Flow="Shear Layer", Resolution=[16, 16, 16])
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, ElementShape="Cross", NumberOfElements=50, Engine="GPU")
view = CreateRenderView()
view.ViewSize = [300, 300]
display = Show(tracer, view)
if "Bound Particles" not in display.Representation.Available:
    fail("no Bound Particles display: %s" % list(display.Representation.Available))
display.SetRepresentationType("Bound Particles")
view.ViewTime = 1.0
ResetCamera(view)
Render(view)
image = os.path.join(sys.argv[1] if len(sys.argv) > 1 else ".", "installed-gpu.png")
SaveScreenshot(image, view, ImageResolution=[300, 300])

from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

reader = vtkPNGReader()
reader.SetFileName(image)
reader.Update()
pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
drawn = (abs(pixels - pixels[0]).max(axis=1) > 8).mean()
if drawn < 0.001:
    fail("the GPU engine drew nothing (%.4f of the pixels)" % drawn)
print("installed plugin: %s traced on the GPU, %.3f of the view drawn" % (plugin[0], drawn))
