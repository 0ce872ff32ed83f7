# Run from the GUI's Python shell by panel.xml after Vorticity was unticked in
# Output Arrays: when the first tracer's output has Force but not Vorticity,
# sets its Coloring Axis to X, which panel.xml then checks in the panel.
from paraview.simple import FindSource

tracer = FindSource("BoundParticleTracer1")
arrays = tracer.GetPointDataInformation()
names = [arrays.GetArray(i).GetName() for i in range(arrays.GetNumberOfArrays())]
if "Force" in names and "Vorticity" not in names:
    tracer.ColoringAxis = 0
