"""What the benchmarks share: VTK's warnings and errors caught while a block
runs, as ParaView's Output Messages shows them."""
import re


class CapturedMessages:
    """Collects VTK's warnings and errors printed while the block runs, one line each."""

    def __init__(self, into):
        from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
        self.into, self.window = into, vtkStringOutputWindow()
        self.previous = vtkOutputWindow.GetInstance()

    def __enter__(self):
        from vtkmodules.vtkCommonCore import vtkOutputWindow
        vtkOutputWindow.SetInstance(self.window)

    def __exit__(self, *exc):
        from vtkmodules.vtkCommonCore import vtkOutputWindow
        vtkOutputWindow.SetInstance(self.previous)
        # A message is "ERROR: In file, line n" then "class (0x...): text", then a blank line.
        for block in re.split(r"\n\s*\n", self.window.GetOutput().strip()):
            lines = [line.strip() for line in block.splitlines() if line.strip()]
            if lines and ("Warning" in lines[0] or "ERROR" in lines[0]):
                kind = "ERROR" if "ERROR" in lines[0] else "Warning"
                text = re.sub(r" \(0x[0-9a-f]+\)", "", " ".join(lines[1:]) or lines[0])
                self.into.append("%s: %s" % (kind, text))
