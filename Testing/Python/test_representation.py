"""The Bound Particles representation: the GPU engine in the render window.

Every image of the GPU path is compared twice: with the same trace run on the
CPU engine and drawn by ParaView's Surface representation (the two must agree:
same lights, same colours, positions within rounding), and with a baseline
image in Testing/Data/Baseline. --update-baselines writes the baselines
instead (look at them before committing them).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments("--baselines", "--output", "--update-baselines")
LoadPlugin(args.plugin, ns=globals())
# Named on every tracer: pvpython takes the default from the active source,
# often another tracer (whose output has 'Velocity'), and a name the input
# lacks is an error.
VELOCITY = ["POINTS", "velocity"]
# The baselines were drawn with random orientations (Release Orientation's
# default was Random then); the display, not the orientation, is under test.
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)

# Against the CPU path: the same trace must look the same.
CPU_MEAN, CPU_PIXELS = 0.5, 0.002
# Against the baselines: the same Mesa must draw the same picture.
BASE_MEAN, BASE_PIXELS = 1.0, 0.005

flow = AnalyticFlow(Flow="Shear Layer", Resolution=[32, 32, 32])
flow.UpdatePipeline()


def render(source, representation, color, scalar_range, name, time=1.0, size=(320, 240),
           frames=(), **display):
    view = bptest.element_view(size)
    shown = Show(source, view)
    shown.SetRepresentationType(representation)
    for key, value in display.items():
        setattr(shown, key, value)
    bptest.colour_display(shown, color, scalar_range)
    for frame in list(frames) + [time]:  # played up to `time`, one frame after another
        view.ViewTime = frame
        Render(view)
    return bptest.save_picture(view, args.output, name)


def compare_paths(cpu, gpu, color, scalar_range, name, frames=(), time=1.0, **display):
    """Draws the CPU path as Surface and the GPU path as Bound Particles (played
    through `frames` first) and checks that they agree; returns the GPU image."""
    cpu_image = render(cpu, "Surface", color, scalar_range, name + "_cpu", time=time)
    gpu_image = render(gpu, "Bound Particles", color, scalar_range, name, time=time,
                       frames=frames, **display)
    mean, pixels = bptest.image_difference(cpu_image, gpu_image)
    bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
                 "%s: GPU vs CPU differ: mean %.3f, pixels %.4f" % (name, mean, pixels))
    return gpu_image


def tracer(shape, engine, count):
    # The baselines show the time line [0, 10] with lifetimes in [5, 10].
    return BoundParticleTracer(ReleaseOrientation="Random", Input=flow, Vectors=VELOCITY, ElementShape=shape,
                               NumberOfElements=count, ElementSize=0.3, Seed=3, Engine=engine,
                               Duration=10.0, LifetimeRange=[5.0, 10.0])


# The representation is offered for the tracer's output.
probe_view = CreateRenderView()
probe = Show(tracer("Strip16", "GPU", 10), probe_view)
bptest.check("Bound Particles" in probe.Representation.Available,
             "representation types %s" % list(probe.Representation.Available))
Delete(probe_view)
del probe_view

COLORS = [(None, None), ("Force", (0.0, 0.004)), ("Lifetime", (5.0, 10.0))]
for shape in ["Strip16", "Cross", "Paddlewheel", "Fish"]:
    cpu = tracer(shape, "CPU", 40)
    gpu = tracer(shape, "GPU", 40)
    for color, scalar_range in COLORS:
        name = "%s_%s" % (shape, color or "Solid")
        gpu_image = compare_paths(cpu, gpu, color, scalar_range, name)
        covered = bptest.covered_fraction(gpu_image)
        bptest.check(covered > 0.005, "%s: the GPU image shows elements (%.4f)" % (name, covered))
        bptest.check_baseline(gpu_image, args.baselines, name, args.update_baselines, BASE_MEAN,
                              BASE_PIXELS)
    Delete(cpu)
    Delete(gpu)

# A release window hides the elements due outside it on both engines: at
# t = 1 the window [1.5, 2] has not opened (nothing drawn); at t = 2 the
# elements released in it are drawn the same by both.
cpu = tracer("Cross", "CPU", 40)
gpu = tracer("Cross", "GPU", 40)
for proxy in (cpu, gpu):
    proxy.ReleaseWindow = 1
    proxy.ReleaseStart = 1.5
    proxy.ReleaseStop = 2.0
    proxy.LifetimeRange = [0.3, 0.6]
before = compare_paths(cpu, gpu, None, None, "Window_before", time=1.0)
bptest.check(bptest.covered_fraction(before) == 0.0,
             "before the window nothing is drawn (%.4f)" % bptest.covered_fraction(before))
during = compare_paths(cpu, gpu, None, None, "Window_during", time=2.0)
bptest.check(bptest.covered_fraction(during) > 0.005,
             "in the window the elements are drawn (%.4f)" % bptest.covered_fraction(during))
after = compare_paths(cpu, gpu, None, None, "Window_after", time=3.0)
bptest.check(bptest.covered_fraction(after) == 0.0,
             "lives of at most 0.6 after the window: nothing drawn (%.4f)" %
             bptest.covered_fraction(after))
Delete(cpu)
Delete(gpu)

# Every other array of the CPU output colours the GPU path the same way.
cpu = tracer("Paddlewheel", "CPU", 40)
gpu = tracer("Paddlewheel", "GPU", 40)
for color, scalar_range in [("Speed", (0.0, 1.3)), ("Vorticity", (0.0, 4.0)),
                            ("Layer", (-1.0, 1.0)), ("Radius", (0.0, 1.4)),
                            ("ElementId", (0.0, 39.0)), ("ParticleIndex", (0.0, 16.0))]:
    compare_paths(cpu, gpu, color, scalar_range, "Paddlewheel_%s" % color)
Delete(cpu)
Delete(gpu)

# Counts that are no power of two: 1000 fish of 23 particles, played frame by
# frame on the GPU, against a CPU replay to the same time.
cpu = tracer("Fish", "CPU", 1000)
gpu = tracer("Fish", "GPU", 1000)
gpu_image = compare_paths(cpu, gpu, "Speed", (0.0, 1.3), "Fish1000",
                          frames=[0.0, 0.2, 0.35, 0.6, 0.3, 0.8])  # on, between, back
bptest.check(bptest.covered_fraction(gpu_image) > 0.02, "1000 fish are drawn")

# An unsteady field played across its time steps, four frames per interval:
# with the next time step streamed to the GPU a slab per frame, and without.
gyre = AnalyticFlow(Flow="Double Gyre", Resolution=[40, 24, 6], NumberOfTimeSteps=9)
for stream in (1, 0):
    traces = [BoundParticleTracer(ReleaseOrientation="Random", Input=gyre, Vectors=VELOCITY, ElementShape="Strip8", NumberOfElements=300,
                                  ElementSize=0.15, Seed=5, Engine=engine)
              for engine in ("CPU", "GPU")]
    gyre_image = compare_paths(traces[0], traces[1], None, None, "Gyre_stream%d" % stream,
                               frames=[0.125 * k for k in range(24)], time=3.0,
                               StreamTimeSteps=stream)
    bptest.check(bptest.covered_fraction(gyre_image) > 0.01, "the gyre's strips are drawn")
    for trace in traces:
        Delete(trace)

# Time Direction = Backward runs on the GPU engine too: the gyre released at
# its last time (4) and played back to 1 draws as the CPU engine's trace, the
# Velocity and ElementSpin components per the data's time (their sign is
# what tells a trace run through the negated flow from one drawn per the
# data), and the frame's output is the GPU's (two points), not the CPU's.
traces = [BoundParticleTracer(ReleaseOrientation="Random", Input=gyre, Vectors=VELOCITY,
                              ElementShape="Strip8", NumberOfElements=300, ElementSize=0.15,
                              Seed=5, Engine=engine, TimeDirection="Backward")
          for engine in ("CPU", "GPU")]
for trace in traces:
    trace.OutputArrays = list(trace.OutputArrays) + ["ElementSpin"]
backward_frames = [4.0 - 0.125 * k for k in range(24)]
for color, scalar_range in [(("Velocity", "X"), (-0.3, 0.3)), (("ElementSpin", "Z"), (-0.6, 0.6))]:
    name = "Backward_%s" % "".join(color)
    with bptest.CapturedMessages() as messages:
        image = compare_paths(traces[0], traces[1], color, scalar_range, name,
                              frames=backward_frames, time=1.0)
    bptest.check(bptest.covered_fraction(image) > 0.01, "%s: the strips are drawn" % name)
    bptest.check(not messages.messages, "%s: nothing said: %s" % (name, messages.messages))
    shown_points = traces[1].GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()
    bptest.check(shown_points == 2, "%s: the GPU engine ran (the output has %d points)" %
                 (name, shown_points))
for trace in traces:
    Delete(trace)

# No stale frames: while the GPU display shows the trace, every other consumer
# of the same output gets the CPU result.
view = CreateRenderView(ViewSize=[320, 240])
shown = Show(gpu, view)
shown.SetRepresentationType("Bound Particles")
view.ViewTime = 0.5
Render(view)
gpu.UpdatePipeline(0.5)
fetched = servermanager.Fetch(gpu)
bptest.check(fetched.GetNumberOfPoints() == 1000 * 23,
             "another consumer gets the CPU result: %d points" % fetched.GetNumberOfPoints())
written = os.path.join(args.output, "saved.vtp")
SaveData(written, proxy=gpu)
reader = XMLPolyDataReader(FileName=[written])
reader.UpdatePipeline()
bptest.check(reader.GetDataInformation().GetNumberOfPoints() == 1000 * 23,
             "Save Data writes the CPU result")
Delete(reader)

# The display's decorations (axes grid, selection) get the GPU output's bounds
# and ranges: a frame makes no CPU step, so after it the tracer's own output
# is still the two-point GPU output, while a fetch still gets the elements.
view.ViewTime = 0.6
Render(view)
own = gpu.GetClientSideObject().GetOutputDataObject(0)
bptest.check(own.GetNumberOfPoints() == 2,
             "a GPU frame makes no CPU step: the output has %d points" % own.GetNumberOfPoints())
bptest.check(servermanager.Fetch(gpu).GetNumberOfPoints() == 1000 * 23,
             "after the frame a fetch gets the elements")

# A downstream filter shown in the same view gets the elements for the view's
# time, the very ones the CPU engine gives.
double_force = Calculator(Input=gpu, Function="Force*2", ResultArrayName="DoubleForce")
Show(double_force, view)
view.ViewTime = 0.7
Render(view)
downstream = double_force.GetClientSideObject().GetOutputDataObject(0)
reference = tracer("Fish", "CPU", 1000)
reference.UpdatePipeline(0.7)
expected = reference.GetClientSideObject().GetOutputDataObject(0)
bptest.check(downstream.GetNumberOfPoints() == expected.GetNumberOfPoints() == 1000 * 23,
             "a downstream display gets the elements: %d points" % downstream.GetNumberOfPoints())
same = all(downstream.GetPoint(i) == expected.GetPoint(i) for i in range(0, 23000, 997))
bptest.check(same, "the downstream display's elements are those of its time")
Delete(reference)
Delete(double_force)
Render(view)
Delete(view)
del view

# A trace the CPU engine answers runs once a frame in the Bound Particles
# display: after the first answer the display asks as the other consumers do
# (asked with the GPU request and again by its decorations without it, the
# tracer ran twice a frame). Set to GPU, the display asks for the GPU again.
view = CreateRenderView(ViewSize=[320, 240])
once = tracer("Cross", "CPU", 40)
once_display = Show(once, view)
once_display.SetRepresentationType("Bound Particles")
runs = []
once_algorithm = once.GetClientSideObject()
tag = once_algorithm.AddObserver("StartEvent", lambda *unused: runs.append(1))
view.ViewTime = 0.1
Render(view)
del runs[:]
frames = [0.2 + 0.1 * k for k in range(10)]
for t in frames:
    view.ViewTime = t
    Render(view)
# (Once more when the display learns the window's renderer, after its first
# render: Automatic may then choose otherwise.)
bptest.check(len(runs) <= len(frames) + 1,
             "a CPU trace runs once a frame: %d runs in %d frames" % (len(runs), len(frames)))
once.Engine = "GPU"
view.ViewTime = 1.5
Render(view)
bptest.check(once_algorithm.GetOutputDataObject(0).GetNumberOfPoints() == 2,
             "set to GPU, the display gets the GPU output again")
once_algorithm.RemoveObserver(tag)
Delete(once)
Delete(view)
del view

# A GPU that cannot hold the system: a clear warning, and the display draws the
# CPU result in the same frame.
cpu_image = render(cpu, "Surface", None, None, "Fallback_cpu")
with bptest.CapturedMessages() as messages:
    fallback_image = render(gpu, "Bound Particles", None, None, "Fallback",
                            GpuTextureSizeLimit=64)
bptest.check(messages.mentions("the CPU engine runs this trace instead"),
             "the fallback says so: %s" % messages.messages)
mean, pixels = bptest.image_difference(cpu_image, fallback_image)
bptest.check(mean <= CPU_MEAN and pixels <= CPU_PIXELS,
             "the fallback draws the CPU result: mean %.3f, pixels %.4f" % (mean, pixels))

bptest.finish()
