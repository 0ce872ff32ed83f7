# Run from the GUI's Python shell by memory.xml after Edit > Reset Session: a new
# tracer whose Coloring Axis becomes X (which memory.xml checks) when the
# memory of the deleted traces went back to the system. The process holds a
# deleted trace's display until the view next updates, so a reading may hold
# the last cycle's; but over the 20 cycles (memory_cycle.py's readings) what
# is held must not grow (the last ten readings within 50 MiB of the first
# five), and after Reset Session the process holds at most 60 MiB more than
# before the first trace. Written to the terminal.
import ctypes
import os

from paraview.simple import AnalyticFlow, BoundParticleTracer, SetActiveSource


def resident():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024.0
    return 0.0


ctypes.CDLL("libc.so.6").malloc_trim(0)  # as memory_cycle.py
with open(os.path.join(os.environ["HOME"], "memory.txt")) as saved:
    readings = [float(x) for x in saved.read().split()]
after_reset = resident()
growth = max(readings[11:]) - max(readings[1:6]) if len(readings) == 21 else float("inf")
kept = after_reset - readings[0]
os.write(2, ("memory_check: before %.0f MiB; cycles 1-5 up to %.0f, cycles 10-19 up to %.0f "
             "(grew %.0f); after Reset Session %.0f (%.0f more than before)\n" %
             (readings[0], max(readings[1:6]), max(readings[11:]), growth, after_reset,
              kept)).encode())
tracer = BoundParticleTracer(Input=AnalyticFlow())
SetActiveSource(tracer)
if growth < 50.0 and kept < 60.0:
    tracer.ColoringAxis = 0
