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
