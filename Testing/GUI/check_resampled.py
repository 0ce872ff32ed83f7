# Run from the GUI's Python shell by mesh_input.xml after Resample Dimensions
# was set to 16 12 10 in the panel: when the first tracer's output reports
# that grid in its field data, sets its Coloring Axis to X, which
# mesh_input.xml then checks.
import gui_check
from paraview import servermanager
from paraview.simple import FindSource

tracer = FindSource("BoundParticleTracer1")
output = servermanager.Fetch(tracer)
dims = output.GetFieldData().GetArray("ResampledDimensions")
values = [dims.GetValue(i) for i in range(3)] if dims is not None else None
if gui_check.passed("check_resampled", {"resampled onto 16 x 12 x 10": values == [16, 12, 10]},
                    {"ResampledDimensions": values}):
    tracer.ColoringAxis = 0
