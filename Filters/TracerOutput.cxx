// SPDX-License-Identifier: BSD-3-Clause
#include "TracerOutput.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include "ValueRanges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>
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
  const std::size_t elements = links.sites.size() / 3;
  for (std::size_t e = 0; e < elements; ++e)
  {
    for (int d : { 0, 2 }) // +u and +v: each link once
    {
      const std::int32_t f = links.neighbours[bp::LinkDirections * e + d];
      for (std::size_t i = 0; f >= 0 && i < n; ++i)
      {
        *out++ = vtkIdType(e * n + i);
        *out++ = vtkIdType(std::size_t(f) * n + i);
      }
    }
  }
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

float* floats(vtkDataArray* a)
{
  return static_cast<vtkFloatArray*>(a)->GetPointer(0);
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
 * Hands `array` its ranges, computed now while the values are warm, in the
 * information keys where VTK caches them: VTK uses them until the array is
 * next modified. ParaView's data information asks for all of them after each
 * update, which cost 40% of a frame when VTK computed them (issue 16). Call it
 * after the array's last Modified().
 */
void primeRanges(vtkDataArray* array, const bp::RangeRunner& run)
{
  const std::size_t tuples = std::size_t(array->GetNumberOfTuples());
  const int n = array->GetNumberOfComponents();
  if (tuples == 0)
  {
    return;
  }
  const void* values = array->GetVoidPointer(0);
  bp::ValueRanges r;
  switch (array->GetDataType())
  {
    case VTK_FLOAT:
      r = bp::valueRanges(static_cast<const float*>(values), tuples, n, run);
      break;
    case VTK_DOUBLE:
      r = bp::valueRanges(static_cast<const double*>(values), tuples, n, run);
      break;
    case VTK_INT:
      r = bp::valueRanges(static_cast<const int*>(values), tuples, n, run);
      break;
    case VTK_ID_TYPE:
      static_assert(std::is_same<vtkIdType, long long>::value, "ValueRanges has long long");
      r = bp::valueRanges(static_cast<const long long*>(values), tuples, n, run);
      break;
    default:
      return; // VTK computes it when asked
  }
  vtkInformation* info = array->GetInformation();
  storeComponentRanges(info, vtkAbstractArray::PER_COMPONENT(), r.component);
  storeComponentRanges(info, vtkAbstractArray::PER_FINITE_COMPONENT(), r.finiteComponent);
  if (n > 1)
  {
    info->Set(vtkDataArray::L2_NORM_RANGE(), r.magnitude.data(), 2);
    info->Set(vtkDataArray::L2_NORM_FINITE_RANGE(), r.finiteMagnitude.data(), 2);
  }
}

/// A pose of an element's trail that the output shows.
struct TrailPose
{
  std::size_t slot;    ///< in the engine's trail ring
  std::size_t element; ///< whose pose it is
  float age;           ///< how long before the time shown
};

/**
 * The trail poses to show at `time`, newest first: those of each shown
 * element's own generation (a released element starts a new trail), strictly
 * older than the time shown (a step taken back leaves none ahead of it).
 */
std::vector<TrailPose> trailPoses(const bp::Engine& engine, double time)
{
  std::vector<TrailPose> poses;
  const int length = int(engine.trailTimes().size());
  const std::size_t E = engine.elementCount();
  for (int k = 0; k < length; ++k)
  {
    const std::size_t slot = std::size_t(engine.trailSlot(k));
    const double recorded = engine.trailTimes()[slot];
    if (!(recorded < time))
    {
      continue;
    }
    for (std::size_t e = 0; e < E; ++e)
    {
      if (engine.trailGenerations()[slot * E + e] == engine.generations()[e] &&
        !(engine.resetFlags()[e] & bp::ReleaseHidden))
      {
        poses.push_back({ slot, e, float(time - recorded) });
      }
    }
  }
  return poses;
}

/**
 * World positions: grid-local ones plus the grid's offset, in double where
 * float would lose more than 1e-4 of a cell at the field's coordinates.
 */
void setPoints(vtkPolyData* output, const bp::Engine& engine, const bpvtk::OutputFrame& frame,
  const std::vector<TrailPose>& trail, bpvtk::OutputStorage& storage, const bp::RangeRunner& run)
{
  const bool doubles = frame.reach * std::ldexp(1.0, -23) > 1e-4 * frame.cellLength;
  const vtkIdType N = vtkIdType(engine.particleCount());
  const std::size_t n = engine.particlesPerElement(), E = engine.elementCount();
  vtkNew<vtkPoints> points;
  points->SetData(
    storage.pointData(doubles ? VTK_DOUBLE : VTK_FLOAT, N + vtkIdType(trail.size() * n)));
  const float* local = engine.positions().data();
  const double offset[3] = { frame.offset[0], frame.offset[1], frame.offset[2] };
  // Written through the array's own pointer: a virtual call per component
  // made this copy cost half an engine step (12 ms at a million particles).
  auto shift = [&](auto* coords)
  {
    using Coordinate = std::remove_pointer_t<decltype(coords)>;
    vtkSMPTools::For(vtkIdType(0), 3 * N,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          coords[k] = Coordinate(double(local[k]) + offset[k % 3]);
        }
      });
    // The trails' poses after the elements, a block of n points each.
    for (std::size_t j = 0; j < trail.size(); ++j)
    {
      const float* p =
        engine.trailPositions().data() + 3 * (trail[j].slot * E + trail[j].element) * n;
      Coordinate* out = coords + 3 * (std::size_t(N) + j * n);
      for (std::size_t k = 0; k < 3 * n; ++k)
      {
        out[k] = Coordinate(double(p[k]) + offset[k % 3]);
      }
    }
  };
  if (auto* d = vtkDoubleArray::SafeDownCast(points->GetData()))
  {
    shift(d->GetPointer(0));
  }
  else
  {
    shift(floats(points->GetData()));
  }
  primeRanges(points->GetData(), run);
  output->SetPoints(points);
}

/// What filling an array may read: the engine, the field, the frame, and the
/// output's arrays by id (null where the frame does not want one); those of
/// earlier rows are filled.
struct FillContext
{
  const bp::Engine& engine;
  const bp::VectorField& field;
  const bpvtk::OutputFrame& frame;
  const bp::RangeRunner& run;
  const std::vector<TrailPose>& trail;
  std::array<vtkDataArray*, std::size_t(bp::OutputArrayId::Count)> arrays;

  vtkDataArray* array(bp::OutputArrayId id) const { return this->arrays[std::size_t(id)]; }
};

/// Writes `count` floats of element e's `stride` at `values` on every
/// particle of every element e.
void perElementTuple(
  float* out, const bp::Engine& engine, const float* values, int stride, int count)
{
  const std::size_t n = engine.particlesPerElement();
  vtkSMPTools::For(vtkIdType(0), vtkIdType(engine.elementCount()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const float* v = values + std::size_t(e) * std::size_t(stride);
        for (std::size_t i = 0; i < n; ++i)
        {
          std::copy_n(v, count, out + (std::size_t(e) * n + i) * std::size_t(count));
        }
      }
    });
}

/// Writes value(e) on every particle of every element e.
template <typename T, typename Value>
void perElement(T* out, const bp::Engine& engine, const Value& value)
{
  const vtkIdType n = vtkIdType(engine.particlesPerElement());
  vtkSMPTools::For(vtkIdType(0), vtkIdType(engine.elementCount()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        std::fill_n(out + e * n, n, T(value(std::size_t(e))));
      }
    });
}

void fillParticleState(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  const std::size_t N = c.engine.particleCount();
  switch (row.id)
  {
    case bp::OutputArrayId::Normals:
      std::memcpy(floats(out), c.engine.normals().data(), sizeof(float) * 3 * N);
      break;
    case bp::OutputArrayId::Force:
      std::memcpy(floats(out), c.engine.forces().data(), sizeof(float) * N);
      break;
    default:
      break;
  }
}

/**
 * Velocity, and Vorticity from the same cell, in one pass: the Velocity row
 * fills both, and the Vorticity row alone only when Velocity is left out.
 */
void fillFieldSample(const bp::OutputArray& row, vtkDataArray* /*out*/, const FillContext& c)
{
  vtkDataArray* velocityArray = c.array(bp::OutputArrayId::Velocity);
  vtkDataArray* vorticityArray = c.array(bp::OutputArrayId::Vorticity);
  if (row.id == bp::OutputArrayId::Vorticity && velocityArray)
  {
    return; // filled with Velocity
  }
  const std::size_t N = c.engine.particleCount();
  const float* positions = c.engine.positions().data();
  std::vector<float> scratch;
  float* velocity = velocityArray ? floats(velocityArray) : nullptr;
  if (!velocity)
  {
    scratch.resize(3 * N);
    velocity = scratch.data();
  }
  float* vorticity = vorticityArray ? floats(vorticityArray) : nullptr;
  bp::sampleAtPositions(c.field, c.frame.time, positions, N, velocity, vorticity, c.run);
}

void fillDerived(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  if (row.id == bp::OutputArrayId::Speed)
  {
    std::vector<float> sampled; // Velocity's values when the output leaves it out
    const float* v = nullptr;
    if (vtkDataArray* velocity = c.array(bp::OutputArrayId::Velocity))
    {
      v = floats(velocity);
    }
    else
    {
      sampled.resize(3 * c.engine.particleCount());
      bp::sampleAtPositions(c.field, c.frame.time, c.engine.positions().data(),
        c.engine.particleCount(), sampled.data(), nullptr, c.run);
      v = sampled.data();
    }
    float* speed = floats(out);
    vtkSMPTools::For(vtkIdType(0), vtkIdType(c.engine.particleCount()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const float* w = v + 3 * i;
          speed[i] = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
      });
  }
}

void fillElementState(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  const bp::Engine& engine = c.engine;
  const int axis = c.frame.coloringAxis;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const auto& b = c.frame.domain;
  const double cu = 0.5 * (b[2 * u] + b[2 * u + 1]), cv = 0.5 * (b[2 * v] + b[2 * v + 1]);
  const float* centres = engine.initialCenters().data();
  switch (row.id)
  {
    case bp::OutputArrayId::Lifetime:
      // An element whose life ended in the last step is released at the next:
      // none left, not a negative time.
      perElement(
        floats(out), engine, [&](std::size_t e) { return std::max(engine.lifetimes()[e], 0.0f); });
      break;
    case bp::OutputArrayId::ElementId:
      perElement(static_cast<vtkIdTypeArray*>(out)->GetPointer(0), engine,
        [&](std::size_t e) { return engine.elementIds()[e]; });
      break;
    case bp::OutputArrayId::Layer: // the release centre along the colouring axis
      perElement(floats(out), engine,
        [&](std::size_t e) { return double(centres[3 * e + axis]) + c.frame.offset[axis]; });
      break;
    case bp::OutputArrayId::Radius: // the release centre's distance from the axis
      perElement(floats(out), engine,
        [&](std::size_t e)
        { return std::hypot(centres[3 * e + u] - cu, centres[3 * e + v] - cv); });
      break;
    case bp::OutputArrayId::ElementOrientation:
      perElementTuple(floats(out), engine, engine.poses().data(), 4, 4);
      break;
    case bp::OutputArrayId::ElementSpin:
      perElementTuple(floats(out), engine, engine.spins().data(), 4, 3);
      break;
    case bp::OutputArrayId::SpinVorticityRatio:
      perElementTuple(floats(out), engine, engine.spins().data() + 3, 4, 1);
      break;
    default:
      break;
  }
}

void fillTemplateIndex(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  if (row.id == bp::OutputArrayId::ParticleIndex)
  {
    int* index = static_cast<vtkIntArray*>(out)->GetPointer(0);
    const vtkIdType n = vtkIdType(c.engine.particlesPerElement());
    vtkSMPTools::For(vtkIdType(0), out->GetNumberOfTuples(),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
          index[i] = int(i % n);
      });
  }
}

/// Age: 0 on the elements, each trail pose's age on its points.
void fillTrailAge(const bp::OutputArray&, vtkDataArray* out, const FillContext& c)
{
  float* age = floats(out);
  const std::size_t N = c.engine.particleCount(), n = c.engine.particlesPerElement();
  std::fill_n(age, N, 0.0f);
  for (std::size_t j = 0; j < c.trail.size(); ++j)
  {
    std::fill_n(age + N + j * n, n, c.trail[j].age);
  }
}

/// Fills `out` as its row's source says.
void fillArray(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  switch (row.source)
  {
    case bp::ArraySource::ParticleState:
      fillParticleState(row, out, c);
      break;
    case bp::ArraySource::FieldSample:
      fillFieldSample(row, out, c);
      break;
    case bp::ArraySource::Derived:
      fillDerived(row, out, c);
      break;
    case bp::ArraySource::ElementState:
      fillElementState(row, out, c);
      break;
    case bp::ArraySource::TemplateIndex:
      fillTemplateIndex(row, out, c);
      break;
    case bp::ArraySource::TrailAge:
      fillTrailAge(row, out, c);
      break;
  }
}

/**
 * The values of a trail pose's points: its element's (the pose is drawn
 * coloured as its element is now), but Age (filled) and Normals (of the pose).
 */
void extendToTrail(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  const std::size_t N = c.engine.particleCount(), n = c.engine.particlesPerElement();
  const std::size_t E = c.engine.elementCount();
  if (row.source == bp::ArraySource::TrailAge || c.trail.empty())
  {
    return;
  }
  if (row.id == bp::OutputArrayId::Normals)
  {
    float* normals = floats(out);
    for (std::size_t j = 0; j < c.trail.size(); ++j)
    {
      const TrailPose& t = c.trail[j];
      bp::elementNormals(c.engine.shape(),
        c.engine.trailPositions().data() + 3 * (t.slot * E + t.element) * n,
        normals + 3 * (N + j * n));
    }
    return;
  }
  auto* bytes = static_cast<unsigned char*>(out->GetVoidPointer(0));
  const std::size_t tuple = std::size_t(out->GetDataTypeSize() * out->GetNumberOfComponents());
  for (std::size_t j = 0; j < c.trail.size(); ++j)
  {
    std::memcpy(bytes + (N + j * n) * tuple, bytes + c.trail[j].element * n * tuple, n * tuple);
  }
}
} // namespace

namespace bpvtk
{

void OutputStorage::applyCells(
  vtkPolyData* output, const bp::Engine& engine, std::size_t trailPoses)
{
  const std::size_t E = engine.elementCount();
  // An element placed outside the release window keeps its points but has
  // no cells: it is not drawn.
  std::vector<std::uint8_t> hidden(E);
  const std::vector<std::uint8_t>& flags = engine.resetFlags();
  std::transform(flags.begin(), flags.end(), hidden.begin(),
    [](std::uint8_t f) { return std::uint8_t((f & bp::ReleaseHidden) != 0); });
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

void fillParticleOutput(vtkPolyData* output, const bp::Engine& engine, const bp::VectorField& field,
  const OutputFrame& frame, OutputStorage& storage, const bp::RangeRunner& run)
{
  const std::vector<TrailPose> trail = trailPoses(engine, frame.time);
  setPoints(output, engine, frame, trail, storage, run);
  storage.applyCells(output, engine, trail.size());
  const vtkIdType points =
    vtkIdType(engine.particleCount() + trail.size() * engine.particlesPerElement());
  FillContext context{ engine, field, frame, run, trail, {} };
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    // Age only with trails: without, it would be 0 everywhere.
    const bool trails = !engine.trailTimes().empty();
    if (frame.wants(row) && (row.source != bp::ArraySource::TrailAge || trails))
    {
      arrays.push_back(storage.array(row, points));
      context.arrays[std::size_t(row.id)] = arrays.back();
    }
  }
  vtkPointData* pd = output->GetPointData();
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    if (vtkDataArray* array = context.array(row.id))
    {
      fillArray(row, array, context);
      extendToTrail(row, array, context);
      addToPointData(pd, row, array);
    }
  }
  for (vtkDataArray* array : context.arrays)
  {
    if (array)
    {
      primeRanges(array, run); // every value written
    }
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
