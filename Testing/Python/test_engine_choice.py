"""Engine = Automatic (the default): on a software renderer (this machine's
Mesa llvmpipe, under Xvfb or EGL) the Bound Particles display gets the CPU
engine's result, and the tracer says why once in Output Messages; Engine = GPU
still runs the GPU engine there."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow  # noqa: E402

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())

class Texts:
    """Collects the text messages (vtkOutputWindowDisplayText) shown meanwhile."""

    def __enter__(self):
        from vtkmodules.vtkCommonCore import vtkStringOutputWindow
        self.window, self.previous = vtkStringOutputWindow(), vtkOutputWindow.GetInstance()
        vtkOutputWindow.SetInstance(self.window)
        return self

    def __exit__(self, *exc):
        vtkOutputWindow.SetInstance(self.previous)
        self.text = self.window.GetOutput()


flow = AnalyticFlow(Flow="ABC", Resolution=[16, 16, 16])
flow.UpdatePipeline()
tracer = BoundParticleTracer(Input=flow, NumberOfElements=200)
bptest.check(tracer.Engine == "Automatic", "the default Engine is %s" % tracer.Engine)
view = CreateRenderView(ViewSize=[200, 200])
shown = Show(tracer, view)
shown.SetRepresentationType("Bound Particles")
with Texts() as texts:
    for t in (0.5, 1.0, 1.5, 2.0):
        view.ViewTime = t
        Render(view)
renderer = view.GetRenderWindow().ReportCapabilities()
software = any(name in renderer for name in ("llvmpipe", "softpipe", "swrast"))
count = texts.text.count("software renderer")
print("renderer: %s; told %d time(s)" % ([l for l in renderer.splitlines() if l.startswith("OpenGL renderer")],
                                          count))
folder = bptest.scratch("bp-engine-choice-")
automatic = os.path.join(folder, "automatic.png")
SaveScreenshot(automatic, view)
if software:
    bptest.check(count == 1, "said %d times that the CPU engine traces: %r" % (count, texts.text))
    bptest.check("llvmpipe" in texts.text or "pipe" in texts.text or "swrast" in texts.text,
                 "the message names the renderer: %r" % texts.text)
    # The display drew the CPU engine's result: Engine = CPU draws the same.
    tracer.Engine = "CPU"
    Render(view)
    cpu = os.path.join(folder, "cpu.png")
    SaveScreenshot(cpu, view)
    mean, pixels = bptest.image_difference(automatic, cpu)
    bptest.check(pixels == 0, "Automatic drew other pixels than CPU (%.4f)" % pixels)
# Engine = GPU is taken as asked, whatever the renderer.
tracer.Engine = "GPU"
with Texts() as again:
    view.ViewTime = 2.5
    Render(view)
bptest.check("software renderer" not in again.text, "Engine = GPU was told: %r" % again.text)
Delete(shown)
Delete(view)
del view
bptest.finish()
