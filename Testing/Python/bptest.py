"""Helpers shared by the pvpython tests."""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from vtkmodules.util import vtkConstants
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import vtkOutputWindow

failures = []
# Folders of scratch(): removed by finish() when every check passed.
scratch_folders = []


def outside_mpi_job():
    """This process's environment without its MPI job's variables: pvpython
    initialises MPI as a singleton, and they would make a child mpiexec (or a
    simulation's MPI_Init) believe it runs inside that job. Its ranks yield
    the core while they wait in MPI instead of spinning: the tests' jobs have
    more ranks than this machine has free cores (a two-rank trace job took 17
    s spinning, 11.5 s yielding, on 2 busy cores)."""
    environment = {k: v for k, v in os.environ.items()
                   if not k.startswith(("OMPI_", "PMIX_", "ORTE_", "OPAL_"))}
    environment["OMPI_MCA_mpi_yield_when_idle"] = "1"
    return environment


def run_group(command, timeout, stderr_apart=False, **popen):
    """Runs `command` outside this process's MPI job (unless `env` is given),
    in a process group of its own, killed whole if it runs past `timeout` s
    (killing mpiexec alone could leave its ranks running). A CompletedProcess:
    stdout with stderr in it unless `stderr_apart`, ending "(killed after N
    s)" when killed; and `seconds`, how long it ran."""
    started = time.time()
    popen.setdefault("env", outside_mpi_job())
    process = subprocess.Popen(command, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE if stderr_apart else subprocess.STDOUT,
                               text=True, start_new_session=True, **popen)
    try:
        out, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        out += "\n(killed after %d s)" % timeout
    done = subprocess.CompletedProcess(command, process.returncode, out, err or "")
    done.seconds = time.time() - started
    return done


def resident_mib():
    """This process's resident memory, MiB."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def check(condition, message):
    """Records a failed expectation and goes on, like EXPECT_* in GoogleTest."""
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


def scratch(prefix):
    """A new folder for a test's files, removed by finish() when every check
    passed and kept (to look at) when one failed."""
    folder = tempfile.mkdtemp(prefix=prefix)
    scratch_folders.append(folder)
    return folder


def finish():
    if failures:
        print("%d check(s) failed; files kept in %s" % (len(failures), " ".join(scratch_folders)))
        sys.exit(1)
    for folder in scratch_folders:
        shutil.rmtree(folder, ignore_errors=True)
    print("all checks passed")
    sys.exit(0)


def arguments(*extra):
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin")
    for name in extra:
        parser.add_argument(name)
    return parser.parse_args()


class CapturedMessages:
    """Collects the VTK errors and warnings shown in ParaView's Output Messages
    (and, with `texts`, its plain messages: notes that do not pop it open)."""

    def __init__(self, texts=False):
        self.events = ["ErrorEvent", "WarningEvent"] + (["TextEvent"] if texts else [])

    def __enter__(self):
        self.messages = []

        @calldata_type(vtkConstants.VTK_STRING)
        def keep(obj, event, text):
            self.messages.append(text)

        self._keep = keep
        window = vtkOutputWindow.GetInstance()
        self._tags = [window.AddObserver(event, keep) for event in self.events]
        return self

    def __exit__(self, *exc):
        window = vtkOutputWindow.GetInstance()
        for tag in self._tags:
            window.RemoveObserver(tag)
        return False

    def mentions(self, part):
        return any(part in m for m in self.messages)


def image_difference(path_a, path_b, threshold=32):
    """(mean absolute difference per channel, fraction of pixels that differ by
    more than `threshold` in some channel) of two images of one size, or None
    when the sizes differ."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy

    def pixels(path):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        image = reader.GetOutput()
        dims = image.GetDimensions()
        values = vtk_to_numpy(image.GetPointData().GetScalars())
        return dims, values[:, :3].astype(numpy.int32)

    dims_a, a = pixels(path_a)
    dims_b, b = pixels(path_b)
    if dims_a != dims_b:
        return None
    d = numpy.abs(a - b)
    return float(d.mean()), float((d.max(axis=1) > threshold).mean())


def covered_fraction(path):
    """Fraction of pixels that are not the background (the corner pixel)."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy

    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    values = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    return float((numpy.abs(values - values[0]).max(axis=1) > 8).mean())


def check_baseline(image, baselines, name, update, mean_bar=1.0, pixel_bar=0.005):
    """Compares `image` with the baseline `name`.png in `baselines` (the same
    Mesa must draw the same picture), or writes it there when `update`."""
    import os
    import shutil

    baseline = os.path.join(baselines, name + ".png")
    if update:
        shutil.copyfile(image, baseline)
        return
    if not os.path.exists(baseline):
        check(False, "no baseline %s (the image is %s)" % (baseline, image))
        return
    mean, pixels = image_difference(baseline, image)
    check(mean <= mean_bar and pixels <= pixel_bar,
          "%s: differs from its baseline: mean %.3f, pixels %.4f" % (name, mean, pixels))


def colour_display(shown, color, scalar_range):
    """The tests' look of a display: `color` (an array's name, or its name and
    a component: ("Velocity", "X")) mapped with Cool to Warm over
    `scalar_range`, or with no `color` a solid sand colour; a little specular."""
    from paraview.simple import ColorBy, GetColorTransferFunction
    if color:
        name = color if isinstance(color, str) else color[0]
        ColorBy(shown, ("POINTS",) + ((color,) if isinstance(color, str) else tuple(color)))
        lut = GetColorTransferFunction(name)
        lut.ApplyPreset("Cool to Warm", True)
        lut.RescaleTransferFunction(*scalar_range)
    else:
        ColorBy(shown, ("POINTS", None))
        shown.DiffuseColor = [0.9, 0.85, 0.7]
    shown.Specular = 0.3


def save_picture(view, folder, name):
    """Saves `view` as folder/name.png and deletes it; returns the path."""
    import os
    from paraview.simple import Delete, SaveScreenshot
    path = os.path.join(folder, name + ".png")
    SaveScreenshot(path, view)
    Delete(view)
    return path


def element_view(size):
    """The display image tests' view: no axes, a dark background, the camera
    on the [-1, 1] box from above one corner."""
    from paraview.simple import CreateRenderView

    view = CreateRenderView(ViewSize=list(size))
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.15]
    view.CameraPosition = [2.2, 1.6, 3.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30
    return view


def fetch(proxy, time):
    """`proxy`'s output at `time`, brought to this process."""
    from paraview import servermanager

    proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def point_array(data, name):
    """Point array `name` of `data` as numpy, or None where it is missing."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    a = data.GetPointData().GetArray(name)
    return None if a is None else vtk_to_numpy(a)
