"""What the engines say in Output Messages (issue 53, items 8 and 11), as a
user of pvpython meets it, on this machine's software renderer (llvmpipe):

- Engine = Automatic with the Bound Particles display: one line that the CPU
  engine traces and why, at the display's first frame in a view that drew
  before (as the GUI's does), by its second in one that never drew (the
  window tells its renderer once it drew: pvpython's first Render), and not
  again at later frames, nor at a frame at another time;
- Engine = GPU: one line naming the GPU engine's path, at its first frame
  and not again;
- BOUNDPARTICLES_GPU_FUSED_STEP set to a value it does not know (ctest sets
  `yes`): one warning that names the variable, the value and the accepted
  values, as BOUNDPARTICLES_GPU_PATH's.
Run in a process of its own: the GPU engine says its path once per process."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments()
LoadPlugin(args.plugin, ns=globals())

ENGINE_NOTE = "Engine is Automatic and this render window draws with a software renderer"
PATH_NOTE = "BoundParticles GPU engine: the "
FUSED = os.environ.get("BOUNDPARTICLES_GPU_FUSED_STEP", "")

flow = AnalyticFlow(Flow="ABC", Resolution=[16, 16, 16])
flow.UpdatePipeline()


def frames(engine, drawn_before):
    """What a Bound Particles display of a new tracer says at each of three
    frames at one time, then at a frame at another time: every message, and
    the warnings among them (those that open Output Messages)."""
    tracer = BoundParticleTracer(Input=flow, NumberOfElements=200, Engine=engine)
    view = CreateRenderView(ViewSize=[200, 200])
    if drawn_before:
        Render(view)
    said, warned = [], []
    for k in range(4):
        with bptest.CapturedMessages(texts=True) as messages, \
                bptest.CapturedMessages() as warnings:
            if k == 0:
                shown = Show(tracer, view)
                shown.SetRepresentationType("Bound Particles")
            if k == 3:
                view.ViewTime = 0.5
            Render(view)
        said.append([m for m in messages.messages if m.strip()])
        warned.extend(warnings.messages)
    Delete(shown)
    Delete(view)
    Delete(tracer)
    return said, warned


probe = CreateRenderView(ViewSize=[32, 32])
Render(probe)  # the window tells its renderer once it drew
renderer = probe.GetRenderWindow().ReportCapabilities()
Delete(probe)
if not any(name in renderer for name in ("llvmpipe", "softpipe", "swrast")):
    print("not a software renderer: Automatic runs the GPU engine here")
    bptest.finish()

for drawn in (True, False):
    said, _ = frames("Automatic", drawn)
    print("Automatic, the view %s before: %r" % ("drawn" if drawn else "never drawn", said))
    told = [sum(ENGINE_NOTE in m for m in frame) for frame in said]
    bptest.check(told == ([1, 0, 0, 0] if drawn else [0, 1, 0, 0]),
                 "Automatic (view %s before): the engine said once, at the %s frame (times "
                 "said per frame %s)" % ("drawn" if drawn else "never drawn",
                                         "first" if drawn else "second", told))
    lines = [m for frame in said for m in frame if ENGINE_NOTE in m]
    bptest.check(all("llvmpipe" in m or "pipe" in m or "swrast" in m for m in lines),
                 "the line names the renderer: %r" % lines)

said, warned = frames("GPU", True)
print("GPU: %r" % said)
told = [sum(PATH_NOTE in m for m in frame) for frame in said]
bptest.check(told == [1, 0, 0, 0], "GPU: the path said at the first frame only, per frame %s"
             % told)
bptest.check(not any(ENGINE_NOTE in m for frame in said for m in frame),
             "Engine = GPU is not told the CPU engine traces")
if FUSED:
    fused = [m for m in warned if "BOUNDPARTICLES_GPU_FUSED_STEP=" in m]
    bptest.check(len(fused) == 1 and "BOUNDPARTICLES_GPU_FUSED_STEP=%s is not one of on, off or "
                 "automatic" % FUSED in fused[0],
                 "an unknown BOUNDPARTICLES_GPU_FUSED_STEP is warned of once: %r" % warned)
bptest.finish()
