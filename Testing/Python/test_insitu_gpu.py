"""In situ on the GPU engine (issue 42, item 2): the tracer with Engine = GPU
behind a Bound Particles display in a render view, its input a trivial
producer fed the double gyre one step at a time and the view rendered after
each step, as a Catalyst render view does. The GPU engine's particles live in
its textures and no Python call reads them back, so the pictures are
compared: in situ at half way and at the last step against the same display
on a post hoc trace of the same steps (the GPU engine replaying them) and
against the CPU engine's post hoc output drawn as Surface, at the same times.
The two times' pictures must differ from each other by far more than the
bars, so that a trace that stopped, or started again, would fail. Nothing is
said on the way.

A step whose vectors are all NaN, or one without the vector array, is
skipped with one error, and the trace goes on from the last good step (issue
53, item 3): the last picture equals that of a run never given the bad step,
on the GPU engine as on the CPU engine (which drew afresh from the next good
step before: the display's own decorations ran the CPU engine on the bad
step, which cannot go on from the GPU's state).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--output", "--steps")

import paraview.simple  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from insitu_feed import copy_of, feed  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)
STEPS = int(args.steps or 16)
# test_far_origin.py's bars for one trace on the two displays.
MEAN_BAR, PIXEL_BAR = 0.5, 0.002
SETTINGS = dict(Vectors=["POINTS", "velocity"], ElementShape="Cross", NumberOfElements=300,
                ElementSize=0.06, Seed=7, LifetimeRange=[3.0, 6.0])

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[48, 24, 2], Bounds=[0, 2, 0, 1, 0, 0.05],
                    NumberOfTimeSteps=STEPS)
flow.UpdatePipeline()
times = list(flow.TimestepValues)
checked = [times[STEPS // 2], times[-1]]


def gyre_view():
    """A view of the whole gyre from above, the same for every picture."""
    view = CreateRenderView(ViewSize=[320, 240])
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.15]
    view.CameraPosition = [1.0, 0.5, 3.4]
    view.CameraFocalPoint = [1.0, 0.5, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30
    return view


def show(tracer, view, representation):
    shown = Show(tracer, view)
    shown.SetRepresentationType(representation)
    bptest.colour_display(shown, None, None)
    return shown


def picture(view, name):
    path = os.path.join(args.output, name + ".png")
    SaveScreenshot(path, view)
    return path


def posthoc_pictures(engine, representation):
    """Pictures of a post hoc trace of the flow at the checked times."""
    tracer = BoundParticleTracer(Input=flow, Engine=engine, **SETTINGS)
    view = gyre_view()
    show(tracer, view, representation)
    paths = []
    for t in checked:
        view.ViewTime = t
        Render(view)
        paths.append(picture(view, "posthoc_%s_%s_%g" % (engine, representation.replace(" ", ""),
                                                         t)))
    Delete(view)
    return paths


def difference(a, b, what):
    mean, pixels = bptest.image_difference(a, b)
    print("%s: mean %.3f, pixels %.4f" % (what, mean, pixels))
    return mean, pixels


gpu_posthoc = posthoc_pictures("GPU", "Bound Particles")
surface_posthoc = posthoc_pictures("CPU", "Surface")

producer = PVTrivialProducer()
insitu = BoundParticleTracer(Input=producer, Engine="GPU", **SETTINGS)
view = gyre_view()
shown = None
insitu_paths = []
with bptest.CapturedMessages() as said:
    for t in times:
        feed(producer, copy_of(flow, t), t)
        if shown is None:
            shown = show(insitu, view, "Bound Particles")
            display = shown.GetClientSideObject().GetActiveRepresentation()
            bptest.check(display.GetClassName() == "vtkBoundParticleRepresentation",
                         "the active display is a %s" % display.GetClassName())
        view.ViewTime = t
        Render(view)
        if t in checked:
            insitu_paths.append(picture(view, "insitu_GPU_BoundParticles_%g" % t))
        own = insitu.GetClientSideObject().GetOutputDataObject(0)
        if t == times[-1]:
            # The GPU engine drew: the tracer's own output is its two-point
            # GPU output, not the CPU engine's elements.
            bptest.check(own.GetNumberOfPoints() == 2,
                         "the GPU engine drew the last step: the tracer's output has %d points"
                         % own.GetNumberOfPoints())
Delete(shown)
Delete(view)
said.messages = [m for m in said.messages if "New time step is not" not in m]
bptest.check(not said.messages, "nothing said in situ: %s" % said.messages[:3])

for k, t in enumerate(checked):
    covered = bptest.covered_fraction(insitu_paths[k])
    bptest.check(covered > 0.005, "t = %g: elements are drawn in situ (%.4f)" % (t, covered))
    for what, other in (("the post hoc GPU display", gpu_posthoc[k]),
                        ("the post hoc CPU Surface", surface_posthoc[k])):
        mean, pixels = difference(insitu_paths[k], other, "t = %g: in situ GPU and %s" % (t, what))
        bptest.check(mean <= MEAN_BAR and pixels <= PIXEL_BAR,
                     "t = %g: in situ GPU differs from %s: mean %.3f, pixels %.4f"
                     % (t, what, mean, pixels))


def with_bad_step(engine, representation, bad, name):
    """The last picture of an in situ trace fed `bad(t)` in place of the step
    half way (None: that step never comes), and the errors said."""
    feeder = PVTrivialProducer()
    tracer = BoundParticleTracer(Input=feeder, Engine=engine, **SETTINGS)
    bad_view = gyre_view()
    bad_shown = None
    with bptest.CapturedMessages() as errors:
        for k, t in enumerate(times):
            data = bad(t) if k == STEPS // 2 else copy_of(flow, t)
            if data is None:
                continue
            feed(feeder, data, t)
            if bad_shown is None:
                bad_shown = show(tracer, bad_view, representation)
            bad_view.ViewTime = t
            Render(bad_view)
        path = picture(bad_view, "bad_step_%s_%s" % (engine, name))
    Delete(bad_shown)
    Delete(bad_view)
    Delete(tracer)
    Delete(feeder)
    return path, [m for m in errors.messages if "New time step is not" not in m]


def nan_vectors(t):
    data = copy_of(flow, t)
    data.GetPointData().GetArray("velocity").Fill(float("nan"))
    return data


def without_vectors(t):
    data = copy_of(flow, t)
    data.GetPointData().GetArray("velocity").SetName("pressure_gradient")
    return data


for engine, representation in (("GPU", "Bound Particles"), ("CPU", "Surface")):
    never, _ = with_bad_step(engine, representation, lambda t: None, "never")
    for name, bad in (("nan", nan_vectors), ("missing", without_vectors)):
        path, errors = with_bad_step(engine, representation, bad, name)
        bptest.check(len(errors) == 1 and "is skipped" in errors[0],
                     "%s, a step with %s vectors: one error that says it is skipped: %s"
                     % (engine, name, [e[:160] for e in errors]))
        mean, pixels = difference(path, never, "%s, a %s step against none" % (engine, name))
        bptest.check(mean <= MEAN_BAR and pixels <= PIXEL_BAR,
                     "%s: after a step with %s vectors the trace goes on from the last good step "
                     "(mean %.3f, pixels %.4f from a run never given it)"
                     % (engine, name, mean, pixels))

# The comparison can tell: half way and the last step are far apart.
mean, pixels = difference(insitu_paths[0], insitu_paths[1], "in situ half way and last step")
bptest.check(pixels > 10 * PIXEL_BAR, "the pictures at t = %g and %g differ (pixels %.4f)"
             % (checked[0], checked[1], pixels))
bptest.finish()
