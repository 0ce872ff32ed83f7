# Run from the GUI's Python shell by defaults.xml after the tracer was applied
# to an Analytic Flow with its defaults: when the flow's outline is still shown,
# the tracer's display is coloured by Speed and its other outputs (the FTLE
# Map, port 1, empty for a random release; State, port 2; Interactions, port
# 3) have no display in the view, sets the tracer's Number
# Of Elements to 999, which defaults.xml then checks; what failed is printed.
import gui_check
from paraview.simple import FindSource, GetActiveView, GetDisplayProperties

view = GetActiveView()
flow = GetDisplayProperties(FindSource("AnalyticFlow1"), view)
tracer = FindSource("BoundParticleTracer1")
elements = GetDisplayProperties(tracer, view)
# The tracer's ports shown by a visible display in the view.
shown_ports = []
for r in view.Representations:
    given = r.SMProxy.GetProperty("Input")
    if given is not None and given.GetNumberOfProxies() > 0 and r.Visibility and \
            given.GetProxy(0) == tracer.SMProxy:
        shown_ports.append(given.GetOutputPortForConnection(0))
found = {
    "outline kept": flow.Visibility == 1 and flow.Representation == "Outline",
    "coloured by Speed": list(elements.ColorArrayName) == ["POINTS", "Speed"],
    "FTLE Map, State and Interactions not shown": shown_ports == [0],
}
if gui_check.passed("check_defaults", found, {"ports shown": shown_ports}):
    # Number Of Elements, not Coloring Axis as the other checks: ParaView
    # 5.13's panel kept that combo box at Z here though the property held X.
    tracer.NumberOfElements = 999
