"""The Bound Particles display in a scene, as the Surface display draws it.

--case translucency: Opacity 0.5 with ParaView's depth peeling. Elements in
front of an opaque sphere and of each other, half of them waiting hidden for
a release window; then coloured by ElementId with the colour map's opacity
(opacity mapping) instead. The translucent images must differ from the
opaque ones, the GPU engine's must match the CPU engine's drawn as Surface,
and both must match their baselines.

--case links: super sets. A sheet of Point elements (a cloth: the links are
all there is to see) and a ring of crosses coloured by ElementId: the GPU
engine's Bound Particles image must show the links as the Surface display
shows the CPU output's link cells, and both must match their baselines; a
structure waiting for its release window shows no links.

Every image is written to --output; --update-baselines writes the baselines
in Testing/Data/Baseline instead of comparing with them (look at them before
committing them).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
import paraview.simple  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403

args = bptest.arguments("--case", "--baselines", "--output", "--update-baselines")
LoadPlugin(args.plugin, ns=globals())
VELOCITY = ["POINTS", "velocity"]
# The baselines were drawn with random orientations (Release Orientation's
# default was Random then); the display, not the orientation, is under test.
paraview.simple._DisableFirstRenderCameraReset()
os.makedirs(args.output, exist_ok=True)

# Against the baselines: the same Mesa must draw the same picture.
BASE_MEAN, BASE_PIXELS = 1.0, 0.005
# GPU against CPU, as in test_representation.py: with the solid colour the two
# are the same to a level, coloured by an array the table is sampled a little
# differently.
SOLID_MEAN, SOLID_PIXELS = 0.02, 0.0002  # pixels differing by more than 4 levels
COLOR_MEAN, COLOR_PIXELS = 0.5, 0.002  # pixels differing by more than 32 levels

flow = AnalyticFlow(Flow="Shear Layer", Resolution=[32, 32, 32])
flow.UpdatePipeline()


def render(scene, name, time, camera):
    """Shows `scene` ((source, representation, display settings) each) in a new
    view at `time`, saves and returns (the image's path, whether the last
    render used depth peeling)."""
    view = CreateRenderView(ViewSize=[320, 240])
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.15]
    view.CameraPosition, view.CameraFocalPoint = camera
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30
    view.DepthPeeling = 1
    view.MaximumNumberOfPeels = 4  # ParaView's default
    for source, representation, display in scene:
        shown = Show(source, view)
        shown.SetRepresentationType(representation)
        display = dict(display)
        color = display.pop("color", None)
        opacity_map = display.pop("opacity_map", None)
        if color:
            name_, scalar_range = color
            ColorBy(shown, ("POINTS", name_))
            lut = GetColorTransferFunction(name_)
            lut.ApplyPreset("Cool to Warm", True)
            lut.RescaleTransferFunction(*scalar_range)
            # The colour map's opacity, as "Enable Opacity Mapping For
            # Surfaces" in the colour map editor: (value, opacity) points.
            lut.EnableOpacityMapping = 1 if opacity_map else 0
            if opacity_map:
                points = GetOpacityTransferFunction(name_)
                points.Points = [v for x, a in opacity_map for v in (x, a, 0.5, 0.0)]
        else:
            ColorBy(shown, ("POINTS", None))
        for key, value in display.items():
            setattr(shown, key, value)
    view.ViewTime = time
    Render(view)
    peeled = view.GetRenderer().GetLastRenderingUsedDepthPeeling()
    path = os.path.join(args.output, name + ".png")
    SaveScreenshot(path, view)
    Delete(view)
    del view
    return path, peeled


def check_baseline(image, name):
    bptest.check_baseline(image, args.baselines, name, args.update_baselines, BASE_MEAN,
                          BASE_PIXELS)


def check_same(cpu_image, gpu_image, name, solid):
    """The GPU engine's Bound Particles image against the CPU engine's Surface one."""
    if solid:
        mean, pixels = bptest.image_difference(cpu_image, gpu_image, threshold=4)
        ok = mean <= SOLID_MEAN and pixels <= SOLID_PIXELS
    else:
        mean, pixels = bptest.image_difference(cpu_image, gpu_image)
        ok = mean <= COLOR_MEAN and pixels <= COLOR_PIXELS
    bptest.check(ok, "%s: GPU vs CPU differ: mean %.3f, pixels %.4f" % (name, mean, pixels))


ENGINES = [("CPU", "Surface"), ("GPU", "Bound Particles")]


def translucency():
    sphere = Sphere(Radius=0.35, ThetaResolution=48, PhiResolution=48)
    sphere_display = ("Surface", {"DiffuseColor": [0.3, 0.5, 0.9]})
    # Released in [0, 1] with lives of 0.2 to 2: at t = 1.5 about half of the
    # elements wait hidden for a window that has closed. Hidden elements must
    # take no part in the peels: the display once let them fill peels, so
    # that with ParaView's 4 peels the layers behind them were left to the
    # final blend (1% of the pixels off by more than 4 levels in this scene).
    camera = ([2.2, 1.6, 3.2], [0.0, 0.0, 0.0])
    # Coloured by ElementId, opaque, then with the colour map's opacity from
    # 0.2 to 0.8: translucent through the colour map alone. The display once
    # drew that in the opaque pass, blended in draw order.
    element_ids = ("ElementId", (0.0, 599.0))
    opacity_map = [(0.0, 0.2), (599.0, 0.8)]
    images = {}
    for engine, representation in ENGINES:
        tracer = BoundParticleTracer(ReleaseOrientation="Random", Input=flow, Vectors=VELOCITY, ElementShape="Paddlewheel",
                                     NumberOfElements=600, ElementSize=0.3, Seed=3,
                                     Engine=engine, Duration=10.0, ReleaseWindow=1,
                                     ReleaseStart=0.0, ReleaseStop=1.0,
                                     LifetimeRange=[0.2, 2.0])
        for opacity in (1.0, 0.5):
            name = "Translucent_%s_%g" % (representation.replace(" ", ""), opacity)
            scene = [(sphere, sphere_display[0], sphere_display[1]),
                     (tracer, representation, {"DiffuseColor": [0.9, 0.85, 0.7],
                                               "Specular": 0.3, "Opacity": opacity})]
            images[engine, opacity], peeled = render(scene, name, 1.5, camera)
            if opacity < 1.0:
                bptest.check(peeled, "%s: the view renders with depth peeling" % name)
        for mapped in (False, True):
            name = "Translucent_%s_%s" % (representation.replace(" ", ""),
                                          "map" if mapped else "colored")
            display = {"color": element_ids, "Specular": 0.3}
            if mapped:
                display["opacity_map"] = opacity_map
            scene = [(sphere, sphere_display[0], sphere_display[1]),
                     (tracer, representation, display)]
            images[engine, "map" if mapped else "colored"], peeled = render(
                scene, name, 1.5, camera)
            if mapped:
                bptest.check(peeled, "%s: the view renders with depth peeling" % name)
        Delete(tracer)
    for engine, representation in ENGINES:
        mean, _ = bptest.image_difference(images[engine, 1.0], images[engine, 0.5])
        bptest.check(mean > 2.0, "%s: Opacity 0.5 shows the sphere through the elements "
                     "(mean difference from opaque %.3f)" % (representation, mean))
        check_baseline(images[engine, 0.5], "Translucent_" + representation.replace(" ", ""))
        mean, _ = bptest.image_difference(images[engine, "colored"], images[engine, "map"])
        bptest.check(mean > 2.0, "%s: the colour map's opacity shows through the elements "
                     "(mean difference from opaque %.3f)" % (representation, mean))
        check_baseline(images[engine, "map"], "OpacityMap_" + representation.replace(" ", ""))
    check_same(images["CPU", 1.0], images["GPU", 1.0], "Opaque", solid=True)
    check_same(images["CPU", 0.5], images["GPU", 0.5], "Translucent", solid=True)
    check_same(images["CPU", "map"], images["GPU", "map"], "OpacityMap", solid=False)
    Delete(sphere)


def links():
    camera = ([0.9, 1.2, 3.4], [0.0, 0.0, 0.0])
    # A cloth: Point elements linked in a 16 x 10 sheet; and a ring of 24
    # crosses, whose links carry the colour of the particles they join.
    systems = [
        ("Sheet", dict(ElementShape="Point", NumberOfElements=160, Linking="Sheet",
                       LatticeWidth=16, ElementSize=0.1, EmitterSize=[1.2, 0.8, 0.0]),
         None),
        ("Ring", dict(ElementShape="Cross", NumberOfElements=24, Linking="Ring",
                      ElementSize=0.12, EmitterSize=[1.0, 1.0, 0.6]),
         ("ElementId", (0.0, 23.0))),
    ]
    for system, settings, color in systems:
        images = {}
        for engine, representation in ENGINES:
            tracer = BoundParticleTracer(ReleaseOrientation="Random", Input=flow, Vectors=VELOCITY, Seed=3, Engine=engine,
                                         Duration=10.0, LifetimeRange=[5.0, 10.0],
                                         EmitterCenter=[-0.5, 0.0, 0.0],
                                         RestorationIterations=8, **settings)
            display = {"Specular": 0.3}
            if color:
                display["color"] = color
            else:
                display["DiffuseColor"] = [0.9, 0.85, 0.7]
            name = "Links_%s_%s" % (system, representation.replace(" ", ""))
            images[engine], _ = render([(tracer, representation, display)], name, 0.6, camera)
            check_baseline(images[engine], name)
            if system == "Sheet":
                # The same cloth waiting for its release window: no element
                # and no link is drawn before it opens, all once it has.
                tracer.ReleaseWindow = 1
                tracer.ReleaseStart = tracer.ReleaseStop = 0.5
                for time in (0.3, 0.8):
                    window_name = "%s_window_%g" % (name, time)
                    images[engine, time], _ = render([(tracer, representation, display)],
                                                     window_name, time, camera)
            Delete(tracer)
        check_same(images["CPU"], images["GPU"], "Links_" + system, solid=color is None)
        cpu_covered = bptest.covered_fraction(images["CPU"])
        gpu_covered = bptest.covered_fraction(images["GPU"])
        bptest.check(gpu_covered >= 0.95 * cpu_covered,
                     "%s: the GPU image covers %.4f, the CPU's %.4f" %
                     (system, gpu_covered, cpu_covered))
        if system == "Sheet":
            # 160 points alone cover some 0.3% of the view: the rest is links.
            bptest.check(gpu_covered > 0.05,
                         "the sheet's links are drawn: %.4f of the view" % gpu_covered)
            for engine, _ in ENGINES:
                before = bptest.covered_fraction(images[engine, 0.3])
                bptest.check(before == 0.0, "%s: before its window the sheet is not drawn "
                             "(%.4f)" % (engine, before))
            check_same(images["CPU", 0.8], images["GPU", 0.8], "Links_Sheet_window",
                       solid=True)
            after = bptest.covered_fraction(images["GPU", 0.8])
            bptest.check(after > 0.05, "once released the links are drawn (%.4f)" % after)


{"translucency": translucency, "links": links}[args.case]()
bptest.finish()
