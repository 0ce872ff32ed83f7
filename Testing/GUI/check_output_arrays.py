# Run from the GUI's Python shell by panel.xml after Vorticity was unticked and
# ElementSpin and ElementFTLE ticked in Output Arrays: when the first tracer's
# output has Force, ElementSpin and ElementFTLE but neither Vorticity nor
# Orientation (a pose array off by default) nor ElementStretch (off by
# default), sets its Coloring Axis to X, which panel.xml then checks.
from paraview.simple import FindSource

tracer = FindSource("BoundParticleTracer1")
arrays = tracer.GetPointDataInformation()
names = [arrays.GetArray(i).GetName() for i in range(arrays.GetNumberOfArrays())]
if (
    "Force" in names
    and "ElementSpin" in names
    and "ElementFTLE" in names
    and "ElementStretch" not in names
    and "Vorticity" not in names
    and "Orientation" not in names
):
    tracer.ColoringAxis = 0
