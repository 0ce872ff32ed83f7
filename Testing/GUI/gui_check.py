"""What the GUI check scripts share. The playback tests (Testing/GUI/*.xml)
run each check from ParaView's Python shell; the script sets a property the
playback then checks (Coloring Axis or Number Of Elements) when everything it
looks for holds. What it found, condition by condition, goes to the terminal
(fd 2, which the test's log has; the shell's own text is lost), so a failed
playback says why. run_gui_playback.sh puts this folder on PYTHONPATH."""
import os
import traceback


def say(script, text):
    """One line on the terminal, named by its script."""
    os.write(2, ("%s: %s\n" % (script, text)).encode())


def passed(script, found, seen=None):
    """Whether every condition of `found` (name: bool) holds; says each one,
    and what was read (`seen`, name: value), on the terminal."""
    text = "; ".join("%s %s" % (name, "yes" if ok else "NO") for name, ok in found.items())
    if seen:
        text += " (seen: %s)" % ", ".join("%s %s" % item for item in seen.items())
    say(script, text)
    return all(found.values())


def run(script, check):
    """Runs check(): an exception is said on the terminal, where the shell
    would keep it to itself and the playback would only see a property
    unset."""
    try:
        check()
    except Exception:
        say(script, "failed:\n" + traceback.format_exc())


def resident_mib():
    """The process's resident memory, MiB."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024.0
    return 0.0
