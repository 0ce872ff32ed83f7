# Run from the GUI's Python shell by time_back.xml at the last frame: records
# every later update of the first tracer (the time it answered, the steps it
# took, whether it replayed from the start) for check_time_back.py.
import builtins

from paraview.simple import FindSource

proxy = FindSource("BoundParticleTracer1")
updates = []


def ended(*unused):
    # The tracer's information properties: what its last update did.
    proxy.UpdatePropertyInformation()
    updates.append({"time": proxy.GetPropertyValue("SimulationTime"),
                    "steps": proxy.GetPropertyValue("StepsInLastUpdate"),
                    "replayed": bool(proxy.GetPropertyValue("LastUpdateReplayed")),
                    "spacing": proxy.GetPropertyValue("CheckpointSpacing")})


# The client-side algorithm is not wrapped in Python; its end is still seen.
proxy.GetClientSideObject().AddObserver("EndEvent", ended)
builtins._boundparticles_time_back = updates
