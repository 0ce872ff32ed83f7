"""The look the README's pictures share, and their command line."""
import argparse
import os

from paraview.simple import CreateRenderView


def picture_arguments(description):
    """--plugin and --output of a picture script; the output folder exists."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--output", required=True)
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    return args


def dark_view(time, size=(1280, 720)):
    """A render view on a dark background at the given time, without axes."""
    view = CreateRenderView()
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = [0.08, 0.09, 0.12]
    try:
        view.UseColorPaletteForBackground = 0  # ParaView 5.10+: the palette would win
    except AttributeError:
        pass
    view.ViewTime = time
    return view


def look_down(view, x, y, scale):
    """A parallel projection looking down -z at (x, y), `scale` high from
    the centre to the top: the flat flows' pictures."""
    view.CameraPosition = [x, y, 6.0]
    view.CameraFocalPoint = [x, y, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = scale


def apply_preset(lut, name):
    """Applies a colour-map preset by its ParaView 5 name: ParaView 6 names the
    matplotlib maps without the " (matplotlib)" suffix ("Viridis")."""
    from paraview import servermanager
    presets = servermanager.vtkSMTransferFunctionPresets.GetInstance()
    for candidate in (name, name.replace(" (matplotlib)", "")):
        if presets.HasPreset(candidate):
            lut.ApplyPreset(candidate, True)
            return
    raise ValueError("no colour-map preset named %r" % name)


def save_tracers_picture(flow, layers, time, camera_position, path, line_width=1.0):
    """The field's outline and each (tracer, array, preset) of `layers`
    coloured by its array, seen from `camera_position` towards the origin,
    saved to `path` at 1280 x 720."""
    from paraview.simple import ColorBy, GetColorTransferFunction, Render, Show
    view = dark_view(time)
    Show(flow, view).SetRepresentationType("Outline")
    for tracer, array, preset in layers:
        tracer.UpdatePipeline(time)
        display = Show(tracer, view)
        ColorBy(display, ("POINTS", array))
        apply_preset(GetColorTransferFunction(array), preset)
        display.Specular = 0.3
        display.LineWidth = line_width
    Render(view)
    view.CameraPosition = list(camera_position)
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    save_and_close(view, path)


def save_and_close(view, path):
    """Saves `view` to `path` at 1280 x 720 and deletes it (views must go
    before the interpreter exits, or pvpython crashes there)."""
    from paraview.simple import Delete, SaveScreenshot
    SaveScreenshot(path, view, ImageResolution=[1280, 720])
    print("wrote %s" % path)
    Delete(view)
