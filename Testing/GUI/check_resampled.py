# Run from the GUI's Python shell by mesh_input.xml after Resample Dimensions
# was set to 16 12 10 in the panel: when the first tracer's output reports
# that grid in its field data, sets its Coloring Axis to X, which
# mesh_input.xml then checks.
from paraview import servermanager
from paraview.simple import FindSource

tracer = FindSource("BoundParticleTracer1")
output = servermanager.Fetch(tracer)
dims = output.GetFieldData().GetArray("ResampledDimensions")
if dims is not None and [dims.GetValue(i) for i in range(3)] == [16, 12, 10]:
    tracer.ColoringAxis = 0
