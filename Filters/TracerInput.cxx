// SPDX-License-Identifier: BSD-3-Clause
#include "TracerInput.h"

#include "DomainMask.h"
#include "VelocityNames.h"

#include "vtkAbstractArray.h"
#include "vtkAlgorithm.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArrayRange.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationExecutivePortKey.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <sstream>
#include <vector>

namespace
{
struct CopyToFloat
{
  template <typename ArrayT>
  void operator()(ArrayT* array, std::vector<float>& out, double scale) const
  {
    const auto values = vtk::DataArrayValueRange(array);
    using Value = typename decltype(values)::ValueType;
    out.resize(values.size());
    if (scale == 1.0)
    {
      std::transform(
        values.begin(), values.end(), out.begin(), [](Value v) { return static_cast<float>(v); });
      return;
    }
    std::transform(values.begin(), values.end(), out.begin(),
      [scale](Value v) { return static_cast<float>(double(v) * scale); });
  }
};

struct LargestFinite
{
  template <typename ArrayT>
  void operator()(ArrayT* array, double& largest) const
  {
    largest = 0.0;
    for (const auto v : vtk::DataArrayValueRange(array))
    {
      const double x = std::abs(double(v));
      largest = std::isfinite(x) && x > largest ? x : largest;
    }
  }
};

/// A vtkValidPointMask's values as 1 (inside) or 0, through the array's own
/// type (a mask resampled from a mesh has as many values as the grid).
struct InsideFlags
{
  template <typename ArrayT>
  void operator()(ArrayT* array, std::vector<std::uint8_t>& out) const
  {
    const auto values = vtk::DataArrayValueRange<1>(array);
    using Value = typename decltype(values)::ValueType;
    // NaN is no answer to "inside?": outside, as a NaN vector is.
    std::transform(values.begin(), values.end(), out.begin(),
      [](Value v) { return std::uint8_t(v != Value(0) && !std::isnan(double(v)) ? 1 : 0); });
  }
};

/// The geometry of a rectilinear grid; empty on success, otherwise what is wrong.
std::string rectilinearGeometry(vtkRectilinearGrid* rectilinear, bp::GridGeometry& g)
{
  std::ostringstream err;
  vtkDataArray* axes[3] = { rectilinear->GetXCoordinates(), rectilinear->GetYCoordinates(),
    rectilinear->GetZCoordinates() };
  int dims[3];
  rectilinear->GetDimensions(dims);
  for (int a = 0; a < 3; ++a)
  {
    if (!axes[a] || axes[a]->GetNumberOfTuples() != dims[a])
    {
      err << "The rectilinear grid's "
          << "XYZ"[a] << " coordinates do not match its " << dims[a] << " points along that axis.";
      return err.str();
    }
    std::vector<double> c(std::size_t(dims[a]));
    for (int i = 0; i < dims[a]; ++i)
    {
      c[std::size_t(i)] = axes[a]->GetComponent(i, 0);
    }
    // Evenly spaced axes are sampled the uniform way: fewer operations, and
    // images and rectilinear grids of the same points trace alike.
    bool even = c.size() > 1;
    const double h = even ? (c.back() - c.front()) / double(c.size() - 1) : 1.0;
    for (std::size_t i = 1; even && i < c.size(); ++i)
    {
      even = std::abs((c[i] - c[i - 1]) - h) <= 1e-6 * std::abs(h);
    }
    if (even)
    {
      g.dims[a] = dims[a];
      g.origin[a] = c.front();
      g.spacing[a] = h;
    }
    else if (c.size() == 1)
    {
      g.dims[a] = 1;
      g.origin[a] = c.front();
    }
    else
    {
      g.setCoordinates(a, std::move(c));
    }
  }
  return std::string();
}
/**
 * Checks what templateFromPolyData() reads before it reads it: every cell's
 * point ids within the mesh (they become 32-bit indices), the Stiffness array
 * one value per cell, and the springs All Pairs would make within the limit.
 */
std::string checkTemplateCells(vtkPolyData* mesh, bp::MeshSprings mode)
{
  std::ostringstream err;
  const vtkIdType n = mesh->GetNumberOfPoints();
  for (vtkCellArray* cells : { mesh->GetPolys(), mesh->GetStrips(), mesh->GetLines() })
  {
    vtkIdType count;
    const vtkIdType* ids;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(count, ids);
      for (vtkIdType k = 0; k < count; ++k)
      {
        if (ids[k] < 0 || ids[k] >= n)
        {
          err << "a cell uses point " << ids[k] << " but the mesh has " << n << " points";
          return err.str();
        }
      }
    }
  }
  vtkDataArray* stiffness = mesh->GetCellData()->GetArray("Stiffness");
  if (stiffness && mesh->GetNumberOfLines() > 0 &&
    stiffness->GetNumberOfTuples() < mesh->GetNumberOfCells())
  {
    err << "its Stiffness cell array has " << stiffness->GetNumberOfTuples() << " values for "
        << mesh->GetNumberOfCells() << " cells; give one value in [0, 1] per cell";
    return err.str();
  }
  const double pairs = 0.5 * double(n) * double(n - 1);
  if (mode == bp::MeshSprings::AllPairs && mesh->GetNumberOfLines() == 0 &&
    pairs > double(bp::MaxTemplateSprings))
  {
    err << "Template Springs = All Pairs on its " << n << " points makes " << pairs
        << " springs, more than the " << bp::MaxTemplateSprings
        << " a template may have; choose Edges or Edges And Diagonals";
    return err.str();
  }
  return std::string();
}
} // namespace

namespace bpvtk
{
namespace
{
/// The input's vtkValidPointMask (ParaView's resampling writes it: 0 where a
/// point lies outside the source's domain) as one byte per point: 1 where
/// the value is non-zero and not NaN. Empty without a usable one; `problem`
/// then says why one of that name was not used.
std::vector<std::uint8_t> validPointMask(vtkDataSet* data, std::string& problem)
{
  std::vector<std::uint8_t> valid;
  vtkAbstractArray* named = data->GetPointData()->GetAbstractArray("vtkValidPointMask");
  vtkDataArray* mask = vtkDataArray::SafeDownCast(named);
  std::ostringstream why;
  if (!named)
  {
    if (data->GetCellData()->GetAbstractArray("vtkValidPointMask"))
    {
      why << "is cell data; it must be point data";
    }
  }
  else if (!mask)
  {
    why << "is a " << named->GetClassName() << "; it must be numbers";
  }
  else if (mask->GetNumberOfComponents() != 1)
  {
    why << "has " << mask->GetNumberOfComponents() << " components; it must have one";
  }
  else if (mask->GetNumberOfTuples() != data->GetNumberOfPoints())
  {
    why << "has " << mask->GetNumberOfTuples() << " values for " << data->GetNumberOfPoints()
        << " points";
  }
  problem = why.str().empty() ? std::string()
                              : "The input's vtkValidPointMask " + why.str() +
      " (0 outside the flow's domain, 1 inside); it is ignored, every point counts as inside.";
  if (!mask || !problem.empty())
  {
    return valid;
  }
  valid.resize(std::size_t(mask->GetNumberOfTuples()));
  using Dispatch = vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::AllTypes>;
  if (!Dispatch::Execute(mask, InsideFlags{}, valid))
  {
    InsideFlags{}(mask, valid);
  }
  return valid;
}
/// The error for a Vectors name the input lacks, with the arrays it has.
std::string missingArray(vtkDataSet* data, const std::string& requested)
{
  std::ostringstream err;
  err << "The input has no array '" << requested << "' for Vectors";
  vtkPointData* pd = data->GetPointData();
  std::string names;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = pd->GetArray(i);
    if (a && a->GetNumberOfComponents() == 3 && a->GetName())
    {
      names += std::string(names.empty() ? "" : ", ") + "'" + a->GetName() + "'";
    }
  }
  err << (names.empty() ? "; it has no 3-component point array."
                        : "; its 3-component point arrays are " + names + ".");
  if (data->GetCellData()->GetAbstractArray(requested.c_str()))
  {
    err << " It has a cell array '" << requested
        << "': the tracer reads point vectors (apply Cell Data to Point Data first).";
  }
  err << " Choose one in Vectors (pvpython: Vectors = ['POINTS', 'name']; a tracer made while "
         "another source is active takes that source's arrays as its default).";
  return err.str();
}
} // namespace

namespace
{
/// The field's dataset (an image or a rectilinear grid with points), or
/// null with `error` saying what the input is instead.
vtkDataSet* fieldDataSet(vtkDataObject* input, std::string& error)
{
  std::ostringstream err;
  vtkDataSet* dataSet = vtkImageData::SafeDownCast(input)
    ? static_cast<vtkDataSet*>(vtkImageData::SafeDownCast(input))
    : vtkRectilinearGrid::SafeDownCast(input);
  if (!dataSet)
  {
    // The tracer resamples any other data first (TracerResample.h).
    err << "The input is a " << (input ? input->GetClassName() : "null data object")
        << "; a field is read from a vtkImageData or a vtkRectilinearGrid.";
  }
  else if (dataSet->GetNumberOfPoints() == 0)
  {
    err << "The input grid is empty: it has no points.";
  }
  error = err.str();
  return error.empty() ? dataSet : nullptr;
}

/// The vector array to trace: `vectors` as selected, or without a selection
/// the first 3-component point array; an error unless it is a 3-component
/// point array of one tuple per point.
std::string chooseVectors(
  vtkDataSet* dataSet, vtkDataArray*& vectors, int association, const std::string& requested)
{
  std::ostringstream err;
  if (!vectors && !requested.empty())
  {
    return missingArray(dataSet, requested);
  }
  if (!vectors && association == vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    // No array chosen and no active vectors: take the first 3-component point array.
    vtkPointData* pd = dataSet->GetPointData();
    for (int i = 0; i < pd->GetNumberOfArrays() && !vectors; ++i)
    {
      vtkDataArray* candidate = pd->GetArray(i);
      if (candidate && candidate->GetNumberOfComponents() == 3)
      {
        vectors = candidate;
      }
    }
  }
  if (!vectors)
  {
    return "The input has no point vector array. Select a 3-component point array with the "
           "Vectors property (pvpython: Vectors = ['POINTS', 'name']).";
  }
  const char* name = vectors->GetName() ? vectors->GetName() : "(unnamed)";
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    err << "The array '" << name
        << "' is not point data; choose a point array (or apply Cell Data to Point Data).";
    if (dataSet->GetPointData()->GetArray(name))
    {
      err << " The input has a point array '" << name << "' too: Vectors = ['POINTS', '" << name
          << "'].";
    }
  }
  else if (vectors->GetNumberOfComponents() != 3)
  {
    err << "The array '" << name << "' has " << vectors->GetNumberOfComponents()
        << " component(s); Bound Particle Tracer needs a 3-component vector array.";
  }
  else if (vectors->GetNumberOfTuples() != dataSet->GetNumberOfPoints())
  {
    err << "The array '" << name << "' has " << vectors->GetNumberOfTuples() << " tuples for "
        << dataSet->GetNumberOfPoints() << " points.";
  }
  return err.str();
}
} // namespace

std::string readSlice(vtkDataObject* input, vtkDataArray* vectors, int association,
  bp::GridGeometry& grid, bp::FieldSlice& slice, int extent[6], std::size_t& nonFinitePoints,
  const std::string& requested, std::string* maskProblem)
{
  nonFinitePoints = 0;
  std::string error;
  vtkDataSet* dataSet = fieldDataSet(input, error);
  if (!dataSet)
  {
    return error;
  }
  vtkImageData* image = vtkImageData::SafeDownCast(dataSet);
  vtkRectilinearGrid* rectilinear = vtkRectilinearGrid::SafeDownCast(dataSet);
  const int* dataExtent = image ? image->GetExtent() : rectilinear->GetExtent();
  std::copy(dataExtent, dataExtent + 6, extent);
  error = chooseVectors(dataSet, vectors, association, requested);
  if (!error.empty())
  {
    return error;
  }
  bp::GridGeometry g;
  if (image)
  {
    if (!image->GetDirectionMatrix()->IsIdentity())
    {
      return "The input image is rotated (its direction matrix is not the identity); Bound "
             "Particle Tracer needs an axis-aligned grid. Resample it with Resample To Image.";
    }
    // Point 0 of an image lies at origin + extent_min * spacing (e.g. after Extract Subset).
    const int* imageExtent = image->GetExtent();
    image->GetDimensions(g.dims.data());
    image->GetOrigin(g.origin.data());
    image->GetSpacing(g.spacing.data());
    for (int a = 0; a < 3; ++a)
    {
      g.origin[a] += imageExtent[2 * a] * g.spacing[a];
    }
  }
  else
  {
    const std::string axesError = rectilinearGeometry(rectilinear, g);
    if (!axesError.empty())
    {
      return axesError;
    }
  }
  auto values = std::make_shared<std::vector<float>>();
  copyToFloats(vectors, *values);
  std::string maskIgnored;
  const std::vector<std::uint8_t> valid = validPointMask(dataSet, maskIgnored);
  if (maskProblem)
  {
    *maskProblem = maskIgnored;
  }
  const bp::DomainMask mask =
    bp::maskOutsidePoints(g, *values, valid.empty() ? nullptr : valid.data());
  nonFinitePoints = mask.nonFinitePoints;
  if (mask.outsidePoints == g.pointCount())
  {
    return "Every point of the input is outside the flow's domain (its vector is NaN or Inf, "
           "or vtkValidPointMask is 0 there): there is no flow to trace.";
  }
  slice.velocity = values;
  slice.outsideCells = mask.outsideCells;
  grid = g;
  return std::string();
}

void copyToFloats(vtkDataArray* array, std::vector<float>& out, double scale)
{
  using Dispatch = vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::AllTypes>;
  if (!Dispatch::Execute(array, CopyToFloat{}, out, scale))
  {
    CopyToFloat{}(array, out, scale);
  }
}

double largestFinite(vtkDataArray* array)
{
  using Dispatch = vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::AllTypes>;
  double largest = 0.0;
  if (!Dispatch::Execute(array, LargestFinite{}, largest))
  {
    LargestFinite{}(array, largest);
  }
  return largest;
}

vtkPolyData* templateMesh(vtkDataObject* data, std::string& error)
{
  error.clear();
  if (auto* mesh = vtkPolyData::SafeDownCast(data))
  {
    return mesh;
  }
  if (vtkCompositeDataSet::SafeDownCast(data))
  {
    error = std::string("The Element Template input is a ") + data->GetClassName() +
      "; give it one polydata (Extract Block picks one, Merge Blocks then Extract Surface "
      "joins them).";
  }
  else if (vtkDataSet::SafeDownCast(data))
  {
    error = std::string("The Element Template input is a ") + data->GetClassName() +
      "; give it a polydata (Extract Surface makes one).";
  }
  else if (data && data->GetNumberOfElements(vtkDataObject::ROW) > 0)
  {
    error = std::string("The Element Template input is a ") + data->GetClassName() +
      ", which has no points; give it a polydata.";
  }
  return nullptr;
}

std::string appendSeedPoints(vtkDataObject* data, std::vector<double>& xyz)
{
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      const std::string error = appendSeedPoints(it->GetCurrentDataObject(), xyz);
      if (!error.empty())
      {
        return error;
      }
    }
    return std::string();
  }
  if (auto* points = vtkDataSet::SafeDownCast(data))
  {
    const vtkIdType n = points->GetNumberOfPoints();
    xyz.reserve(xyz.size() + 3 * std::size_t(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      xyz.insert(xyz.end(), x, x + 3);
    }
    return std::string();
  }
  if (data && data->GetNumberOfElements(vtkDataObject::ROW) > 0)
  {
    return std::string("The Seed Source gives a ") + data->GetClassName() +
      ", which has no points; give it a dataset (or a multiblock of datasets).";
  }
  return std::string(); // no data: no points
}

namespace
{
/// The mesh's polygons (as fans) and strips as triangles.
std::vector<std::array<std::uint32_t, 3>> templateTriangles(vtkPolyData* mesh)
{
  std::vector<std::array<std::uint32_t, 3>> triangles;
  vtkIdType count;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(count, ids);
    for (vtkIdType k = 1; k + 1 < count; ++k) // a fan over each polygon
    {
      triangles.push_back(
        { std::uint32_t(ids[0]), std::uint32_t(ids[k]), std::uint32_t(ids[k + 1]) });
    }
  }
  auto strips = vtk::TakeSmartPointer(mesh->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k + 2 < count; ++k) // every other triangle turned round
    {
      const auto a = std::uint32_t(ids[k]), b = std::uint32_t(ids[k + 1]),
                 c = std::uint32_t(ids[k + 2]);
      triangles.push_back(
        k % 2 ? std::array<std::uint32_t, 3>{ b, a, c } : std::array<std::uint32_t, 3>{ a, b, c });
    }
  }
  return triangles;
}

/// The mesh's lines as springs, each segment with its line's "Stiffness"
/// (cell data; 1 without the array).
void templateLines(vtkPolyData* mesh, std::vector<std::array<std::uint32_t, 2>>& springs,
  std::vector<float>& stiffness)
{
  vtkDataArray* stiffnessArray = mesh->GetCellData()->GetArray("Stiffness");
  const vtkIdType firstLine = mesh->GetNumberOfVerts();
  vtkIdType line = 0;
  vtkIdType count;
  const vtkIdType* ids;
  auto lines = vtk::TakeSmartPointer(mesh->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell(), ++line)
  {
    lines->GetCurrentCell(count, ids);
    const float k =
      stiffnessArray ? float(stiffnessArray->GetComponent(firstLine + line, 0)) : 1.0f;
    for (vtkIdType j = 0; j + 1 < count; ++j)
    {
      springs.push_back({ std::uint32_t(ids[j]), std::uint32_t(ids[j + 1]) });
      stiffness.push_back(k);
    }
  }
}
} // namespace

std::string templateFromPolyData(vtkPolyData* mesh, bp::MeshSprings mode, bp::ElementTemplate& out)
{
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    return "The Element Template input has no points.";
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  const std::string cellsError = checkTemplateCells(mesh, mode);
  if (!cellsError.empty())
  {
    return "The Element Template input is unusable: " + cellsError + ".";
  }
  std::vector<std::array<float, 3>> points(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    points[i] = { float(x[0]), float(x[1]), float(x[2]) };
  }
  const std::vector<std::array<std::uint32_t, 3>> triangles = templateTriangles(mesh);
  std::vector<std::array<std::uint32_t, 2>> springs;
  std::vector<float> stiffness;
  templateLines(mesh, springs, stiffness);
  if (springs.empty())
  {
    springs = bp::meshSprings(std::size_t(n), triangles, mode);
    stiffness.assign(springs.size(), 1.0f);
  }
  out = bp::makeTemplate("Element Template", points, triangles, springs);
  for (std::size_t k = 0; k < out.springs.size() && k < stiffness.size(); ++k)
  {
    out.springs[k].stiffness = stiffness[k];
  }
  if (vtkDataArray* pinned = mesh->GetPointData()->GetArray("Pinned"))
  {
    out.pinned.assign(std::size_t(n), 0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      out.pinned[i] = pinned->GetComponent(i, 0) != 0.0 ? 1 : 0;
    }
  }
  const std::string error = out.validate();
  return error.empty() ? error : "The Element Template input is unusable: " + error + ".";
}

namespace
{
/// The first dataset of `input` (itself, or a composite's first leaf with
/// point or cell arrays).
vtkDataSet* firstDataSet(vtkDataObject* input)
{
  if (auto* set = vtkDataSet::SafeDownCast(input))
  {
    return set;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* set = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (set && set->GetPointData()->GetNumberOfArrays() + set->GetCellData()->GetNumberOfArrays())
    {
      return set;
    }
  }
  return nullptr;
}
} // namespace

std::string describeVectorsChoice(
  vtkDataObject* input, const std::string& name, int association, const std::string& why)
{
  vtkDataSet* set = firstDataSet(input);
  if (!set || name.empty())
  {
    return std::string();
  }
  std::vector<std::string> others;
  bool active = false;
  for (vtkDataSetAttributes* arrays : { static_cast<vtkDataSetAttributes*>(set->GetPointData()),
         static_cast<vtkDataSetAttributes*>(set->GetCellData()) })
  {
    const int at = arrays == set->GetPointData() ? vtkDataObject::FIELD_ASSOCIATION_POINTS
                                                 : vtkDataObject::FIELD_ASSOCIATION_CELLS;
    for (int i = 0; i < arrays->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* array = arrays->GetArray(i);
      if (!array || array->GetNumberOfComponents() != 3 || !array->GetName())
      {
        continue;
      }
      if (at == association && name == array->GetName())
      {
        active = arrays->GetVectors() == array;
        continue;
      }
      if (std::find(others.begin(), others.end(), array->GetName()) == others.end())
      {
        others.emplace_back(array->GetName());
      }
    }
  }
  if (others.empty())
  {
    return std::string();
  }
  std::ostringstream note;
  note << "Bound Particle Tracer: traces '" << name << "' ("
       << (!why.empty()                         ? why
              : active                          ? "the input's active vectors"
              : bp::velocityNameRank(name) >= 0 ? "named like a velocity"
                                                : "as Vectors asks")
       << "); the input's other 3-component arrays: ";
  for (std::size_t k = 0; k < others.size(); ++k)
  {
    note << (k ? ", " : "") << others[k];
  }
  note << ". Set Vectors to trace another.\n";
  return note.str();
}

std::string cellVectorsMadePoints(vtkInformation* inInfo, const std::string& name)
{
  if (!inInfo || name.empty())
  {
    return std::string();
  }
  // ParaView puts its post filter between a source and the filters that
  // read it: it makes an array a filter asks for out of the other
  // association's array of that name, silently (vtkPVPostFilter).
  vtkExecutive* executive = vtkExecutive::PRODUCER()->GetExecutive(inInfo);
  vtkAlgorithm* producer = executive ? executive->GetAlgorithm() : nullptr;
  if (!producer || !producer->IsA("vtkPVPostFilter") || producer->GetNumberOfInputPorts() < 1 ||
    producer->GetNumberOfInputConnections(0) < 1)
  {
    return std::string();
  }
  vtkDataSet* given = firstDataSet(executive->GetInputData(0, 0));
  if (!given || given->GetPointData()->GetAbstractArray(name.c_str()) ||
    !given->GetCellData()->GetAbstractArray(name.c_str()))
  {
    return std::string();
  }
  return "The input has no point array '" + name + "' (Vectors asks for one), only a cell array '" +
    name +
    "': ParaView interpolates it to the points for the tracer (as Cell Data to Point Data "
    "would), and that is traced, here and at every step that holds only the cell array. "
    "Choose a point array in Vectors to trace another.";
}

} // namespace bpvtk
