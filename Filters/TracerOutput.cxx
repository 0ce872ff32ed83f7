// SPDX-License-Identifier: BSD-3-Clause
#include "TracerOutput.h"
#include "TracerOutputArrays.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include "SuperSetLinks.h"
#include "ValueRanges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace
{
/// A line per link of a super set: particle i of an element to particle i of
/// its neighbour, each link once.
vtkSmartPointer<vtkCellArray> buildLinkCells(const bp::LinkTable& links, std::size_t n)
{
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(vtkIdType(2 * links.linkCount() * n));
  vtkIdType* out = connectivity->GetPointer(0);
  bp::forEachLink(links,
    [&out, n](std::size_t e, std::size_t f)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        *out++ = vtkIdType(e * n + i);
        *out++ = vtkIdType(f * n + i);
      }
    });
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(2, connectivity);
  return cells;
}

/// The cells of the `shown` elements (their indices, increasing).
vtkSmartPointer<vtkCellArray> buildCells(
  const bp::ElementTemplate& shape, const std::vector<std::uint32_t>& shown, int& kind)
{
  const std::size_t elements = shown.size();
  const std::size_t n = shape.particleCount();
  int cellSize;
  std::vector<std::uint32_t> local;
  const std::vector<std::uint32_t> strip = bp::triangleStrip(shape);
  if (!strip.empty())
  {
    // One strip per element: the same triangles, a fourteenth of the cells
    // for a Strip16, which ParaView walks cell by cell every frame.
    kind = 3;
    cellSize = int(strip.size());
    local = strip;
  }
  else if (!shape.triangles.empty())
  {
    kind = 2;
    cellSize = 3;
    for (const auto& t : shape.triangles)
      local.insert(local.end(), t.begin(), t.end());
  }
  else if (!shape.springs.empty())
  {
    kind = 1;
    cellSize = 2;
    for (const auto& s : shape.springs)
    {
      local.push_back(s.a);
      local.push_back(s.b);
    }
  }
  else
  {
    kind = 0;
    cellSize = 1;
    for (std::size_t i = 0; i < n; ++i)
      local.push_back(std::uint32_t(i));
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(vtkIdType(local.size() * elements));
  vtkIdType* out = connectivity->GetPointer(0);
  vtkSMPTools::For(vtkIdType(0), vtkIdType(elements),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const vtkIdType offset = vtkIdType(shown[std::size_t(e)]) * vtkIdType(n);
        vtkIdType* o = out + e * vtkIdType(local.size());
        for (std::size_t k = 0; k < local.size(); ++k)
          o[k] = offset + local[k];
      }
    });
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(cellSize, connectivity);
  return cells;
}

int vtkTypeOf(bp::ValueType type)
{
  switch (type)
  {
    case bp::ValueType::IdType:
      return VTK_ID_TYPE;
    case bp::ValueType::Int:
      return VTK_INT;
    case bp::ValueType::Float:
      break;
  }
  return VTK_FLOAT;
}

vtkSmartPointer<vtkDataArray> newArray(const bp::OutputArray& row, vtkIdType tuples)
{
  auto a = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(vtkTypeOf(row.type)));
  a->SetName(row.name);
  a->SetNumberOfComponents(row.components);
  a->SetNumberOfTuples(tuples);
  return a;
}

/// Adds `array` to the point data as its row's attribute.
void addToPointData(vtkPointData* pd, const bp::OutputArray& row, vtkDataArray* array)
{
  switch (row.role)
  {
    case bp::ArrayRole::Normals:
      pd->SetNormals(array);
      break;
    case bp::ArrayRole::Vectors:
      pd->SetVectors(array);
      break;
    case bp::ArrayRole::Scalars:
      pd->SetScalars(array);
      break;
    case bp::ArrayRole::Plain:
      pd->AddArray(array);
      break;
  }
}

/// Stores per-component ranges under `key` as vtkDataArray::ComputeRange does.
void storeComponentRanges(
  vtkInformation* info, vtkInformationInformationVectorKey* key, const std::vector<bp::Range>& r)
{
  vtkNew<vtkInformationVector> perComponent;
  perComponent->SetNumberOfInformationObjects(int(r.size()));
  for (std::size_t c = 0; c < r.size(); ++c)
  {
    perComponent->GetInformationObject(int(c))->Set(
      vtkDataArray::COMPONENT_RANGE(), r[c].data(), 2);
  }
  info->Set(key, perComponent);
}

/**
 * Calls f with `array`'s values as T* for the value types the output writes
 * (float, double, int, vtkIdType); false for any other.
 */
template <typename F>
bool withValues(vtkDataArray* array, F&& f)
{
  void* values = array->GetVoidPointer(0);
  switch (array->GetDataType())
  {
    case VTK_FLOAT:
      f(static_cast<float*>(values));
      return true;
    case VTK_DOUBLE:
      f(static_cast<double*>(values));
      return true;
    case VTK_INT:
      f(static_cast<int*>(values));
      return true;
    case VTK_ID_TYPE:
      static_assert(std::is_same<vtkIdType, long long>::value, "ValueRanges has long long");
      f(static_cast<long long*>(values));
      return true;
    default:
      return false;
  }
}

/**
 * Hands `array` its ranges in the information keys where VTK caches them:
 * VTK uses them until the array is next modified. ParaView's data
 * information asks for all of them after each update, which cost 40% of a
 * frame when VTK computed them (issue 16). Call it after the array's last
 * Modified().
 */
void storeRanges(vtkDataArray* array, const bp::ValueRanges& r)
{
  vtkInformation* info = array->GetInformation();
  storeComponentRanges(info, vtkAbstractArray::PER_COMPONENT(), r.component);
  storeComponentRanges(info, vtkAbstractArray::PER_FINITE_COMPONENT(), r.finiteComponent);
  if (array->GetNumberOfComponents() > 1)
  {
    info->Set(vtkDataArray::L2_NORM_RANGE(), r.magnitude.data(), 2);
    info->Set(vtkDataArray::L2_NORM_FINITE_RANGE(), r.finiteMagnitude.data(), 2);
  }
}

/// An output array in the pass that writes them all: what writes its
/// particles' tuples (blocks of whole elements) and what writes the tuples
/// after them (the trails', may be empty when there are none).
struct OutputWrite
{
  vtkDataArray* array;
  bp::BlockWriter particles;
  std::function<void()> trail;
};

/**
 * Writes every array in one parallel pass over blocks of whole elements of
 * `n` particles, each block's ranges taken as it is written (while in
 * cache), then the trails' tuples, and hands each array its ranges.
 */
void writeAll(const std::vector<OutputWrite>& writes, std::size_t particles, std::size_t n,
  const bp::RangeRunner& run)
{
  std::vector<bp::WrittenArray> pass(writes.size());
  for (std::size_t k = 0; k < writes.size(); ++k)
  {
    withValues(writes[k].array, [&](auto* values) { pass[k].setValues(values); });
    pass[k].components = writes[k].array->GetNumberOfComponents();
    pass[k].write = writes[k].particles;
  }
  std::vector<bp::ValueRanges> ranges = bp::writeTogether(pass, particles, n, run);
  for (std::size_t k = 0; k < writes.size(); ++k)
  {
    vtkDataArray* array = writes[k].array;
    const std::size_t tuples = std::size_t(array->GetNumberOfTuples());
    if (tuples > particles)
    {
      writes[k].trail();
      const std::size_t c = std::size_t(array->GetNumberOfComponents());
      withValues(array,
        [&](auto* values)
        {
          bp::mergeRanges(
            ranges[k], bp::valueRanges(values + particles * c, tuples - particles, int(c), run));
        });
    }
  }
  for (std::size_t k = 0; k < writes.size(); ++k)
  {
    storeRanges(writes[k].array, ranges[k]); // after the arrays' last Modified()
  }
}

/**
 * The output's points, and how to write them: world positions, grid-local
 * ones plus the grid's offset, in double where float would lose more than
 * 1e-4 of a cell at the field's coordinates.
 */
OutputWrite setPoints(vtkPolyData* output, const bp::Engine& engine,
  const bpvtk::OutputFrame& frame, const std::vector<bpvtk::TrailPose>& trail,
  bpvtk::OutputStorage& storage)
{
  const bool doubles = frame.reach * std::ldexp(1.0, -23) > 1e-4 * frame.cellLength;
  const std::size_t N = engine.particleCount();
  const std::size_t n = engine.particlesPerElement(), E = engine.elementCount();
  vtkNew<vtkPoints> points;
  points->SetData(
    storage.pointData(doubles ? VTK_DOUBLE : VTK_FLOAT, vtkIdType(N + trail.size() * n)));
  output->SetPoints(points);
  vtkDataArray* data = points->GetData();
  // Written through the array's own pointer: a virtual call per component
  // made this copy cost half an engine step (12 ms at a million particles).
  // Four points (12 values) a round against the offset repeated four times:
  // a loop the compiler turns into packed conversions and additions.
  std::array<double, 12> tiled;
  for (std::size_t k = 0; k < 12; ++k)
  {
    tiled[k] = frame.offset[k % 3];
  }
  auto shift = [tiled, data](const float* local, std::size_t begin, std::size_t end)
  {
    withValues(data,
      [&](auto* coords)
      {
        using Coordinate = std::remove_pointer_t<decltype(coords)>;
        Coordinate* out = coords + 3 * begin;
        const std::size_t values = 3 * (end - begin);
        std::size_t k = 0;
        for (; k + 12 <= values; k += 12)
        {
          for (std::size_t j = 0; j < 12; ++j)
          {
            out[k + j] = Coordinate(double(local[k + j]) + tiled[j]);
          }
        }
        for (; k < values; ++k)
        {
          out[k] = Coordinate(double(local[k]) + tiled[k % 3]);
        }
      });
  };
  const float* local = engine.positions().data();
  return { data,
    [shift, local](std::size_t begin, std::size_t end) { shift(local + 3 * begin, begin, end); },
    [shift, &engine, &trail, N, n, E]
    {
      // The trails' poses after the elements, a block of n points each.
      for (std::size_t j = 0; j < trail.size(); ++j)
      {
        const float* p =
          engine.trailPositions().data() + 3 * (trail[j].slot * E + trail[j].element) * n;
        shift(p, N + j * n, N + (j + 1) * n);
      }
    } };
}

} // namespace

namespace bpvtk
{

void OutputStorage::applyCells(
  vtkPolyData* output, const bp::Engine& engine, std::size_t trailPoses)
{
  const std::size_t E = engine.elementCount();
  // An element placed outside the release window, or terminated at the
  // boundary (Boundary Terminate), keeps its points but has no cells.
  std::vector<std::uint8_t> hidden(E);
  const std::vector<std::uint8_t>& flags = engine.resetFlags();
  std::transform(flags.begin(), flags.end(), hidden.begin(),
    [](std::uint8_t f) { return std::uint8_t((f & bp::HiddenFlags) != 0); });
  if (!this->Cells || this->Elements != E || hidden != this->Hidden)
  {
    this->Elements = E; // in parallel, the count changes as elements move
    this->Hidden = std::move(hidden);
    std::vector<std::uint32_t> shown;
    shown.reserve(E);
    for (std::size_t e = 0; e < E; ++e)
    {
      if (!this->Hidden[e])
      {
        shown.push_back(std::uint32_t(e));
      }
    }
    this->Cells = buildCells(engine.shape(), shown, this->Kind);
    // A super set is released whole: hidden, it has no links either.
    this->LinkCells = engine.links().empty() || shown.size() < E
      ? nullptr
      : buildLinkCells(engine.links(), engine.particlesPerElement());
    if (this->LinkCells && this->Kind == 1)
    {
      // Springs drawn as lines: the links join them in the one line array.
      this->Cells->Append(this->LinkCells);
    }
  }
  vtkSmartPointer<vtkCellArray> cells = this->Cells;
  if (trailPoses > 0)
  {
    // The trail poses' points follow the elements' as E + j: their cells
    // are made anew each time, the elements' appended to the kept ones.
    std::vector<std::uint32_t> poses(trailPoses);
    for (std::size_t j = 0; j < trailPoses; ++j)
    {
      poses[j] = std::uint32_t(E + j);
    }
    int kind = this->Kind;
    cells = vtkSmartPointer<vtkCellArray>::New();
    cells->Append(this->Cells);
    cells->Append(buildCells(engine.shape(), poses, kind));
  }
  switch (this->Kind)
  {
    case 0:
      output->SetVerts(cells);
      break;
    case 1:
      output->SetLines(cells);
      break;
    case 3:
      output->SetStrips(cells);
      break;
    default:
      output->SetPolys(cells);
  }
  if (this->LinkCells && this->Kind != 1)
  {
    output->SetLines(this->LinkCells);
  }
}

vtkSmartPointer<vtkDataArray> OutputStorage::take(
  std::vector<vtkSmartPointer<vtkDataArray>>& kept, int dataType, int components, vtkIdType tuples)
{
  for (vtkSmartPointer<vtkDataArray>& a : kept)
  {
    // Held here alone: the last output let go of it, and so did every copy.
    if (a->GetReferenceCount() == 1 && a->GetDataType() == dataType &&
      a->GetNumberOfComponents() == components && a->GetNumberOfTuples() == tuples)
    {
      a->Modified(); // new values; drops the cached ranges
      return a;
    }
  }
  auto a = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(dataType));
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  if (kept.size() == 2)
  {
    kept.erase(kept.begin()); // the oldest; its holders keep it alive
  }
  kept.push_back(a);
  return a;
}

vtkSmartPointer<vtkDataArray> OutputStorage::array(const bp::OutputArray& row, vtkIdType tuples)
{
  auto a = this->take(this->Kept[std::size_t(row.id)], vtkTypeOf(row.type), row.components, tuples);
  a->SetName(row.name);
  return a;
}

vtkSmartPointer<vtkDataArray> OutputStorage::pointData(int dataType, vtkIdType count)
{
  return this->take(this->Kept.back(), dataType, 3, count);
}

vtkDataArray* OutputStorage::unchanged(const bp::OutputArray& row, std::uint64_t key) const
{
  const auto& last = this->Unchanged[std::size_t(row.id)];
  return key != 0 && last.first == key ? last.second.Get() : nullptr;
}

void OutputStorage::setUnchanged(const bp::OutputArray& row, std::uint64_t key, vtkDataArray* array)
{
  // Without a key nothing is held: the array's memory is free to be reused.
  this->Unchanged[std::size_t(row.id)] = { key, key != 0 ? array : nullptr };
}

void fillParticleOutput(vtkPolyData* output, const bp::Engine& engine, const bp::VectorField& field,
  const OutputFrame& frame, OutputStorage& storage, const bp::RangeRunner& run)
{
  const std::vector<TrailPose> trail = trailPoses(engine, field, frame.time);
  std::vector<OutputWrite> writes = { setPoints(output, engine, frame, trail, storage) };
  storage.applyCells(output, engine, trail.size());
  const vtkIdType points =
    vtkIdType(engine.particleCount() + trail.size() * engine.particlesPerElement());
  FillContext context{ engine, field, frame, run, trail, {} };
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  std::array<std::uint64_t, std::size_t(bp::OutputArrayId::Count)> keys{};
  std::array<bool, std::size_t(bp::OutputArrayId::Count)> shownAgain{};
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    // Age only with trails: without, it would be 0 everywhere.
    const bool trails = !engine.trailTimes().empty();
    const std::size_t r = std::size_t(row.id);
    keys[r] = unchangedKey(row, context);
    if (frame.wants(row) && (row.source != bp::ArraySource::TrailAge || trails))
    {
      vtkDataArray* last = storage.unchanged(row, keys[r]);
      shownAgain[r] = last != nullptr;
      arrays.push_back(last ? vtkSmartPointer<vtkDataArray>(last) : storage.array(row, points));
      context.arrays[r] = arrays.back();
    }
  }
  // In the table's order: a row may read the arrays of rows before it.
  vtkPointData* pd = output->GetPointData();
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    vtkDataArray* array = context.array(row.id);
    if (array && shownAgain[std::size_t(row.id)])
    {
      addToPointData(pd, row, array); // its values and ranges as they were
    }
    else if (array)
    {
      writes.push_back({ array,
        [&row, array, &context](std::size_t begin, std::size_t end)
        { writeParticles(row, array, context, begin, end); },
        [&row, array, &context] { extendToTrail(row, array, context); } });
      addToPointData(pd, row, array);
    }
  }
  writeAll(writes, engine.particleCount(), engine.particlesPerElement(), run);
  // Once written: the arrays that may be shown again as they are.
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    vtkDataArray* array = context.array(row.id);
    storage.setUnchanged(row, array ? keys[std::size_t(row.id)] : 0, array);
  }
}

void fillRangeOutput(
  vtkPolyData* output, const bp::RangeFacts& facts, const std::array<double, 6>& worldBounds)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(worldBounds[0], worldBounds[2], worldBounds[4]);
  points->InsertNextPoint(worldBounds[1], worldBounds[3], worldBounds[5]);
  output->SetPoints(points);
  vtkPointData* pd = output->GetPointData();
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    const std::array<double, 2> range = bp::expectedRange(row, facts);
    vtkSmartPointer<vtkDataArray> a = newArray(row, 2);
    for (int c = 0; c < row.components; ++c)
    {
      a->SetComponent(0, c, range[0]);
      a->SetComponent(1, c, range[1]);
    }
    addToPointData(pd, row, a);
  }
}

void addFieldValue(vtkPolyData* output, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  output->GetFieldData()->AddArray(a);
}

} // namespace bpvtk
