"""A saved trace state (the tracer's State output written as .vtp) read back
for a test: shared by the pvpython tests and the GUI's check scripts
(run_gui_playback.sh puts this folder on their path)."""
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read_state(path):
    """The state file's cell arrays (the engine's records) and field arrays,
    by name: numeric arrays as numpy arrays, string arrays as lists."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    cells = {}
    for k in range(data.GetCellData().GetNumberOfArrays()):
        a = data.GetCellData().GetArray(k)
        cells[a.GetName()] = vtk_to_numpy(a).copy()
    fields = {}
    for k in range(data.GetFieldData().GetNumberOfArrays()):
        a = data.GetFieldData().GetAbstractArray(k)
        if a.IsA("vtkDataArray"):
            fields[a.GetName()] = vtk_to_numpy(a).copy()
        else:
            fields[a.GetName()] = [a.GetValue(i) for i in range(a.GetNumberOfValues())]
    return cells, fields
