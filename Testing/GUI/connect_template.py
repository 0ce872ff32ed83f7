# Run from the GUI's Python shell by panel.xml: connects a Sphere as the
# first tracer's Element Template and shows the tracer's panel again.
from paraview.simple import FindSource, SetActiveSource, Sphere

tracer = FindSource("BoundParticleTracer1")
tracer.ElementTemplate = Sphere(ThetaResolution=6, PhiResolution=6)
SetActiveSource(tracer)
