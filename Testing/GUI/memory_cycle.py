# Run from the GUI's Python shell by memory.xml, 21 times: one cycle of a
# tracer made, played over four frames and deleted: 8,000 Strip16 elements
# on the CPU engine and the Surface display (about 40 MiB of trace and
# output), or, in every other cycle, 2,000 on the GPU engine and the Bound
# Particles display.
# The process's resident memory as the run starts (after the last cycle's
# delete, which ParaView completes between two runs) is appended to
# memory.txt in the test's home folder (memory_check.py reads it) and written
# to the terminal.
import os

import gui_check
from paraview.simple import (AnalyticFlow, BoundParticleTracer, Delete, FindSource,
                             GetActiveView, GetAnimationScene, Render, Show)

saved = os.path.join(os.environ["HOME"], "memory.txt")
flow = FindSource("Flow")
if flow is None:
    flow = AnalyticFlow(registrationName="Flow", Flow="Shear Layer", Resolution=[32, 32, 32])
    Show(flow).SetRepresentationType("Outline")
    Render()
    open(saved, "w").close()
with open(saved) as past:
    cycle = len(past.read().split())
# No malloc_trim here: the plugin hands freed memory back itself (the GUI a
# moment after a tracer's displays are gone, pqBoundParticleDisplays), which
# is what this test checks.
reading = gui_check.resident_mib()
with open(saved, "a") as out:
    out.write("%.1f " % reading)
gui_check.say("memory_cycle", "%.0f MiB before cycle %d" % (reading, cycle))
# The 21st run only reads the memory after the 20th cycle. (No SystemExit:
# in the GUI's Python shell it quits ParaView.)
if cycle < 20:
    gpu = cycle % 2 == 1
    tracer = BoundParticleTracer(Input=flow, ElementShape="Strip16",
                                 NumberOfElements=2000 if gpu else 8000, NumberOfTimeSteps=4,
                                 Engine="GPU" if gpu else "CPU")
    display = Show(tracer, GetActiveView())
    if gpu:
        display.SetRepresentationType("Bound Particles")
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.Play()
    Delete(display)
    Delete(tracer)
    Render()
