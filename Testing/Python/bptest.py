"""Helpers shared by the pvpython tests."""
import argparse
import sys

from vtkmodules.util import vtkConstants
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import vtkOutputWindow

failures = []


def check(condition, message):
    """Records a failed expectation and goes on, like EXPECT_* in GoogleTest."""
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")
    sys.exit(0)


def arguments(*extra):
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin")
    for name in extra:
        parser.add_argument(name)
    return parser.parse_args()


class CapturedMessages:
    """Collects the VTK errors and warnings shown in ParaView's Output Messages."""

    def __enter__(self):
        self.messages = []

        @calldata_type(vtkConstants.VTK_STRING)
        def keep(obj, event, text):
            self.messages.append(text)

        self._keep = keep
        window = vtkOutputWindow.GetInstance()
        self._tags = [window.AddObserver("ErrorEvent", keep),
                      window.AddObserver("WarningEvent", keep)]
        return self

    def __exit__(self, *exc):
        window = vtkOutputWindow.GetInstance()
        for tag in self._tags:
            window.RemoveObserver(tag)
        return False

    def mentions(self, part):
        return any(part in m for m in self.messages)
