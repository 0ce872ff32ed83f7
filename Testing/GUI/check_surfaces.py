# Run from the GUI's Python shell by surfaces.xml, after the frames were
# played to t = 6 (one Next Frame at a time) with the panel's Gates, Outlets
# and Walls settings applied to its tracer: solid-body rotation about z, 10
# squares released near (0, 0.5, 0), the Surfaces a half-plane y = 0,
# x from 0 to 1, whose cell array Kind is 1 (Outlet) everywhere. By the
# panel's settings it expects, from the Interactions output (port 3):
#  - Gate, Surface Interaction Array None: each element Passed (5) once,
#    about t = 3 pi / 2, still drawn; says so by setting Coloring Axis to X;
#  - Outlet, None: each element Terminated (1) there, none drawn: Y;
#  - Gate, Surface Interaction Array Kind (1, Outlet, per cell): as Outlet: Z.
# Every event on the Surfaces' block 0 (SurfaceId 6), on the plane.
import gui_check
import numpy as np
from paraview import servermanager
from paraview.simple import FindSource, GetAnimationScene
from vtkmodules.util.numpy_support import vtk_to_numpy

PASSED, TERMINATED = 5, 1
COUNT = 10
tracer = FindSource("BoundParticleTracer1")


def check():
    time = GetAnimationScene().AnimationTime
    tracer.UpdatePipeline(time)
    events = servermanager.Fetch(tracer, None, None, 3)
    kinds = vtk_to_numpy(events.GetPointData().GetArray("Interaction"))
    ids = vtk_to_numpy(events.GetPointData().GetArray("SurfaceId"))
    elements = vtk_to_numpy(events.GetPointData().GetArray("ElementId"))
    times = vtk_to_numpy(events.GetPointData().GetArray("Time"))
    points = vtk_to_numpy(events.GetPoints().GetData()) if events.GetPoints() else \
        np.zeros((0, 3))
    drawn = servermanager.Fetch(tracer).GetNumberOfCells()
    by_array = tracer.SurfaceInteractionArray == "Kind"
    gate = tracer.SurfaceInteraction == "Gate" and not by_array
    expected, axis = (PASSED, "X") if gate else (TERMINATED, "Y" if not by_array else "Z")
    found = {"played to t = 6": abs(time - 6.0) < 1e-9,
             "Surface Interaction Array None or Kind":
                 tracer.SurfaceInteractionArray in ("None", "Kind"),
             "one event per element": sorted(elements.tolist()) == list(range(COUNT)),
             "every event %s" % ("Passed" if gate else "Terminated"):
                 len(kinds) > 0 and bool(np.all(kinds == expected)),
             "every event on the Surfaces (SurfaceId 6)": len(ids) > 0 and bool(np.all(ids == 6)),
             "on the half-plane": len(points) > 0 and bool(np.all(np.abs(points[:, 1]) < 1e-5))
                 and bool(np.all(points[:, 0] > 0)),
             "about a three-quarter turn": len(times) > 0
                 and bool(np.all(np.abs(times - 1.5 * np.pi) < 0.3)),
             "elements drawn" if gate else "no element drawn": (drawn > 0) == gate}
    if gui_check.passed("check_surfaces", found,
                        {"time": time,  "interactions": sorted(set(kinds.tolist())),
                         "surface ids": sorted(set(ids.tolist())), "events": len(kinds),
                         "cells drawn": drawn,
                         "event times": (float(times.min()), float(times.max()))
                         if len(times) else None}):
        tracer.ColoringAxis = axis


gui_check.run("check_surfaces", check)
