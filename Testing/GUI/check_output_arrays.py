# Run from the GUI's Python shell by panel.xml after Vorticity was unticked and
# ElementSpin and ElementFTLE ticked in Output Arrays: when the first tracer's
# output has Force, ElementSpin and ElementFTLE but neither Vorticity nor
# Orientation (a pose array off by default) nor ElementStretch (off by
# default), sets its Coloring Axis to X, which panel.xml then checks.
import gui_check
from paraview.simple import FindSource

tracer = FindSource("BoundParticleTracer1")
arrays = tracer.GetPointDataInformation()
names = [arrays.GetArray(i).GetName() for i in range(arrays.GetNumberOfArrays())]
found = {"%s %s" % (name, "present" if wanted else "absent"): (name in names) == wanted
         for name, wanted in [("Force", True), ("ElementSpin", True), ("ElementFTLE", True),
                              ("ElementStretch", False), ("Vorticity", False),
                              ("Orientation", False)]}
if gui_check.passed("check_output_arrays", found, {"arrays": names}):
    tracer.ColoringAxis = 0
