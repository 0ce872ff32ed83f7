"""What one update of a Bound Particle Tracer costs, for the pvpython benches
(play_frames.py, smp_loops.py): the one-step update and the engine's step."""
import statistics
import time


def update_and_step_ms(tracer, warmup, updates, long_steps, repeats):
    """(update, step) in ms for a tracer whose time line has at least
    warmup + updates + long_steps * repeats + 1 steps: the median of `updates`
    one-step updates after `warmup` of them, and the median over `repeats`
    updates of `long_steps` steps each of their time per step."""
    times = list(tracer.TimestepValues)
    tracer.UpdatePipeline(times[0])
    one_step = []
    for k in range(1, warmup + updates + 1):
        start = time.perf_counter()
        tracer.UpdatePipeline(times[k])
        one_step.append(time.perf_counter() - start)
    per_step = []
    for r in range(1, repeats + 1):
        start = time.perf_counter()
        tracer.UpdatePipeline(times[warmup + updates + r * long_steps])
        per_step.append((time.perf_counter() - start) / long_steps)
    return 1e3 * statistics.median(one_step[warmup:]), 1e3 * statistics.median(per_step)


def shear_layer(analytic_flow, res):
    """The pvpython benches' field: the shear layer at res^3 points, and the
    step that moves its fastest point (speed 1.25) half a cell.
    `analytic_flow` is the plugin's AnalyticFlow constructor."""
    flow = analytic_flow(Flow="Shear Layer", Resolution=[res, res, res])
    flow.UpdatePipeline()
    return flow, 0.5 * (2.0 / (res - 1)) / 1.25


def strip16_tracer(tracer_class, flow, dt, elements, steps, **properties):
    """A Bound Particle Tracer (`tracer_class`) of `elements` Strip16 on
    `flow`'s velocity, `steps` time steps dt apart, element size 0.04, with
    `properties` on top."""
    settings = dict(Input=flow, Vectors=["POINTS", "velocity"], ElementShape="Strip16",
                    NumberOfElements=elements, StepSizeUnit="Time", StepSize=dt,
                    ElementSize=0.04, Duration=dt * (steps - 1), NumberOfTimeSteps=steps)
    settings.update(properties)
    return tracer_class(**settings)
