"""Play with the defaults in the ParaView GUI, beside pvpython doing the same.

For each data set: open it and Apply, add a Bound Particle Tracer from the
Filters menu and Apply (its defaults; Vectors must be ['POINTS', 'velocity']),
then press the VCR toolbar's Play, so that the frames go through the GUI's
animation machinery (pqVCRController, which processes the Qt events of every
tick: panels, toolbars, the time widgets). Each play runs --frames frames from
the start (the scene's playback window), --repeats times with the Surface
display and as many with the Bound Particles display. pvpython then does the
same in a render view of the GUI's view size (the input hidden only where the
GUI's Apply hides it: the tracer's replace_input="2" hides an opaque surface,
the plugin a 2D image's slice, and an outline stays) and plays with
GetAnimationScene().Play(). Prints one row per data set and display:
frames per second (median of the plays, wall clock from the scene's start of
play to its end), CPU ms per frame of the whole process (its llvmpipe render
threads included) and of its main thread alone (the pipeline, the panels and
the GUI's event loop), GUI and pvpython side by side.

    bash bench/gui_play.sh [--frames 50] [--repeats 3] [--data DIR] [--only a.vti,b.pvd]
                           [--setup FILE.py] [--gui-only] [--out DIR]

Wall-clock fps depends on what else runs on the machine (two cores here); the
CPU columns depend on it much less, the main thread's least.

This file has four roles, chosen by how it is run:
- python3 gui_play.py xml ...: writes the GUI's event file (QtTesting XML);
- run by the GUI's Python shell (Run Script, from that event file): each run
  prepares the tracer just applied, or records the plays just made;
- pvpython gui_play.py pvpython ...: the same plays in pvpython;
- python3 gui_play.py table ...: prints the table of both.
"""
import json
import os
import statistics
import sys
import time

DATA_SETS = ["combustor.vti", "office.vti", "carotid.vti", "nek_eddy.pvd", "gfs_wind10m.pvd"]
DISPLAYS = ["Surface", "Bound Particles"]
VECTORS = ["POINTS", "velocity"]


# ---------------------------------------------------------------- timing (GUI and pvpython)
class PlayTimer:
    """Times every Play of the animation scene: its start and end events and
    every tick, wall clock and the process's CPU time."""

    def __init__(self, scene):
        self.runs, self.current = [], None
        self.scene = scene.GetClientSideObject()  # vtkSMAnimationScene (builtin session)
        self.tags = [self.scene.AddObserver("StartEvent", self.start),
                     self.scene.AddObserver("AnimationCueTickEvent", self.tick),
                     self.scene.AddObserver("EndEvent", self.end)]

    def start(self, *unused):
        self.current = dict(wall=time.perf_counter(), cpu=time.process_time(),
                            main=time.thread_time(), ticks=[])

    def tick(self, *unused):
        if self.current is not None:
            self.current["ticks"].append(time.perf_counter())

    def end(self, *unused):
        run, self.current = self.current, None
        if run is None or not run["ticks"]:
            return
        frames = len(run["ticks"])
        wall = time.perf_counter() - run["wall"]
        cpu = time.process_time() - run["cpu"]
        main = time.thread_time() - run["main"]  # the observers run in the main thread
        gaps = [b - a for a, b in zip(run["ticks"], run["ticks"][1:])]
        self.runs.append(dict(frames=frames, seconds=wall, fps=frames / wall,
                              cpu_ms=1e3 * cpu / frames, main_ms=1e3 * main / frames,
                              median_frame_ms=1e3 * statistics.median(gaps) if gaps else 0.0))

    def take(self):
        runs, self.runs = self.runs, []
        return runs

    def remove(self):
        for tag in self.tags:
            self.scene.RemoveObserver(tag)


def run_setup(path, simple, tracer, reader, view, scene, gui):
    """--setup: a Python file run before the plays of each data set, in the GUI
    (gui=True) and in pvpython (gui=False), to measure what a setting or a
    change of state costs (e.g. simple.SetActiveSource(None) in the GUI)."""
    if path:
        with open(path) as f:
            exec(compile(f.read(), path, "exec"),
                 dict(simple=simple, tracer=tracer, reader=reader, view=view, scene=scene,
                      gui=gui))


def representation_of(display):
    return display.SMProxy.GetProperty("Representation").GetElement(0)


def set_frames(scene, tracer, frames):
    """Plays `frames` time values from the start: the scene's playback window
    (vtkSMAnimationScene; not a proxy property in ParaView 5.11)."""
    times = list(tracer.TimestepValues)
    count = max(1, min(frames, len(times)))
    scene.GetClientSideObject().SetPlaybackTimeWindow(times[0], times[count - 1])
    return count, len(times)


# ---------------------------------------------------------------- in the GUI's Python shell
def gui_step():
    """One Run Script of the event file: prepare the tracer just applied, or
    record the plays since the last step (then switch the display, or finish
    the data set and delete its pipeline)."""
    import builtins
    from paraview import simple

    config = json.loads(os.environ["BOUNDPARTICLES_GUI_PLAY"])
    state = builtins.__dict__.setdefault("_boundparticles_gui_play", {"rows": [], "current": None})
    scene = simple.GetAnimationScene()
    view = simple.GetActiveViewOrCreate("RenderView")
    current = state["current"]
    if current is None:
        tracer = simple.GetActiveSource()
        if tracer is None or tracer.GetXMLName() != "BoundParticleTracer":
            raise RuntimeError("gui_play: the active source is not a Bound Particle Tracer")
        reader = tracer.Input
        vectors = list(tracer.Vectors)
        if vectors[-2:] != VECTORS:
            tracer.Vectors = VECTORS
        frames, offered = set_frames(scene, tracer, config["frames"])
        display = simple.GetDisplayProperties(tracer, view)
        display.SetRepresentationType(DISPLAYS[0])
        shown = simple.GetDisplayProperties(reader, view)
        simple.Render(view)
        run_setup(config.get("setup"), simple, tracer, reader, view, scene, gui=True)
        state["timer"] = PlayTimer(scene)
        state["tracer"] = tracer
        state["current"] = dict(data=config["data_sets"][len(state["rows"]) // len(DISPLAYS)],
                                display=DISPLAYS[0], frames=frames, offered=offered,
                                vectors=vectors[-2:], view_size=list(view.ViewSize),
                                input_shown=shown.Visibility,
                                input_representation=representation_of(shown),
                                engine=str(tracer.Engine).strip("'"))
        return
    runs = state["timer"].take()
    state["rows"].append(dict(current, runs=runs))
    tracer = state["tracer"]
    display = simple.GetDisplayProperties(tracer, view)
    following = DISPLAYS.index(current["display"]) + 1
    if following < len(DISPLAYS):
        display.SetRepresentationType(DISPLAYS[following])
        simple.Render(view)
        state["current"] = dict(current, display=DISPLAYS[following])
    else:
        state["timer"].remove()
        state["current"] = state["tracer"] = None
        reader = tracer.Input
        simple.Delete(tracer)
        simple.Delete(reader)
        simple.SetActiveSource(None)
    with open(config["output"], "w") as out:
        json.dump(state["rows"], out, indent=1)


# ---------------------------------------------------------------- the GUI's event file
def write_events(path, data_dir, script, data_sets, repeats):
    from xml.sax.saxutils import quoteattr

    def event(name, command, arguments=""):
        return '<pqevent object="pqClientMainWindow/%s" command="%s" arguments=%s />' % (
            name, command, quoteattr(arguments))

    apply = event("propertiesDock/propertiesPanel/Accept", "activate")
    run_script = [event("pythonShellDock/pythonShell/runScriptButton", "activate"),
                  event("pythonShellDock/pythonShell/PythonShellRunScriptDialog",
                        "filesSelected", script)]
    play = event("VCRToolbar/actionVCRPlay", "activate")
    lines = ["<?xml version=\"1.0\" ?>", "<pqevents>"]
    for name in data_sets:
        lines += [event("menubar/menu_File", "activate", "actionFileOpen"),
                  event("FileOpenDialog", "filesSelected", os.path.join(data_dir, name)),
                  apply,
                  event("menubar", "activate", "menuFilters"),
                  event("menubar/menuFilters/Alphabetical", "activate", "BoundParticleTracer"),
                  apply] + run_script  # prepare: Surface display
        for _ in DISPLAYS:
            lines += [play] * repeats + run_script  # record, then the next display or finish
    lines.append("</pqevents>")
    with open(path, "w") as out:
        out.write("\n  ".join(lines) + "\n")


# ---------------------------------------------------------------- pvpython
def pvpython_plays(args):
    from paraview import simple

    simple.LoadPlugin(args.plugin, ns=globals())  # defines BoundParticleTracer here
    rows = []
    for name in args.data_sets:
        view = simple.GetActiveViewOrCreate("RenderView")
        view.ViewSize = args.view_size
        reader = simple.OpenDataFile(os.path.join(args.data, name))
        shown = simple.Show(reader, view)
        simple.Render(view)
        tracer = globals()["BoundParticleTracer"](Input=reader, Vectors=VECTORS)
        display = simple.Show(tracer, view)
        # What the GUI's Apply does: the tracer's <Visibility replace_input="2"/>
        # hides an input shown as an opaque surface
        # (pqApplyBehavior::hideInputIfRequired) and the plugin one shown as a
        # slice (pqBoundParticleDefaults::shown); an outline stays.
        if (representation_of(shown) in ("Surface", "Surface With Edges") and shown.Opacity == 1
                or representation_of(shown) == "Slice"):
            simple.Hide(reader, view)
        scene = simple.GetAnimationScene()
        scene.UpdateAnimationUsingDataTimeSteps()
        frames, offered = set_frames(scene, tracer, args.frames)
        run_setup(args.setup, simple, tracer, reader, view, scene, gui=False)
        timer = PlayTimer(scene)
        for representation in DISPLAYS:
            display.SetRepresentationType(representation)
            simple.Render(view)
            for _ in range(args.repeats):
                scene.Play()
            rows.append(dict(data=name, display=representation, frames=frames, offered=offered,
                             vectors=VECTORS, view_size=list(view.ViewSize),
                             input_shown=shown.Visibility,
                             input_representation=representation_of(shown),
                             engine=str(tracer.Engine).strip("'"),
                             runs=timer.take()))
        timer.remove()
        simple.Delete(tracer)
        simple.Delete(reader)
        print("pvpython: %s done" % name, file=sys.stderr, flush=True)
    with open(args.output, "w") as out:
        json.dump(rows, out, indent=1)
    # pvpython 5.11 can crash tearing the render view down at exit (an X error
    # in vtkOpenGLFXAAFilter::ReleaseGraphicsResources): the results are written.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


# ---------------------------------------------------------------- table
def print_table(gui_file, pv_file):
    def load(path):
        try:
            with open(path) as f:
                return {(r["data"], r["display"]): r for r in json.load(f)}
        except (OSError, ValueError):
            return {}

    gui, pv = load(gui_file), load(pv_file)
    keys = list(gui) + [k for k in pv if k not in gui]
    if not keys:
        print("gui_play: no results")
        return 1

    def cells(row):
        if not row or not row["runs"]:
            return ("-", "-", "-", "-")
        runs = row["runs"]
        main = [r["main_ms"] for r in runs if "main_ms" in r]
        return ("%.1f" % statistics.median(r["fps"] for r in runs),
                "%.1f" % statistics.median(r["cpu_ms"] for r in runs),
                "%.1f" % statistics.median(main) if main else "-",
                " ".join("%.1f" % r["fps"] for r in runs))

    first = gui.get(keys[0]) or pv.get(keys[0])
    print("Play with the defaults (Vectors %s), %d frames from the start per play, view %dx%d; "
          "fps: median over plays (wall clock), cpu: process CPU ms per frame (render threads "
          "included), main: the main thread's CPU ms per frame"
          % (first["vectors"], first["frames"], first["view_size"][0], first["view_size"][1]))
    header = ("data set", "display", "frames", "GUI fps", "GUI cpu", "GUI main", "pvpy fps",
              "pvpy cpu", "pvpy main", "GUI/pvpy", "GUI plays (fps)", "pvpython plays (fps)")
    fmt = "%-16s %-15s %6s %8s %8s %8s %8s %8s %9s %8s  %-18s %s"
    print(fmt % header)
    for key in keys:
        g, p = gui.get(key), pv.get(key)
        gc, pc = cells(g), cells(p)
        ratio = "-"
        if gc[0] != "-" and pc[0] != "-":
            ratio = "%.2f" % (float(gc[0]) / float(pc[0]))
        frames = (g or p)["frames"]
        print(fmt % (key[0], key[1], frames, gc[0], gc[1], gc[2], pc[0], pc[1], pc[2], ratio,
                     gc[3], pc[3]))
    for label, rows in (("GUI", gui), ("pvpython", pv)):
        if rows:
            print("%s: engine %s; input shown: %s" % (
                label, ", ".join(sorted({r["engine"] for r in rows.values()})),
                ", ".join("%s %s" % (r["data"], r.get("input_representation", "?")
                                     if r["input_shown"] else "hidden")
                          for r in rows.values() if r["display"] == DISPLAYS[0])))
    missing = [k for k in keys if not (gui.get(k) and gui[k]["runs"])]
    if missing:
        print("gui_play: no GUI plays recorded for %s" % ", ".join("/".join(k) for k in missing))
        return 1
    return 0


def main():
    import argparse

    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="mode", required=True)
    xml = sub.add_parser("xml")
    xml.add_argument("--output", required=True)
    xml.add_argument("--data", required=True)
    xml.add_argument("--data-sets", required=True)
    xml.add_argument("--repeats", type=int, default=3)
    pv = sub.add_parser("pvpython")
    pv.add_argument("--plugin", required=True)
    pv.add_argument("--data", required=True)
    pv.add_argument("--data-sets", required=True)
    pv.add_argument("--frames", type=int, default=50)
    pv.add_argument("--repeats", type=int, default=3)
    pv.add_argument("--view-size", type=int, nargs=2, default=[844, 527])
    pv.add_argument("--output", required=True)
    pv.add_argument("--setup")
    table = sub.add_parser("table")
    table.add_argument("gui")
    table.add_argument("pvpython")
    args = parser.parse_args()
    if args.mode == "xml":
        write_events(args.output, os.path.abspath(args.data), os.path.abspath(__file__),
                     args.data_sets.split(","), args.repeats)
    elif args.mode == "pvpython":
        args.data_sets = args.data_sets.split(",")
        pvpython_plays(args)
    else:
        return print_table(args.gui, args.pvpython)
    return 0


MODES = ("xml", "pvpython", "table")
if "BOUNDPARTICLES_GUI_PLAY" in os.environ and not (len(sys.argv) > 1 and sys.argv[1] in MODES):
    gui_step()  # run by the GUI's Python shell (the driver sets the variable for the GUI only)
elif __name__ == "__main__":
    sys.exit(main())
