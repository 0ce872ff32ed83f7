"""Strips lying along a wall and sliding along it, on real data: the GFS
10 m wind (gfs_wind10m.pvd of the shared data: 48 hours of global surface
wind on a 1-degree longitude-latitude grid, 360 x 180, flat) traced with
Boundary = Slip, so the grid's sides are walls. Here the side at 179 E, where
the globe's grid ends (the real wind blows on across it), stands in the
Southern Ocean's westerlies.

150 Strip8 elements of 4 degrees, released upright (their width along z, which
the flat field keeps) between 131 E and 179 E, 40 S and 64 S, are carried east
into that side; there they lie down flat along it and slide north with the
wind's component along it. After 48 hours the strips on the wall are orange,
those in the air blue; the lines on the grey map of the wind's speed are the
paths of the wall strips' centres over the last day, blue in the air and
orange along the wall (where the centre of a strip lying flat on it is).

    pvpython demo/walls.py --plugin BoundParticles.so --output docs [--data DIR]

DIR is the shared data folder: by default $BOUNDPARTICLES_DATA_DIR, or the
CMake cache variable BOUNDPARTICLES_DATA_DIR of build/ (or of
$BOUNDPARTICLES_BUILD_DIR), as the tests read it; it is read in place.
"""
import argparse
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import apply_preset, dark_view, save_and_close  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TIME = 48.0


def default_data():
    """$BOUNDPARTICLES_DATA_DIR, else the build's CMake cache variable of that
    name, else its default (../shared/data beside the repository)."""
    if os.environ.get("BOUNDPARTICLES_DATA_DIR"):
        return os.environ["BOUNDPARTICLES_DATA_DIR"]
    build = os.environ.get("BOUNDPARTICLES_BUILD_DIR", os.path.join(ROOT, "build"))
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as cache:
            for line in cache:
                if line.startswith("BOUNDPARTICLES_DATA_DIR:"):
                    return line.split("=", 1)[1].strip()
    except OSError:
        pass
    return os.path.join(os.path.dirname(ROOT), "shared", "data")


def wall_scene(data):
    """The wind of the shared data folder `data` and its tracer: 150 upright
    Strip8 elements released in the Southern Ocean west of 179 E, with
    Boundary = Slip (Testing/Python/test_walls_picture.py checks what the
    picture shows on it)."""
    wind = PVDReader(FileName=os.path.join(data, "gfs_wind10m.pvd"))
    wind.UpdatePipeline()
    tracer = BoundParticleTracer(Input=wind, Vectors=["POINTS", "velocity_deg_per_hour"],
                                 ElementShape="Strip8", NumberOfElements=150, ElementSize=4.0,
                                 ReleaseOrientation="Fixed", ElementRotation=[90.0, 0.0, 0.0],
                                 EmitterCenter=[155.0, -52.0, 0.0], EmitterSize=[48.0, 24.0, 0.0],
                                 Boundary="Slip", Integrator="Runge-Kutta 2",
                                 Duration=TIME, LifetimeRange=[1000.0, 1000.0], Seed=4)
    return wind, tracer


def ground_tracks(tracer, time, wall_x, span):
    """The path of the centre of each element that lies on the wall x =
    `wall_x` at `time`, over the `span` before it, as a polyline just above
    the map (z = -0.45); the tracer is left updated to `time`."""
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    frames = [t for t in tracer.TimestepValues if time - span - 1e-9 <= t <= time + 1e-9]
    centres = []
    for t in frames:
        tracer.UpdatePipeline(t)
        points = vtk_to_numpy(servermanager.Fetch(tracer).GetPoints().GetData())
        centres.append(points.reshape(tracer.NumberOfElements, -1, 3).mean(axis=1)[:, :2])
    lying = [e for e, (x, _) in enumerate(centres[-1]) if x > wall_x - 1e-4]
    paths = [[centres[f][e].tolist() for f in range(len(frames))] for e in lying]
    script = """
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
points, lines = vtkPoints(), vtkCellArray()
for path in %r:
    lines.InsertNextCell(len(path))
    for x, y in path:
        lines.InsertCellPoint(points.InsertNextPoint(x, y, -0.45))
output = self.GetPolyDataOutput()
output.SetPoints(points)
output.SetLines(lines)
""" % (paths,)
    return ProgrammableSource(OutputDataSetType="vtkPolyData", Script=script)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--data", default=default_data(),
                        help="the shared data folder (default: %(default)s)")
    parser.add_argument("--time", type=float, default=TIME)
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.data, "gfs_wind10m.pvd")):
        parser.error("no gfs_wind10m.pvd in %s: give the shared data folder with --data" % args.data)
    os.makedirs(args.output, exist_ok=True)
    return args


def main():
    args = arguments()
    LoadPlugin(args.plugin, ns=globals())
    wind, tracer = wall_scene(args.data)
    x0, x1, y0, y1, _, _ = wind.GetDataInformation().GetBounds()
    tracks = ground_tracks(tracer, args.time, x1, 24.0)
    # 1 where a particle lies on a side of the grid, 0 elsewhere.
    on_wall = Calculator(Input=tracer, ResultArrayName="OnWall",
                         Function="min(min(coordsX-%r,%r-coordsX),min(coordsY-%r,%r-coordsY)) < 1e-4"
                         % (x0, x1, y0, y1))
    view = dark_view(args.time)
    # The wind speed as a dim map under the upright strips.
    below = Transform(Input=wind)
    below.Transform.Translate = [0.0, 0.0, -0.5]
    speed = Show(below, view)
    ColorBy(speed, ("POINTS", "velocity", "Magnitude"))
    lut = GetColorTransferFunction("velocity")
    apply_preset(lut, "Grayscale")
    lut.RescaleTransferFunction(-10.0, 45.0)
    # The wall (the grid's side at 179 E), faintly, just behind the strips
    # pressed onto it (in their plane it would mottle them).
    wall = Plane(Origin=[x1 + 0.3, -70.0, -0.5], Point1=[x1 + 0.3, -34.0, -0.5],
                 Point2=[x1 + 0.3, -70.0, 1.5])
    wall_display = Show(wall, view)
    wall_display.AmbientColor = wall_display.DiffuseColor = [0.6, 0.65, 0.8]
    wall_display.Opacity = 0.2
    # Where the centre of each strip lying on the wall went over the last
    # day, drawn on the map: blue in the air, orange where it slid along
    # the wall.
    slid = Calculator(Input=tracks, ResultArrayName="OnWall",
                      Function="coordsX > %r" % (x1 - 1e-4))
    track_display = Show(slid, view)
    ColorBy(track_display, ("POINTS", "OnWall"))
    track_display.LineWidth = 2.0
    track_display.Opacity = 0.7
    # Strips in the air, shaded, blue (orange where one touches the wall)...
    air = Threshold(Input=on_wall, Scalars=["POINTS", "OnWall"], AllScalars=0)
    air.LowerThreshold, air.UpperThreshold = 0.0, 0.5
    display = Show(air, view)
    ColorBy(display, ("POINTS", "OnWall"))
    walls = GetColorTransferFunction("OnWall")
    walls.RGBPoints = [0.0, 0.55, 0.75, 1.0, 0.5, 0.55, 0.75, 1.0,
                       0.5001, 1.0, 0.55, 0.15, 1.0, 1.0, 0.55, 0.15]
    display.Specular = 0.3
    # ...and those lying on it, unshaded orange: many lie in the same plane
    # there, where shading would mottle them.
    lying = Threshold(Input=on_wall, Scalars=["POINTS", "OnWall"], AllScalars=1)
    lying.LowerThreshold, lying.UpperThreshold = 0.5, 1.0
    flat = Show(lying, view)
    ColorBy(flat, None)
    flat.AmbientColor = flat.DiffuseColor = [1.0, 0.55, 0.15]
    flat.Ambient, flat.Diffuse = 1.0, 0.0
    Render(view)
    view.CameraPosition = [156.0, -74.0, 14.0]
    view.CameraFocalPoint = [174.0, -52.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    save_and_close(view, os.path.join(args.output, "walls.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
