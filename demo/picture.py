"""The look the README's pictures share."""
from paraview.simple import CreateRenderView


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
