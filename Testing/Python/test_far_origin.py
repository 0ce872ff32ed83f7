"""The Bound Particles display far from the world origin.

The same Analytic Flow is laid over [-1, 1]^3 moved by 0 (the reference),
1e6, 6.4e6 (an Earth radius: Earth-centred coordinates) and 1e8 along all
three axes. The tracer works relative to the field's first grid point, so
the trace is the same at every offset; only the picture could differ. At
each offset the CPU output is drawn as Surface, and the Bound Particles
display draws the same trace on both engines (Engine = CPU: the CPU output;
Engine = GPU: the engine's textures), all with the same camera relative to
the field. Each display's picture must match the Surface picture at its
offset and the same display's picture at offset 0.

Float32 world positions would lose the field: at 6.4e6 a float is 0.5 apart
(the elements become flat blocks), at 1e8 it is 8 apart (nothing is left).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments("--output")
LoadPlugin(args.plugin, ns=globals())
VELOCITY = ["POINTS", "velocity"]
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)

OFFSETS = [0.0, 1.0e6, 6.4e6, 1.0e8]
# The bars of test_representation.py: a display against Surface of the same
# trace, and a picture against the same picture elsewhere (rounding only).
MEAN_BAR, PIXEL_BAR = 0.5, 0.002
SURFACE = ("CPU", "Surface")
CPU_DISPLAY = ("CPU", "Bound Particles")
GPU_DISPLAY = ("GPU", "Bound Particles")


class Case:
    """A picture taken at every offset: the tracer's settings, the colouring
    (its range relative to the field), the displays drawn, and whether each
    display must match Surface (else only itself at offset 0)."""

    def __init__(self, name, displays, color=None, scalar_range=None, against_surface=True,
                 **settings):
        self.name, self.displays, self.color, self.scalar_range = (name, displays, color,
                                                                   scalar_range)
        self.against_surface, self.settings = against_surface, settings


CASES = [
    Case("Solid", [SURFACE, CPU_DISPLAY, GPU_DISPLAY]),
    # Speed: the GPU samples the field at the particles (grid-local).
    Case("Speed", [SURFACE, CPU_DISPLAY, GPU_DISPLAY], "Speed", (0.0, 1.3)),
    # Layer is a world coordinate: its range moves with the field. The CPU
    # output stores it as float, which cannot tell 1e8 - 1 from 1e8 + 1, so
    # only the GPU display (which colours grid-local) is checked, against
    # itself at offset 0.
    Case("Layer", [GPU_DISPLAY], "Layer", (-1.0, 1.0), against_surface=False),
    # Trails: the GPU draws past poses from its trail ring (and fades them
    # itself, so it is checked against itself at offset 0, not Surface).
    Case("Trails", [CPU_DISPLAY, GPU_DISPLAY], against_surface=False, Trails=1,
         TrailLength=4),
]


def render(source, representation, color, scalar_range, offset, name, time=1.0):
    view = bptest.element_view((320, 240))
    # The display tests' camera, moved with the field.
    view.CameraPosition = [c + offset for c in view.CameraPosition]
    view.CameraFocalPoint = [c + offset for c in view.CameraFocalPoint]
    shown = Show(source, view)
    shown.SetRepresentationType(representation)
    bptest.colour_display(shown, color, scalar_range)
    view.ViewTime = time
    Render(view)
    return bptest.save_picture(view, args.output, name)


def label(offset):
    return "0" if offset == 0.0 else ("%.1e" % offset).replace("+0", "").replace("+", "")


def compare(a, b, what):
    mean, pixels = bptest.image_difference(a, b)
    print("%s: mean %.3f, pixels %.4f" % (what, mean, pixels))
    bptest.check(mean <= MEAN_BAR and pixels <= PIXEL_BAR,
                 "%s differ: mean %.3f, pixels %.4f" % (what, mean, pixels))


reference = {}
for offset in OFFSETS:
    flow = AnalyticFlow(Flow="Shear Layer", Resolution=[32, 32, 32],
                        Bounds=[-1.0 + offset, 1.0 + offset] * 3)
    flow.UpdatePipeline()
    for case in CASES:
        tracers = {
            engine: BoundParticleTracer(Input=flow, Vectors=VELOCITY, ElementShape="Cross",
                                        NumberOfElements=40, ElementSize=0.3, Seed=3,
                                        Engine=engine, Duration=10.0,
                                        LifetimeRange=[5.0, 10.0],
                                        EmitterCenter=[offset] * 3, EmitterSize=[2.0] * 3,
                                        **case.settings)
            for engine in set(engine for engine, _ in case.displays)
        }
        scalar_range = case.scalar_range
        if case.color == "Layer":
            scalar_range = [v + offset for v in scalar_range]
        pictures = {}
        for engine, representation in case.displays:
            kind = "%s_%s_%s" % (engine, representation.replace(" ", ""), case.name)
            name = "%s_at_%s" % (kind, label(offset))
            path = render(tracers[engine], representation, case.color, scalar_range, offset,
                          name)
            pictures[(engine, representation)] = path
            covered = bptest.covered_fraction(path)
            bptest.check(covered > 0.005, "%s: elements are drawn (%.4f)" % (name, covered))
            if offset == 0.0:
                reference[kind] = path
            else:
                compare(reference[kind], path, "%s and the same at offset 0" % name)
        if case.against_surface:
            for display in case.displays:
                if display != SURFACE:
                    compare(pictures[SURFACE], pictures[display],
                            "%s and Surface at its offset" %
                            os.path.basename(pictures[display])[:-4])
        for proxy in tracers.values():
            Delete(proxy)
    Delete(flow)

bptest.finish()
