"""Plots bench/play_frames.py's CSV: where a frame of Play goes, per engine and display.

Each bar is one frame split into the tracer's update (the CPU engine's step
and the output), the draw (the same frame drawn again with only the camera
moved) and the rest (ParaView's data information, geometry filter, buffer
uploads; with the GPU engine, its passes on this machine's llvmpipe).

    python3 bench/plot_play.py play_frames.csv play_frames.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
counts = sorted({int(r["elements"]) for r in rows})
fig, axes = plt.subplots(1, len(counts), figsize=(6 * len(counts), 4.5))
axes = axes if len(counts) > 1 else [axes]
for axis, count in zip(axes, counts):
    sel = [r for r in rows if int(r["elements"]) == count]
    labels, step, output, draw, rest = [], [], [], [], []
    for r in sel:
        engine_step = float(r["step"]) if r["engine"] == "CPU" else 0.0
        update = float(r["update"])
        frame, drawn = float(r["frame"]), float(r["draw"])
        labels.append("%s\n%s\n%s arrays" % (r["engine"], r["display"], r["arrays"]))
        step.append(engine_step)
        output.append(max(0.0, update - engine_step))
        draw.append(drawn)
        rest.append(max(0.0, frame - update - drawn))
    x = range(len(sel))
    bottom = [0.0] * len(sel)
    for values, name, colour in ((step, "engine step (CPU)", "tab:green"),
                                 (output, "output arrays", "tab:olive"),
                                 (draw, "draw", "tab:blue"),
                                 (rest, "rest of the frame", "tab:gray")):
        axis.bar(x, values, bottom=bottom, color=colour, label=name)
        bottom = [b + v for b, v in zip(bottom, values)]
    axis.set_xticks(list(x))
    axis.set_xticklabels(labels, fontsize=7)
    axis.set_ylabel("ms per frame")
    axis.set_title("%d Strip16 elements (%d particles)" % (count, 16 * count))
    axis.grid(True, axis="y", alpha=0.3)
axes[0].legend(fontsize=8)
fig.suptitle("A frame of Play in ParaView (llvmpipe, 2 cores): frame = update + draw + rest")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
