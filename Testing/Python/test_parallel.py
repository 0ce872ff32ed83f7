"""Parallel and client-server runs trace the same elements as the built-in one.

Runs Testing/Python/parallel_trace.py built in (the reference), then either
under pvbatch with 1, 2 and 4 MPI ranks (--mode batch) or as a client of a
two-rank pvserver on a free localhost port (--mode server), and compares the
traces sorted by (ElementId, ParticleIndex): the same elements, positions and
velocities within a float tolerance. Checks that the work was shared (every
rank holds elements, elements changed ranks, no element is split) and that
the Bound Particles display draws the same picture when the ranks' images are
composited, with remote rendering on and off. A state saved at 0.5 resumes bit
for bit on as many processes, and on another number (saved on 1 resumed on 2,
saved on 2 resumed on 1 and 4) with the same elements as a trace on that
number, within the same tolerance. Periodic along x and y, strips in a
uniform flow are back where they were after one period, whole, on every
number of processes, each process holding the elements of its block and
reading whole x-y planes over a part of z (the axis the processes split).
The Surfaces' cases (a gate and an outlet, a Slip wall, a mesh's hole) hold
events of the kinds they are there for, and their variants far from the
origin trace what they do near it, moved.
"""
import argparse
import json
import os
import signal
import socket
import subprocess
import sys
import time

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bptest  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--mode", choices=["batch", "server"], required=True)
parser.add_argument("--pvpython", required=True)
parser.add_argument("--pvbatch", required=True)
parser.add_argument("--pvserver", required=True)
parser.add_argument("--mpiexec", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--data", help="the shared real data sets' folder (read in place)")
args = parser.parse_args()

here = os.path.dirname(os.path.abspath(__file__))
script = os.path.join(here, "parallel_trace.py")
os.makedirs(args.output, exist_ok=True)
mpiexec = [args.mpiexec, "--allow-run-as-root", "--oversubscribe"]


environment = bptest.outside_mpi_job()
run_group = bptest.run_group


# The job's own limit: a trace job takes seconds. A job killed at the limit
# (a multi-rank render hang seen under load, never in tracing) runs again once.
JOB_LIMIT = 120


def run(command, name, hang_tries=2):
    """Runs a job; one killed at the job limit runs again once."""
    print("running", " ".join(command), flush=True)
    started = time.time()
    done = run_group(command, JOB_LIMIT)
    print(done.stdout[-3000:])
    print("%s took %.1f s" % (name, time.time() - started))
    if done.returncode != 0:  # the tail may hold only the other ranks' stack traces
        print("%s's errors:\n" % name + "\n".join(
            line for line in done.stdout.splitlines()
            if "ERR|" in line or "FATL|" in line or "Abort" in line))
    if done.stdout.endswith("(killed after %d s)" % JOB_LIMIT) and hang_tries > 1:
        print("%s ran past %d s; running it again" % (name, JOB_LIMIT))
        return run(command, name, hang_tries - 1)
    bptest.check(done.returncode == 0, "%s exited with %d" % (name, done.returncode))
    return done


def write_rectilinear(path):
    """An ABC-like field on a rectilinear grid at negative coordinates whose z
    layers thicken with height (as an atmosphere model's do)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkRectilinearGrid
    from vtkmodules.vtkIOXML import vtkXMLRectilinearGridWriter
    axes = [numpy.linspace(-4.0, -2.0, 20), numpy.linspace(-1.0, 0.5, 16),
            -3.0 + 1.5 * numpy.linspace(0.0, 1.0, 24) ** 1.5]
    grid = vtkRectilinearGrid()
    grid.SetDimensions(*[len(a) for a in axes])
    for a, setter in zip(axes, (grid.SetXCoordinates, grid.SetYCoordinates, grid.SetZCoordinates)):
        setter(numpy_to_vtk(a.copy(), deep=True))
    z, y, x = numpy.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    phase = [2 * numpy.pi * (c - a[0]) / (a[-1] - a[0]) for c, a in zip((x, y, z), axes)]
    velocity = 0.3 * numpy.stack([numpy.sin(phase[2]) + numpy.cos(phase[1]),
                                  numpy.sin(phase[0]) + numpy.cos(phase[2]),
                                  numpy.sin(phase[1]) + numpy.cos(phase[0])], axis=-1)
    array = numpy_to_vtk(velocity.reshape(-1, 3).copy(), deep=True)
    array.SetName("velocity")
    grid.GetPointData().SetVectors(array)
    writer = vtkXMLRectilinearGridWriter()
    writer.SetFileName(path + ".vtr")
    writer.SetInputData(grid)
    writer.Write()
    # The same field as a raw volume series with its z layers listed.
    velocity.astype("<f4").tofile(path + ".raw")
    spacing = [float(a[1] - a[0]) for a in axes[:2]] + [1.0]
    with open(path + ".bpvol", "w") as f:
        json.dump({"dimensions": [len(a) for a in axes], "origin": [axes[0][0], axes[1][0], 0.0],
                   "spacing": spacing, "z_coordinates": [float(z) for z in axes[2]],
                   "scalar_type": "float32", "byte_order": "little", "times": [0.0],
                   "files": [os.path.basename(path) + ".raw"]}, f)


stretched = os.path.join(args.output, "stretched")
write_rectilinear(stretched)
inputs = ["--rectilinear", stretched + ".vtr", "--bpvol", stretched + ".bpvol"] + (
    ["--data", args.data] if args.data else [])


def trace(name, launcher, extra=()):
    out = os.path.join(args.output, name + ".npz")
    if os.path.exists(out):
        os.remove(out)
    run(launcher + [script, "--plugin", args.plugin, "--output", out] + inputs + list(extra),
        name)
    return numpy.load(out) if os.path.exists(out) else None


def coverage(png):
    """The fraction of pixels that differ from the corner (background) colour."""
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    return float((abs(image - image[0]).sum(axis=1) > 30).mean())


# Traces whose elements the data, not the split, places: the combustor's flow
# fills 42% of its box, and seeds (a line, a cloud) need not cross every block.
# Release Weights crowd releases where the weights are large.
UNEVEN = ("combustor", "seeded", "seed_cloud", "seed_line", "seed_surface", "weighted")


def check_balance(result, base, element, process, ranks, name):
    """Elements spread over the field are shared fairly at the first time
    compared, and the output's ElementsPerProcess says how they are shared."""
    held = numpy.array([len(numpy.unique(element[process == r])) for r in range(ranks)])
    print("%s %s: elements per rank %s" % (name, base, held.tolist()))
    if ranks > 1 and base.endswith("_0") and not base.startswith(UNEVEN):
        share = held.max() / held.mean()
        bptest.check(share <= 1.5, "%s %s: a fair share per rank (max/mean %.2f, %s)" %
                     (name, base, share, held.tolist()))
    if ranks > 1:
        reported = result[base + "_per_process"] if base + "_per_process" in result.files else None
        bptest.check(reported is not None and reported.tolist() == held.tolist(),
                     "%s %s: ElementsPerProcess %s, held %s" %
                     (name, base, None if reported is None else reported.tolist(),
                      held.tolist()))


def check_close(name, base, reference, reference_base, result, result_base):
    """The same elements and particles (in order), and positions and
    velocities within the tolerance of pieces against a whole; whether the
    elements and particles are the same."""
    expected = {s: reference[reference_base + s] for s in ARRAYS}
    got = {s: result[result_base + s] for s in ARRAYS}
    same_ids = (expected["_element"].shape == got["_element"].shape and
                (expected["_element"] == got["_element"]).all() and
                (expected["_particle"] == got["_particle"]).all())
    bptest.check(same_ids, "%s %s: the same elements and particles (%d points, expected %d)" %
                 (name, base, len(got["_element"]), len(expected["_element"])))
    if not same_ids:
        return False
    points = expected["_points"]
    diagonal = numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))
    # Pieces locate cells from their own first point, so positions may
    # differ by float rounding; the velocity sampled there by that times
    # the field's gradient (steep in the combustor): its tolerance is a
    # share of the top speed.
    top_speed = float(numpy.linalg.norm(expected["_velocity"], axis=1).max())
    for array, scale, share in (("_points", diagonal, 2e-5), ("_velocity", top_speed, 1e-3)):
        error = float(abs(got[array] - expected[array]).max())
        print("%s %s%s: largest difference %.3g (scale %.3g)" %
              (name, base, array, error, scale))
        bptest.check(error <= share * scale, "%s %s%s differ by %g" % (name, base, array, error))
    return True


ARRAYS = ("_points", "_element", "_particle", "_velocity")


def compare(reference, result, name, ranks):
    if result is None:
        bptest.check(False, "%s wrote no trace" % name)
        return
    for key in reference.files:
        if key.endswith("_cells") and key in result.files:
            bptest.check((reference[key] == result[key]).all(), "%s %s: %d cells, built in %d" %
                         (name, key, result[key][0], reference[key][0]))
        if key.endswith("_times"):
            same = (reference[key].shape == result[key].shape and
                    numpy.allclose(reference[key], result[key], rtol=1e-12, atol=0))
            bptest.check(same, "%s %s: the same time line as the built-in run (%d values)" %
                         (name, key, len(result[key])))
        if key.endswith("_map"):
            # The FTLE map: whole on process 0 whatever the process count.
            same = (key in result.files and reference[key].shape == result[key].shape and
                    numpy.allclose(result[key], reference[key], rtol=0,
                                   atol=1e-3 * max(float(abs(reference[key]).max(initial=0)),
                                                   1e-9)))
            print("%s %s: %d map points" % (name, key, len(reference[key])))
            bptest.check(same, "%s %s: the FTLE map differs from the built-in run's" % (name, key))
        if key.endswith("_events"):
            check_events(name, key, reference[key], result[key] if key in result.files else None)
        if not key.endswith("_points"):
            continue
        base = key[: -len("_points")]
        if not check_close(name, base, reference, base, result, base):
            continue
        if base.startswith("inertial_plane"):
            # The flat field's plane (parallel_trace.PLANE_Z), whatever the process count.
            z = result[key][:, 2]
            bptest.check(len(z) > 0 and (z == 0.25).all(), "%s %s: points leave the plane z = "
                         "0.25 (z in [%g, %g])" % (name, base, z.min(initial=0), z.max(initial=0)))
        for array in ("_age", "_spin", "_ftle", "_stretch", "_slip"):
            if base + array in reference.files:
                scale = max(float(abs(reference[base + array]).max()), 1e-9)
                error = float(abs(result[base + array] - reference[base + array]).max())
                print("%s %s%s: largest difference %.3g (scale %.3g)" %
                      (name, base, array, error, scale))
                bptest.check(error <= 1e-3 * scale, "%s %s%s differ by %g" %
                             (name, base, array, error))
        process = result[base + "_process"]
        counts = numpy.bincount(process, minlength=ranks)
        print("%s %s: elements' particles per rank %s" % (name, base, counts.tolist()))
        bptest.check(len(counts) == ranks and ((counts > 0).all() or base.startswith(UNEVEN)),
                     "%s %s: every rank holds elements (%s)" % (name, base, counts.tolist()))
        element = result[base + "_element"]
        check_balance(result, base, element, process, ranks, name)
        split = [e for e in numpy.unique(element) if len(numpy.unique(process[element == e])) > 1]
        bptest.check(not split, "%s %s: elements split between ranks: %s" %
                     (name, base, split[:5]))
    if ranks > 1:
        for trace_name in ("crosses", "points"):
            first = result[trace_name + "_0_process"]
            last = result[trace_name + "_1_process"]
            moved = int((first != last).sum())
            print("%s %s: %d particles changed ranks between the two times" %
                  (name, trace_name, moved))
            bptest.check(moved > 0, "%s %s: no element changed ranks" % (name, trace_name))


# The Interactions output's kinds, by their values.
EVENT_KINDS = ("Released", "Terminated", "Stuck", "Slid", "Bounced", "Passed")


def check_events(name, key, expected, got):
    """The Interactions output (process 0's, every event): the same events in
    the same order, (Time, ElementId, ParticleIndex, Interaction, SurfaceId,
    Normal, SurfaceCell) exactly, points and velocities within the pieces'
    tolerance."""
    if got is None or expected.shape != got.shape:
        bptest.check(False, "%s %s: %s events, expected %d" %
                     (name, key, None if got is None else len(got), len(expected)))
        return
    print("%s %s: %d events (%s)" % (name, key, len(got), ", ".join(
        "%s %d" % (kind, int((got[:, 6] == k).sum())) for k, kind in enumerate(EVENT_KINDS)
        if (got[:, 6] == k).any())))
    bptest.check(numpy.array_equal(got[:, 3:11], expected[:, 3:11]) and
                 numpy.array_equal(got[:, 14:], expected[:, 14:]),
                 "%s %s: the events differ from the built-in run's" % (name, key))
    if len(expected):
        diagonal = numpy.linalg.norm(expected[:, :3].max(axis=0) - expected[:, :3].min(axis=0))
        speed = max(float(abs(expected[:, 11:14]).max()), 1e-9)
        bptest.check(float(abs(got[:, :3] - expected[:, :3]).max()) <= 2e-5 * max(diagonal, 1e-9),
                     "%s %s: the events' points differ" % (name, key))
        bptest.check(float(abs(got[:, 11:14] - expected[:, 11:14]).max()) <= 1e-3 * speed,
                     "%s %s: the events' velocities differ" % (name, key))


# What each Surfaces case's events must hold at every time compared, near the
# origin and far from it (parallel_trace.py's *_far cases): the outlet ends
# elements and the gate counts passages; the Slip wall slides them and the
# gate beside it counts; the mesh's hole slides them.
REQUIRED_EVENTS = {"gates": ("Terminated", "Passed"), "surface_walls": ("Slid", "Passed"),
                   "mask_slip": ("Slid",)}


def check_event_kinds(result, name):
    """Each case of REQUIRED_EVENTS, and its far variant, traced with events
    of every kind it names: a comparison of no events shows nothing."""
    for case, kinds in REQUIRED_EVENTS.items():
        for variant in (case, case + "_far"):
            keys = [k for k in (result.files if result is not None else ())
                    if k.startswith(variant + "_") and k.endswith("_events") and
                    k[len(variant) + 1:-len("_events")].isdigit()]
            bptest.check(len(keys) == 2, "%s %s: %d times with events, not 2" %
                         (name, variant, len(keys)))
            for key in sorted(keys):
                counts = {kind: int((result[key][:, 6] == k).sum())
                          for k, kind in enumerate(EVENT_KINDS)}
                for kind in kinds:
                    bptest.check(counts[kind] > 0, "%s %s: no %s events (%s)" %
                                 (name, key, kind, counts))


def check_far_moved(result, name):
    """Each far variant traces what its case near the origin does, moved by
    parallel_trace.py's FAR: the same elements and particles, positions and
    velocities within the pieces' tolerance; the same events (elements,
    particles, kinds, surfaces, normals and cells exactly, times within
    1e-8, points and velocities within the same tolerances). Walls, gates
    and outlets act far from the origin as they do near it."""
    if result is None or "far_offset" not in result.files:
        bptest.check(False, "%s: no far variants traced" % name)
        return
    offset = result["far_offset"]
    for case in REQUIRED_EVENTS:
        for k in (0, 1):
            near, far = "%s_%d" % (case, k), "%s_far_%d" % (case, k)
            label = "%s %s" % (name, far)
            if far + "_points" not in result.files or near + "_points" not in result.files:
                bptest.check(False, "%s: not traced" % label)
                continue
            same = all(numpy.array_equal(result[near + s], result[far + s])
                       for s in ("_element", "_particle"))
            bptest.check(same, "%s: not the elements and particles of %s" % (label, near))
            if not same:
                continue
            points = result[near + "_points"]
            diagonal = numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))
            speed = float(numpy.linalg.norm(result[near + "_velocity"], axis=1).max())
            moved = float(abs(result[far + "_points"] - offset - points).max())
            faster = float(abs(result[far + "_velocity"] - result[near + "_velocity"]).max())
            print("%s: positions within %.3g of %s's moved, velocities within %.3g" %
                  (label, moved, near, faster))
            bptest.check(moved <= 2e-5 * diagonal and faster <= 1e-3 * speed,
                         "%s: %s moved differs by %g (velocities %g)" %
                         (label, near, moved, faster))
            near_events, far_events = result[near + "_events"], result[far + "_events"]
            bptest.check(near_events.shape == far_events.shape and len(near_events) > 0,
                         "%s: %d events, %d near the origin" %
                         (label, len(far_events), len(near_events)))
            if near_events.shape != far_events.shape or not len(near_events):
                continue
            exact = (numpy.array_equal(far_events[:, 4:11], near_events[:, 4:11]) and
                     numpy.array_equal(far_events[:, 14:], near_events[:, 14:]))
            times = float(abs(far_events[:, 3] - near_events[:, 3]).max())
            at = float(abs(far_events[:, :3] - offset - near_events[:, :3]).max())
            going = float(abs(far_events[:, 11:14] - near_events[:, 11:14]).max())
            print("%s: %d events as near the origin; times within %.3g, points within %.3g, "
                  "velocities within %.3g" % (label, len(far_events), times, at, going))
            bptest.check(exact and times <= 1e-8 and at <= 2e-5 * diagonal and
                         going <= 1e-3 * speed,
                         "%s: the events differ from %s's (times by %g, points by %g, velocities "
                         "by %g)" % (label, near, times, at, going))


def check_step_back(result, name):
    """Back to 0.45 after 1.0 (resumed from a checkpoint) is the trace run
    straight to 0.45, bit for bit, on any number of processes."""
    if result is None or "back_1_points" not in result.files:
        bptest.check(False, "%s: no step back traced" % name)
        return
    same = all(numpy.array_equal(result["back_1" + s], result["back_fresh_0" + s])
               for s in ("_points", "_element", "_particle", "_velocity", "_events"))
    bptest.check(same, "%s: back to 0.45 after 1.0 differs from a trace straight to 0.45" % name)


def check_shared_start(result, name):
    """A tracer started on a source another tracer left with more ghost
    layers than it asks for traces what the same tracer did first on that
    source, bit for bit, on any number of processes."""
    if result is None or "shared_start_1_points" not in result.files:
        bptest.check(False, "%s: no shared_start traced" % name)
        return
    for k in (0, 1):
        same = all(numpy.array_equal(result["shared_start_%d%s" % (k, s)],
                                     result["unsteady_z_%d%s" % (k, s)])
                   for s in ("_points", "_element", "_particle", "_velocity"))
        bptest.check(same, "%s: shared_start at its time %d differs from unsteady_z, the same "
                     "tracer first on the source" % (name, k))


def check_save_resume(result, name):
    """A tracer that went on from a state saved at 0.5 (on as many processes)
    traces to 1.0 what one that never stopped does, bit for bit."""
    if result is None or "resumed_0_points" not in result.files:
        bptest.check(False, "%s: no resumed trace" % name)
        return
    same = all(numpy.array_equal(result["resumed_0" + s], result["resumed_straight_0" + s])
               for s in ("_points", "_element", "_particle", "_velocity"))
    bptest.check(same, "%s: resumed from the state saved at 0.5, at 1.0 it differs from the "
                 "trace that never stopped" % name)


def check_periodic(result, run_name, ranks):
    """Each of parallel_trace.py's periodic cases."""
    for case in ("periodic", "periodic_mesh"):
        check_periodic_case(result, run_name, case, ranks)
    check_periodic_extents(result, run_name, ranks)


def check_periodic_extents(result, run_name, ranks):
    """The periodic_blocks case's field as each rank asked for it
    (parallel_trace.py's periodic_extents): whole along x and y, the
    periodic axes; along z, the one left to split, a part of [-8, 8] on every
    rank of several (its block with its ghost layers), the parts together
    the whole axis. Before the blocks split z only, 2 ranks split x and each
    read the whole field."""
    name = "%s periodic_blocks" % run_name
    if result is None or "periodic_extents" not in result.files:
        bptest.check(False, "%s: no extents recorded" % name)
        return
    extents = result["periodic_extents"]
    for rank, extent in enumerate(extents):
        print("%s: rank %d read the field's extent %s" % (name, rank, extent.tolist()))
    bptest.check(len(extents) == ranks, "%s: %d ranks recorded an extent, not %d" %
                 (name, len(extents), ranks))
    if len(extents) != ranks:
        return
    whole_xy = (extents[:, 0:4] == [-10, 10, -5, 5]).all()
    bptest.check(whole_xy, "%s: a rank read part of a periodic axis: %s" %
                 (name, extents.tolist()))
    if ranks < 2:
        return
    part = ((extents[:, 4] > -8) | (extents[:, 5] < 8)).all()
    bptest.check(part, "%s: a rank read the whole z axis, which is not periodic, so holds the "
                 "whole field: %s" % (name, extents.tolist()))
    covered = extents[:, 4].min() == -8 and extents[:, 5].max() == 8
    bptest.check(covered, "%s: the ranks' z ranges leave part of [-8, 8]: %s" %
                 (name, extents.tolist()))


def check_periodic_case(result, run_name, case, ranks):
    """A periodic case of parallel_trace.py (x and y periodic, the uniform
    flow (1, 0.5, 0) on [-10, 10] x [-5, 5] x [-8, 8]): after one period
    every strip is back where it was, shape and all; halfway, each is whole
    and its centre inside the box; and each process holds the elements whose
    centres lie in its block, but for those a step took across a block's
    side or a seam since the last exchange (within a step, 0.056, of it)."""
    name = "%s %s" % (run_name, case)
    if result is None or case + "_2_points" not in result.files:
        bptest.check(False, "%s: not traced" % name)
        return
    start, back = result[case + "_0_points"], result[case + "_2_points"]
    same = (numpy.array_equal(result[case + "_0_element"], result[case + "_2_element"]) and
            start.shape == back.shape and len(start) > 0)
    bptest.check(same, "%s: the same elements after one period" % name)
    if not same:
        return
    moved = float(abs(back - start).max())
    print("%s: back within %.3g after one period" % (name, moved))
    bptest.check(moved < 1e-3, "%s: every strip back where it was after one period "
                 "(%.3g)" % (name, moved))
    middle = result[case + "_1_points"].reshape(-1, 4, 3)  # Strip4
    centres = middle.mean(axis=1)
    spread = float(abs(middle[:, :, :2] - centres[:, None, :2]).max())
    print("%s: halfway, centres in x %.3f to %.3f, y %.3f to %.3f, particles within "
          "%.3f of their centres" % (name, centres[:, 0].min(), centres[:, 0].max(),
                                     centres[:, 1].min(), centres[:, 1].max(), spread))
    bptest.check(spread < 1.0, "%s: a strip torn across a seam (%.3f)" % (name, spread))
    inside = (abs(centres[:, 0]) <= 10.0).all() and (abs(centres[:, 1]) <= 5.0).all()
    bptest.check(inside, "%s: centres outside the period" % name)
    if ranks < 2:
        return
    step = 0.06
    for k in range(3):
        points = result["%s_%d_points" % (case, k)].reshape(-1, 4, 3).mean(axis=1)
        process = result["%s_%d_process" % (case, k)][::4]
        near_seam = (abs(abs(points[:, 0]) - 10.0) < step) | (abs(abs(points[:, 1]) - 5.0) < step)
        boxes = [(points[(process == r) & ~near_seam].min(axis=0),
                  points[(process == r) & ~near_seam].max(axis=0))
                 for r in range(ranks) if ((process == r) & ~near_seam).any()]
        worst = float("-inf")
        for i, (low_a, high_a) in enumerate(boxes):
            for low_b, high_b in boxes[i + 1:]:
                overlap = numpy.minimum(high_a, high_b) - numpy.maximum(low_a, low_b)
                worst = max(worst, float(overlap.min()))
        print("%s_%d: the ranks' boxes of element centres overlap by %.3f at most" %
              (name, k, worst))
        bptest.check(worst <= 2 * step, "%s_%d: a rank holds elements in another's block (its "
                     "boxes overlap by %.3f)" % (name, k, worst))


def state_of(run_name):
    """The state parallel_trace.py saved at 0.5 in the run `run_name`."""
    return os.path.join(args.output, run_name + ".npz") + "-state.pvtp"


def check_resume_across(result, name, ranks, saved_by):
    """A tracer that went on from a state saved at 0.5 on another number of
    processes (`saved_by`: the runs that saved them) traces to 1.0 the
    elements one that never stopped traces on this number: the same ids and
    count, positions within the tolerance of pieces against a whole; every
    process holds some; and it stepped from 0.5 only."""
    for saver in saved_by:
        base = "resumed_from_%s_0" % saver
        label = "%s, from the state %s saved" % (name, saver)
        if result is None or base + "_points" not in result.files:
            bptest.check(False, "%s: no trace" % label)
            continue
        check_close(label, base, result, "resumed_straight_0", result, base)
        held = numpy.bincount(result[base + "_process"], minlength=ranks)
        print("%s: elements' particles per rank %s" % (label, held.tolist()))
        bptest.check(len(held) == ranks and (held > 0).all(),
                     "%s: every rank holds elements (%s)" % (label, held.tolist()))
        steps = int(result[base + "_steps"][0])
        straight = int(result["resumed_straight_0_steps"][0])
        print("%s: %d steps to 1.0, %d from the start" % (label, steps, straight))
        bptest.check(0 < steps < straight, "%s: %d steps to 1.0 (from the start %d): not resumed" %
                     (label, steps, straight))


def compare_pictures(reference_dir, result_dir, name):
    expected = coverage(os.path.join(reference_dir, "remote.png"))
    bptest.check(expected > 0.01, "the built-in picture shows elements (%.3f)" % expected)
    for label in ("remote", "local"):
        png = os.path.join(result_dir, label + ".png")
        if not os.path.exists(png):
            bptest.check(False, "%s wrote no %s picture" % (name, label))
            continue
        got = coverage(png)
        print("%s %s rendering covers %.4f of the picture, built in %.4f" %
              (name, label, got, expected))
        bptest.check(abs(got - expected) <= 0.15 * expected,
                     "%s %s rendering covers %.4f, built in %.4f" % (name, label, got, expected))


reference_pictures = os.path.join(args.output, "builtin-pictures")
reference = trace("builtin", [args.pvpython], ["--render", reference_pictures])
check_step_back(reference, "builtin")
check_event_kinds(reference, "builtin")
check_far_moved(reference, "builtin")
check_shared_start(reference, "builtin")
check_save_resume(reference, "builtin")
check_periodic(reference, "builtin", 1)

if args.mode == "batch":
    # Each run resumes from states the runs before it saved on other numbers
    # of processes: 1 to 2, 2 to 1, 2 to 4.
    resume_from = {2: ["builtin"], 1: ["pvbatch-2"], 4: ["pvbatch-2"]}
    for ranks in (2, 1, 4):
        name = "pvbatch-%d" % ranks
        pictures = os.path.join(args.output, name + "-pictures")
        states = ["--resume-from=%s=%s" % (saver, state_of(saver)) for saver in resume_from[ranks]]
        result = trace(name, mpiexec + ["-n", str(ranks), args.pvbatch],
                       (["--render", pictures] if ranks == 2 else []) + states)
        compare(reference, result, name, ranks)
        check_step_back(result, name)
        check_event_kinds(result, name)
        check_far_moved(result, name)
        check_shared_start(result, name)
        check_save_resume(result, name)
        check_resume_across(result, name, ranks, resume_from[ranks])
        check_periodic(result, name, ranks)
        if ranks == 2:
            compare_pictures(reference_pictures, pictures, name)
else:
    def client_server():
        """A two-rank pvserver and a pvpython client traced and rendered."""
        with socket.socket() as sock:
            sock.bind(("127.0.0.1", 0))
            port = sock.getsockname()[1]
        log_path = os.path.join(args.output, "pvserver.log")
        with open(log_path, "w") as log:
            server = subprocess.Popen(
                mpiexec + ["-n", "2", args.pvserver, "--server-port=%d" % port],
                stdout=log, stderr=subprocess.STDOUT, env=environment, start_new_session=True)
        try:
            deadline = time.time() + 120
            while time.time() < deadline and server.poll() is None:
                with open(log_path) as log:
                    if "Accepting connection" in log.read():
                        break
                time.sleep(0.2)
            pictures = os.path.join(args.output, "client-pictures")
            out = os.path.join(args.output, "client-server.npz")
            if os.path.exists(out):
                os.remove(out)
            client = run_group(
                [args.pvpython, script, "--plugin", args.plugin, "--output", out,
                 "--connect", "localhost:%d" % port, "--render", pictures,
                 "--resume-from=builtin=" + state_of("builtin")] + inputs, 300)
            print(client.stdout[-3000:])
            try:
                server.wait(timeout=60)  # the server ends when its client disconnects
            except subprocess.TimeoutExpired:
                pass
        finally:
            if server.poll() is None:
                os.killpg(server.pid, signal.SIGKILL)
                server.wait()
        with open(log_path) as log:
            server_log = log.read()
        print(server_log[-2000:])
        if client.returncode != 0:
            print("the server's messages:\n" + "\n".join(
                line for line in server_log.splitlines()
                if "ERR|" in line or "WARN|" in line or "Abort" in line))
        bptest.check(client.returncode == 0, "the client exited with %d" % client.returncode)
        served = numpy.load(out) if os.path.exists(out) else None
        compare(reference, served, "client-server", 2)
        check_event_kinds(served, "client-server")
        check_far_moved(served, "client-server")
        check_shared_start(served, "client-server")
        check_save_resume(served, "client-server")
        check_resume_across(served, "client-server", 2, ["builtin"])
        check_periodic(served, "client-server", 2)
        compare_pictures(reference_pictures, pictures, "client-server")

    client_server()

bptest.finish()
