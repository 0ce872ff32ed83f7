# Run from the GUI's Python shell by play_updates.xml before Play: counts the
# data-updated events of the first tracer's proxy and of its input's that
# reach the GUI (observers at priority 0, as the GUI's own), during Play and
# after it, and lets the Speed colour map grow on every frame (so that the
# check sees the scene still rescale it while the events are held back).
import builtins

from paraview.simple import FindSource, GetAnimationScene, GetColorTransferFunction

scene = GetAnimationScene().GetClientSideObject()
watch = {"playing": False, "plays": 0, "ticks": 0}


def started(*unused):
    watch["playing"] = True
    watch["plays"] += 1


def ended(*unused):
    watch["playing"] = False


def ticked(*unused):
    if watch["playing"]:
        watch["ticks"] += 1


def counter(name):
    watch[name + " during"] = watch[name + " after"] = 0

    def updated(*unused):
        watch[name + (" during" if watch["playing"] else " after")] += 1

    return updated


# Ahead of every other observer of the scene: the plugin fires the held-back
# events from its own end-of-play observer, which must count as after Play.
scene.AddObserver("StartEvent", started, 10000.0)
scene.AddObserver("EndEvent", ended, 10000.0)
scene.AddObserver("AnimationCueTickEvent", ticked)
for name in ("BoundParticleTracer1", "AnalyticFlow1"):
    FindSource(name).SMProxy.AddObserver("UpdateDataEvent", counter(name), 0.0)
GetColorTransferFunction("Speed").AutomaticRescaleRangeMode = "Grow and update every timestep"
builtins._boundparticles_play_updates = watch
