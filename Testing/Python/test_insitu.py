"""In situ (issue 42): the tracer on an input that offers only its present
time step, fed one step at a time through a trivial producer (Catalyst's
producer before VTK 9.3 flags anything), advances with each step that arrives
and gets the elements a post hoc trace of the same steps gets; a repeated or
earlier step is refused with a message and the trace keeps its state; a
step without the vector array is an error and is skipped, the next good step
going on from the last one; a step whose grid changes (dimensions, origin,
spacing) warns and goes on in the new grid with every element kept, and
elements outside a grid that shrank or moved are released again into it.
"""
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402

args = bptest.arguments("--engine", "--steps")

from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402

LoadPlugin(args.plugin, ns=globals())
STEPS = int(args.steps or 20)
SETTINGS = dict(Vectors=["POINTS", "velocity"], ElementShape="Paddlewheel", NumberOfElements=200,
                Seed=3, Engine=args.engine or "CPU")

flow = AnalyticFlow(Flow="Double Gyre", Resolution=[40, 20, 2], Bounds=[0, 2, 0, 1, 0, 0.05],
                    NumberOfTimeSteps=STEPS)
flow.UpdatePipeline()
times = list(flow.TimestepValues)
bptest.check(len(times) == STEPS, "the flow offers %d time steps (%d)" % (STEPS, len(times)))


def elements(proxy, time):
    proxy.UpdatePipeline(time)
    data = servermanager.Fetch(proxy)
    if not data.GetNumberOfPoints():
        return {}
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
    index = vtk_to_numpy(data.GetPointData().GetArray("ParticleIndex"))
    points = vtk_to_numpy(data.GetPoints().GetData()) if data.GetNumberOfPoints() else None
    return {(int(e), int(p)): points[k] for k, (e, p) in enumerate(zip(ids, index))}


def step_of(time):
    """The flow's data at `time`, as a simulation would hand it over."""
    flow.UpdatePipeline(time)
    data = flow.GetClientSideObject().GetOutputDataObject(0).NewInstance()
    data.DeepCopy(flow.GetClientSideObject().GetOutputDataObject(0))
    return data


def farthest(a, b):
    if set(a) != set(b):
        return float("inf")
    return max(abs(a[key] - b[key]).max() for key in a)


posthoc = BoundParticleTracer(Input=flow, **SETTINGS)
reference = {t: elements(posthoc, t) for t in (times[STEPS // 2], times[-1])}

producer = PVTrivialProducer()
insitu = BoundParticleTracer(Input=producer, **SETTINGS)
# Made before the simulation's first step, the tracer has no bounds to take
# its emitter box from: the default box spans the field (6.1's BoundsDomain
# gave size 0, every element at one point).
bptest.check(list(insitu.EmitterSize) == [-1.0, -1.0, -1.0],
             "a tracer made before the first step spans the field: Emitter Size %s"
             % list(insitu.EmitterSize))
with bptest.CapturedMessages() as said:
    for k, t in enumerate(times):
        producer.GetClientSideObject().SetOutput(step_of(t), t)
        producer.MarkModified(producer)
        got = elements(insitu, t)
        if t in reference:
            gap = farthest(got, reference[t])
            print("t = %g: in situ and post hoc %g apart" % (t, gap))
            bptest.check(gap <= 1e-4 * 2.0, "in situ equals post hoc at t = %g (%g apart)" % (t, gap))
said.messages = [m for m in said.messages if "New time step is not" not in m]  # ParaView's own
bptest.check(not said.messages, "no messages while the steps increase: %s" % said.messages)

# A repeated step and an earlier one are refused; the trace stays.
last = elements(insitu, times[-1])
for t in (times[-1], times[-3]):
    with bptest.CapturedMessages() as said:
        producer.GetClientSideObject().SetOutput(step_of(t), t)
        producer.MarkModified(producer)
        kept = elements(insitu, t)
    bptest.check(said.mentions("the step is refused"), "step t = %g refused: %s" % (t, said.messages))
    bptest.check(farthest(kept, last) == 0.0, "the trace keeps its state after t = %g" % t)

# A step one interval on continues the trace as post hoc would.
dt = times[1] - times[0]
later = times[-1] + dt
longer = AnalyticFlow(Flow="Double Gyre", Resolution=[40, 20, 2], Bounds=[0, 2, 0, 1, 0, 0.05],
                      NumberOfTimeSteps=STEPS + 1)
longer.UpdatePipeline()
bptest.check(abs(list(longer.TimestepValues)[-1] - later) < 1e-9, "the longer flow ends one step on")
flow.NumberOfTimeSteps = STEPS + 1
producer.GetClientSideObject().SetOutput(step_of(later), later)
producer.MarkModified(producer)
gap = farthest(elements(insitu, later), elements(BoundParticleTracer(Input=longer, **SETTINGS), later))
bptest.check(gap <= 2e-4, "after refused steps the trace goes on as post hoc (%g apart)" % gap)
# A first step with no finite time is an error and an empty output; the next
# good step starts the trace.
fresh_producer = PVTrivialProducer()
fresh = BoundParticleTracer(Input=fresh_producer, **SETTINGS)
with bptest.CapturedMessages() as said:
    fresh_producer.GetClientSideObject().SetOutput(step_of(times[0]), float("nan"))
    fresh_producer.MarkModified(fresh_producer)
    fresh.UpdatePipeline()
    empty = servermanager.Fetch(fresh).GetNumberOfPoints()
bptest.check(said.mentions("must have a finite time") and empty == 0,
             "a step at NaN: error and empty output (%d points): %s" % (empty, said.messages))
fresh_producer.GetClientSideObject().SetOutput(step_of(times[1]), times[1])
fresh_producer.MarkModified(fresh_producer)
bptest.check(len(elements(fresh, times[1])) > 0, "the next good step starts the trace")
# Backward needs the whole time series: in situ, where only the present step
# comes, it is refused with a message and an empty output.
backward_feed = PVTrivialProducer()
backward = BoundParticleTracer(Input=backward_feed, **dict(SETTINGS, TimeDirection="Backward"))
with bptest.CapturedMessages() as said:
    backward_feed.GetClientSideObject().SetOutput(step_of(times[0]), times[0])
    backward_feed.MarkModified(backward_feed)
    backward.UpdatePipeline(times[0])
    empty = servermanager.Fetch(backward).GetNumberOfPoints()
bptest.check(said.mentions("Time Direction = Backward needs the whole time series") and empty == 0,
             "in situ backward: refused, empty output (%d points): %s" % (empty, said.messages))
Delete(backward)
Delete(backward_feed)


def trace_in_situ(step_at, settings, take=elements):
    """The tracer fed step_at(k, t) for each time (None: that step never
    comes); take(tracer, t) at the last step fed (its elements by default),
    and the messages said."""
    feed = PVTrivialProducer()
    tracer = BoundParticleTracer(Input=feed, **settings)
    with bptest.CapturedMessages() as said:
        for k, t in enumerate(times):
            data = step_at(k, t)
            if data is not None:
                feed.GetClientSideObject().SetOutput(data, t)
                feed.MarkModified(feed)
                got = take(tracer, t)
    said.messages = [m for m in said.messages if "New time step is not" not in m]
    Delete(tracer)
    Delete(feed)
    return got, said


# A step without the Vectors array: an error, the step skipped, and the next
# good step goes on from the last one, as if the bad step had never come.
def renamed(t):
    data = step_of(t)
    data.GetPointData().GetArray("velocity").SetName("pressure_gradient")
    return data


BAD = STEPS // 2
skipped, said = trace_in_situ(lambda k, t: renamed(t) if k == BAD else step_of(t), SETTINGS)
bptest.check(said.mentions("no array 'velocity'") and said.mentions("is skipped"),
             "a step without the vectors: an error that says the step is skipped: %s" % said.messages)
never, _ = trace_in_situ(lambda k, t: None if k == BAD else step_of(t), SETTINGS)
gap = farthest(skipped, never)
print("a skipped step: %d particles, %g from a trace never given it" % (len(skipped), gap))
bptest.check(len(skipped) > 0 and gap == 0.0,
             "after a skipped step the trace goes on as if it never came (%g apart)" % gap)


# A step whose Vectors are only a cell array (issue 53, item 7): ParaView
# interpolates it to the points for the tracer, as it does post hoc; the
# tracer says so (the point array asked for is missing, only a cell array
# is there) and traces it, in situ as post hoc.
def cells_only(t, name="velocity"):
    data = step_of(t)
    data.GetPointData().RemoveArray("velocity")
    zeros = numpy_to_vtk(numpy.zeros((data.GetNumberOfCells(), 3), dtype=numpy.float32), deep=1)
    zeros.SetName(name)
    data.GetCellData().AddArray(zeros)
    return data


CELLS_SAID = "only a cell array 'velocity'"
from_cells, said = trace_in_situ(lambda k, t: cells_only(t) if k == BAD else step_of(t), SETTINGS)
print("a step with cell Vectors only: %s" % said.messages)
bptest.check(said.mentions(CELLS_SAID) and said.mentions("no point array 'velocity'") and len(said.messages) == 1,
             "a step with cell Vectors only: one warning that the point array is missing and the cell "
             "array is traced (%s)" % said.messages)
bptest.check(len(from_cells) > 0 and farthest(from_cells, never) > 0.0,
             "a step with cell Vectors only is traced, not skipped (%g from a trace never given it)"
             % farthest(from_cells, never))
_, said = trace_in_situ(lambda k, t: cells_only(t, "pressure_gradient") if k == BAD else step_of(t), SETTINGS)
bptest.check(said.mentions("no array 'velocity'") and said.mentions("is skipped") and not said.mentions(CELLS_SAID),
             "a step whose cell array has another name: skipped as without the vectors (%s)" % said.messages)
# Post hoc the same: a grid with cell Vectors only.
cell_flow = PointDatatoCellData(Input=flow)
cell_flow.PassPointData = 0
with bptest.CapturedMessages() as said:
    got = elements(BoundParticleTracer(Input=cell_flow, **SETTINGS), times[2])
bptest.check(len(got) > 0 and said.mentions(CELLS_SAID),
             "post hoc, cell Vectors only: traced with the same warning (%s)" % said.messages)


# A step whose grid changes: solid-body rotation about the z axis, linear in
# x and y, so every grid samples it exactly and a trace that changes grids
# must follow the one that never does. The second grid has other dimensions,
# origin and spacing, and covers every element.
def rotation(grid, scale=1.0):
    dims, origin, spacing = grid
    image = vtkImageData()
    image.SetDimensions(dims)
    image.SetOrigin(origin)
    image.SetSpacing(spacing)
    z, y, x = numpy.meshgrid(*[origin[a] + spacing[a] * numpy.arange(dims[a]) for a in (2, 1, 0)],
                             indexing="ij")
    velocity = numpy_to_vtk((scale * numpy.stack([-y, x, 0 * x], axis=-1)).reshape(-1, 3).astype(numpy.float32),
                            deep=1)
    velocity.SetName("velocity")
    image.GetPointData().AddArray(velocity)
    return image


FIRST = ((41, 41, 2), (-1.0, -1.0, 0.0), (0.05, 0.05, 0.05))
OTHER = ((47, 53, 2), (-1.13, -1.07, 0.0), (0.049, 0.0431, 0.05))
ROTATION = dict(SETTINGS, EmitterCenter=[0, 0, 0.025], EmitterSize=[0.8, 0.8, 0], LifetimeRange=[20, 30])
kept, _ = trace_in_situ(lambda k, t: rotation(FIRST), ROTATION)
for name, grid_at in (("once", lambda k: OTHER if k >= BAD else FIRST),
                      ("back and forth", lambda k: OTHER if k % 3 == 2 else FIRST)):
    moved, said = trace_in_situ(lambda k, t: rotation(grid_at(k)), ROTATION)
    gap = farthest(moved, kept)
    print("the grid changed %s: %d particles, %g from a trace on one grid" % (name, len(moved), gap))
    bptest.check(len(moved) > 0 and gap <= 1e-5, "grid changed %s: every element goes on (%g apart)"
                 % (name, gap))
    warned = [m for m in said.messages if "grid changed at t = %g" % times[BAD if name == "once" else 2] in m]
    bptest.check(len(warned) == 1 and len(said.messages) == 1,
                 "grid changed %s: one warning, at the first change (%s)" % (name, said.messages))


# The grid shrinks and moves (issue 53, item 2): elements outside the new grid
# are released again into the new grid, not into the first grid's box, with
# the emitter box spanning the field (EmitterSize -1) or set to the first
# grid's bounds (as the GUI's default box is). A slow rotation (at most 0.1
# a step), so an element outside the new grid by more than that at a step
# was released outside it.
SHRUNK = ((23, 21, 2), (-0.6, -0.45, 0.0), (0.05, 0.05, 0.05))


def outside_new_grid(settings):
    """The largest share of elements whose centre lies outside SHRUNK by
    more than 0.1, over the steps after the change, and the messages."""
    feed = PVTrivialProducer()
    tracer = BoundParticleTracer(Input=feed, **settings)
    dims, origin, spacing = SHRUNK
    low = numpy.array(origin[:2])
    high = low + numpy.array(spacing[:2]) * (numpy.array(dims[:2]) - 1)
    shares = []
    with bptest.CapturedMessages() as said:
        for k, t in enumerate(times):
            feed.GetClientSideObject().SetOutput(rotation(SHRUNK if k >= BAD else FIRST, 0.1), t)
            feed.MarkModified(feed)
            got = elements(tracer, t)
            if k <= BAD or not got:
                continue
            centres = {}
            for (e, _), xyz in got.items():
                centres.setdefault(e, []).append(xyz[:2])
            centre = numpy.array([numpy.mean(c, axis=0) for c in centres.values()])
            out = numpy.any((centre < low - 0.1) | (centre > high + 0.1), axis=1)
            shares.append(float(out.mean()))
    said.messages = [m for m in said.messages if "New time step is not" not in m]
    Delete(tracer)
    Delete(feed)
    return max(shares) if shares else 1.0, len(shares), said


for name, box in (("spanning the field", {}),
                  ("the first grid's bounds", dict(EmitterCenter=[0, 0, 0.025], EmitterSize=[2, 2, 0.05]))):
    share, steps, said = outside_new_grid(dict(SETTINGS, LifetimeRange=[20, 30], **box))
    print("the grid shrank and moved, emitter box %s: at most %.1f%% of the elements outside the new grid "
          "over %d steps" % (name, 100 * share, steps))
    bptest.check(steps > 0 and share == 0.0, "the grid shrank and moved, emitter box %s: releases land in "
                 "the new grid (%.1f%% of the elements outside it)" % (name, 100 * share))
    bptest.check(said.mentions("released again, into the new grid") and len(said.messages) == 1,
                 "the grid shrank and moved: one warning, that says where releases land (%s)" % said.messages)


# A restart from a saved state (issue 57): a trace's State saved at step K,
# and a new tracer whose Initial State File it is, fed from step K on as a
# simulation restarted from its checkpoint K would feed it, ends on the bits
# of the trace that never stopped. A state saved at another step than the
# first one fed is not used, and said so once; one saved by other settings
# is an error naming the setting (an empty output at that step), and the
# trace starts at the next step without it.
KEEP = STEPS // 2
states = bptest.scratch("bp-insitu-state-")
state_file = os.path.join(states, "state.vtp")


def save_state_in_situ(settings, path, keep=KEEP):
    feed = PVTrivialProducer()
    tracer = BoundParticleTracer(Input=feed, **settings)
    for t in times[:keep + 1]:
        feed.GetClientSideObject().SetOutput(step_of(t), t)
        feed.MarkModified(feed)
        tracer.UpdatePipeline(t)
    SaveData(path, proxy=OutputPort(tracer, 2))
    Delete(tracer)
    Delete(feed)


save_state_in_situ(SETTINGS, state_file)


def point_arrays(tracer, t):
    """Every point array of the tracer's output at t (with the points), by name."""
    tracer.UpdatePipeline(t)
    out = servermanager.Fetch(tracer)
    arrays = {}
    if out.GetNumberOfPoints():
        arrays["points"] = vtk_to_numpy(out.GetPoints().GetData()).copy()
        for i in range(out.GetPointData().GetNumberOfArrays()):
            array = out.GetPointData().GetArray(i)
            arrays[array.GetName()] = vtk_to_numpy(array).copy()
    return arrays


def last_output(step_at, settings):
    """trace_in_situ's, with every point array of the last output."""
    return trace_in_situ(step_at, settings, take=point_arrays)


never_stopped, _ = last_output(lambda k, t: step_of(t), SETTINGS)
restarted, said = last_output(lambda k, t: step_of(t) if k >= KEEP else None,
                              dict(SETTINGS, InitialStateFile=state_file))
bptest.check(not said.messages, "a restart in situ says nothing: %s" % said.messages)
bptest.check(len(never_stopped) > 1 and restarted.keys() == never_stopped.keys() and
             all(numpy.array_equal(restarted[k], never_stopped[k]) for k in never_stopped),
             "restarted in situ from step %d: every array has the bits of the trace that never "
             "stopped (%s)" % (KEEP, sorted(never_stopped)))
late, said = last_output(lambda k, t: step_of(t) if k >= KEEP + 2 else None,
                         dict(SETTINGS, InitialStateFile=state_file))
unused = [m for m in said.messages if "it is not used" in m]
bptest.check(len(unused) == 1 and len(said.messages) == 1 and late, "a state at another step than "
             "the first fed: said once, the trace starts there: %s" % said.messages)
other, said = last_output(lambda k, t: step_of(t) if k >= KEEP else None,
                          dict(SETTINGS, NumberOfElements=150, InitialStateFile=state_file))
refusals = [m for m in said.messages if "numberOfElements" in m]
bptest.check(refusals and len(refusals) == len(said.messages) and other,
             "a state of other settings in situ: said by name at the restart step only, then "
             "the trace starts at the next step without it: %s" % said.messages)
# Seed Type Surface across the unsteady gyre (the line y = 0.5, where the
# profile of v along x moves with the gyres): its points are drawn at the
# first step handed, after the restart the restart step's, and a state keeps
# only their hash: the restart is refused (by the emitter box fitted around
# them, named first), with why, and the trace starts at the next step
# without it. (Saved at step 3: the gyre
# of step KEEP, half its period on, is the start's again.)
SURFACE = dict(SETTINGS, SeedType="Surface",
               SeedSource=Plane(Origin=[0, 0.5, 0], Point1=[2, 0.5, 0], Point2=[0, 0.5, 0.05],
                                XResolution=40))
surface_state = os.path.join(states, "surface.vtp")
save_state_in_situ(SURFACE, surface_state, keep=3)
inlet, said = last_output(lambda k, t: step_of(t) if k >= 3 else None,
                          dict(SURFACE, InitialStateFile=surface_state))
refusals = [m for m in said.messages if "was saved by a trace that differs" in m]
bptest.check(refusals and len(refusals) == len(said.messages) and
             all("Seed Type Surface draws its points" in m for m in refusals) and inlet,
             "a Surface restarted in situ in an unsteady flow: refused, with why (%s)" %
             said.messages)
missing, said = last_output(lambda k, t: step_of(t) if k >= KEEP else None,
                            dict(SETTINGS, InitialStateFile=os.path.join(states, "none.vtp")))
bptest.check(said.messages and all("none.vtp" in m for m in said.messages) and missing,
             "a missing state in situ: said at the restart step only, then the trace starts "
             "without it: %s" % said.messages)


# Times of the size of seconds since 1970 (1.7e9: doubles 2.4e-7 apart): a
# simulation restarted from its checkpoint that computes its restart time
# anew, a few units in the last place from the time it saved at, restarts
# (one time within the times' rounding, bp::TracePlan::sameTime) and goes on
# as the trace that never stopped, within float rounding of the field's
# weights; a restart step 0.1 later is another step, not used.
EPOCH = 1.7e9


def at_epoch(first, settings, restart=0.0, save=None):
    """The tracer fed the steps from `first` on at EPOCH + t, the first one
    `restart` later; its elements at the last step (or, with `save`, the
    State output saved at step KEEP) and the messages said."""
    feed = PVTrivialProducer()
    tracer = BoundParticleTracer(Input=feed, **settings)
    got = {}
    with bptest.CapturedMessages() as said:
        for k, t in enumerate(times[:KEEP + 1] if save else times):
            if k < first:
                continue
            handed = EPOCH + t + (restart if k == first else 0.0)
            feed.GetClientSideObject().SetOutput(step_of(t), handed)
            feed.MarkModified(feed)
            tracer.UpdatePipeline(handed)
        if save:
            SaveData(save, proxy=OutputPort(tracer, 2))
        else:
            got = elements(tracer, handed)
    said.messages = [m for m in said.messages if "New time step is not" not in m]
    Delete(tracer)
    Delete(feed)
    return got, said


epoch_state = os.path.join(states, "epoch.vtp")
at_epoch(0, SETTINGS, save=epoch_state)
epoch_straight, _ = at_epoch(0, SETTINGS)
saved_at = EPOCH + times[KEEP]
nudge = numpy.nextafter(numpy.nextafter(numpy.nextafter(saved_at, 2 * EPOCH), 2 * EPOCH),
                        2 * EPOCH) - saved_at  # three units in the last place
epoch_restarted, said = at_epoch(KEEP, dict(SETTINGS, InitialStateFile=epoch_state),
                                 restart=float(nudge))
gap = farthest(epoch_restarted, epoch_straight)
print("times at 1.7e9, restarted %g later than saved: %g from the trace that never stopped"
      % (nudge, gap))
bptest.check(not said.messages and gap <= 1e-4 * 2.0,
             "times at 1.7e9: a restart %g after the saved time goes on from the state (%g from "
             "the trace that never stopped): %s" % (nudge, gap, said.messages[:2]))
_, said = at_epoch(KEEP, dict(SETTINGS, InitialStateFile=epoch_state), restart=0.1)
bptest.check(said.mentions("it is not used"),
             "times at 1.7e9: a restart step 0.1 after the saved time is another step, the state "
             "not used: %s" % said.messages[:2])


# The GPU engine behind a Bound Particles display follows the same changes of
# grid: its picture is the one of a trace on one grid, pixel for pixel.
def gpu_picture(name, grid_at):
    feed = PVTrivialProducer()
    tracer = BoundParticleTracer(Input=feed, **dict(ROTATION, Engine="GPU", NumberOfElements=400))
    view = CreateRenderView(ViewSize=[240, 240], OrientationAxesVisibility=0)
    shown = Show(tracer, view)
    shown.SetRepresentationType("Bound Particles")
    view.CameraPosition = [0, 0, 6]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    for k, t in enumerate(times):
        feed.GetClientSideObject().SetOutput(rotation(grid_at(k)), t)
        feed.MarkModified(feed)
        view.ViewTime = t
        Render(view)
    path = os.path.join(folder, name + ".png")
    SaveScreenshot(path, view)
    Delete(view)
    return path


folder = bptest.scratch("bp-insitu-post-")
gpu_picture("warm-up", lambda k: FIRST)  # a session's first view draws apart
one_grid = gpu_picture("one-grid", lambda k: FIRST)
bptest.check(bptest.covered_fraction(one_grid) > 0.005,
             "the GPU picture shows elements (%g covered)" % bptest.covered_fraction(one_grid))
for name, grid_at in (("once", lambda k: OTHER if k >= BAD else FIRST),
                      ("back-and-forth", lambda k: OTHER if k % 3 == 2 else FIRST)):
    mean, differing = bptest.image_difference(one_grid, gpu_picture(name, grid_at))
    print("GPU, the grid changed %s: %g of the pixels differ from one grid's picture" % (name, differing))
    bptest.check(differing <= 0.0005, "GPU, the grid changed %s: the picture of one grid (%g of the "
                 "pixels differ, mean %g)" % (name, differing, mean))
bptest.finish()
