"""Helpers of the in situ tests: a trivial producer fed one step at a time as
a simulation feeds Catalyst's, and the tracer's elements by particle."""
import numpy
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy


def copy_of(proxy, time, port=0):
    """`proxy`'s output at `time`, deep-copied, as a simulation would hand it over."""
    proxy.UpdatePipeline(time)
    source = proxy.GetClientSideObject().GetOutputDataObject(port)
    data = source.NewInstance()
    data.DeepCopy(source)
    return data


def feed(producer, data, time):
    """Hands `data` at `time` to a PVTrivialProducer, as Catalyst's adaptor does."""
    producer.GetClientSideObject().SetOutput(data, time)
    producer.MarkModified(producer)


def by_particle(data):
    """{(ElementId, ParticleIndex): position} of a tracer's output."""
    if data is None or data.GetNumberOfPoints() == 0:
        return {}
    ids = vtk_to_numpy(data.GetPointData().GetArray("ElementId"))
    index = vtk_to_numpy(data.GetPointData().GetArray("ParticleIndex"))
    points = vtk_to_numpy(data.GetPoints().GetData())
    return {(int(e), int(p)): points[k] for k, (e, p) in enumerate(zip(ids, index))}


def elements(proxy, time):
    """The tracer's elements at `time`, by particle."""
    proxy.UpdatePipeline(time)
    return by_particle(servermanager.Fetch(proxy))


def farthest(a, b):
    """The largest distance along an axis between the same particles of `a`
    and `b`; infinite when they hold different particles (or none)."""
    if not a or set(a) != set(b):
        return float("inf")
    return float(max(numpy.abs(a[key] - b[key]).max() for key in a))
