# Run from the GUI's Python shell by engine_messages.xml (issue 53, item 11).
# First (Coloring Axis Z, the default): the tracer applied with Engine
# Automatic and shown as Bound Particles through the representation box;
# sets Coloring Axis X. Second (Engine GPU applied since): sets Coloring Axis
# Y. Each step also says on the terminal whether the window draws with a
# software renderer: run_engine_messages.sh counts the engines' lines that
# the GUI's output window wrote there. (The shell cannot listen to Output
# Messages itself: while it runs, VTK's output window is the shell's own.)
import gui_check
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties

tracer = FindSource("BoundParticleTracer1")
view = GetActiveView()
renderer = view.GetRenderWindow().ReportCapabilities()
software = any(name in renderer for name in ("llvmpipe", "softpipe", "swrast"))
representation = GetDisplayProperties(tracer, view).Representation
seen = {"engine": tracer.Engine, "representation": representation}
gui_check.say("check_engine_messages", "software renderer: %s" % ("yes" if software else "no"))
if tracer.ColoringAxis == "Z":
    found = {"Automatic": tracer.Engine == "Automatic",
             "Bound Particles": representation == "Bound Particles"}
    if gui_check.passed("check_engine_messages (Automatic)", found, seen):
        tracer.ColoringAxis = "X"
else:
    found = {"GPU": tracer.Engine == "GPU", "Bound Particles": representation == "Bound Particles"}
    if gui_check.passed("check_engine_messages (GPU)", found, seen):
        tracer.ColoringAxis = "Y"
