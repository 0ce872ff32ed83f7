"""Plots bench/run.sh's CSV: particle-steps per second against element count."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
for axis, field in zip(axes, ("steady", "unsteady")):
    for shape, colour in (("Square", "tab:blue"), ("Strip8", "tab:orange"), ("Strip16", "tab:green")):
        sel = [r for r in rows if r["field"] == field and r["shape"] == shape]
        if not sel:
            continue
        n = [int(r["elements"]) for r in sel]
        axis.plot(n, [float(r["cpu2_particle_steps_per_s"]) for r in sel], "-o", color=colour,
                  label="%s CPU, 2 threads" % shape)
        for path, style in (("fragment", "--s"), ("compute", "-.^"), ("fused", "--D")):
            gpu = [float(r.get("%s_particle_steps_per_s" % path) or 0) for r in sel]
            if any(gpu):
                axis.plot(n, gpu, style, color=colour, alpha=0.8,
                          label="%s GPU engine, %s (headless EGL)" % (shape, path))
        axis.plot(n, [float(r["plain2_particle_steps_per_s"]) for r in sel], ":", color=colour,
                  alpha=0.6, label="%s plain Euler loop" % shape)
    axis.set_xscale("log", base=2)
    axis.set_yscale("log")
    axis.set_xlabel("elements")
    axis.set_title("%s field" % field)
    axis.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel("particle-steps per second")
axes[1].legend(fontsize=7, loc="lower right")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
