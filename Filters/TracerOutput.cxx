// SPDX-License-Identifier: BSD-3-Clause
#include "TracerOutput.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <cstring>
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

vtkSmartPointer<vtkCellArray> buildCells(
  const bp::ElementTemplate& shape, std::size_t elements, int& kind)
{
  const std::size_t n = shape.particleCount();
  int cellSize;
  std::vector<std::uint32_t> local;
  if (!shape.triangles.empty())
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
        const vtkIdType offset = e * vtkIdType(n);
        vtkIdType* o = out + e * vtkIdType(local.size());
        for (std::size_t k = 0; k < local.size(); ++k)
          o[k] = offset + local[k];
      }
    });
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(cellSize, connectivity);
  return cells;
}

vtkSmartPointer<vtkDataArray> newArray(const bp::OutputArray& row, vtkIdType tuples)
{
  vtkSmartPointer<vtkDataArray> a;
  switch (row.type)
  {
    case bp::ValueType::IdType:
      a = vtkSmartPointer<vtkIdTypeArray>::New();
      break;
    case bp::ValueType::Int:
      a = vtkSmartPointer<vtkIntArray>::New();
      break;
    case bp::ValueType::Float:
      a = vtkSmartPointer<vtkFloatArray>::New();
      break;
  }
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

/**
 * World positions: grid-local ones plus the grid's offset, in double where
 * float would lose more than 1e-4 of a cell at the field's coordinates.
 */
void setPoints(vtkPolyData* output, const bp::Engine& engine, const bpvtk::OutputFrame& frame)
{
  vtkNew<vtkPoints> points;
  if (frame.reach * std::ldexp(1.0, -23) > 1e-4 * frame.cellLength)
  {
    points->SetDataTypeToDouble();
  }
  const vtkIdType N = vtkIdType(engine.particleCount());
  points->SetNumberOfPoints(N);
  vtkDataArray* coords = points->GetData();
  const float* local = engine.positions().data();
  const double offset[3] = { frame.offset[0], frame.offset[1], frame.offset[2] };
  vtkSMPTools::For(vtkIdType(0), N,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType id = begin; id < end; ++id)
      {
        for (int c = 0; c < 3; ++c)
        {
          coords->SetComponent(id, c, double(local[3 * id + c]) + offset[c]);
        }
      }
    });
  output->SetPoints(points);
}

/// The arrays computed per element (Lifetime, ElementId, Layer, Radius) and
/// per particle from its element (Speed, ParticleIndex), in one pass.
struct ElementArrays
{
  vtkDataArray* arrays[10] = { nullptr };
  vtkDataArray*& operator[](bp::OutputArrayId id) { return this->arrays[std::size_t(id)]; }
};

void fillElementArrays(
  ElementArrays& out, const bp::Engine& engine, const bpvtk::OutputFrame& frame)
{
  using Id = bp::OutputArrayId;
  const std::size_t E = engine.elementCount(), n = engine.particlesPerElement();
  const auto& bounds = frame.domain;
  const int axis = frame.coloringAxis;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double cu = 0.5 * (bounds[2 * u] + bounds[2 * u + 1]);
  const double cv = 0.5 * (bounds[2 * v] + bounds[2 * v + 1]);
  const float* vel = floats(out[Id::Velocity]);
  float* speed = floats(out[Id::Speed]);
  float* lifetime = floats(out[Id::Lifetime]);
  float* layer = floats(out[Id::Layer]);
  float* radius = floats(out[Id::Radius]);
  vtkIdType* elementId = static_cast<vtkIdTypeArray*>(out[Id::ElementId])->GetPointer(0);
  int* particleIndex = static_cast<vtkIntArray*>(out[Id::ParticleIndex])->GetPointer(0);
  vtkSMPTools::For(vtkIdType(0), vtkIdType(E),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const float* c = engine.initialCenters().data() + 3 * e;
        const float lay = float(double(c[axis]) + frame.offset[axis]);
        const float rad = float(std::hypot(c[u] - cu, c[v] - cv));
        const float life = engine.lifetimes()[e];
        for (std::size_t i = 0; i < n; ++i)
        {
          const vtkIdType id = e * vtkIdType(n) + vtkIdType(i);
          const float* w = vel + 3 * id;
          speed[id] = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
          lifetime[id] = life;
          layer[id] = lay;
          radius[id] = rad;
          elementId[id] = vtkIdType(engine.elementIds()[e]);
          particleIndex[id] = int(i);
        }
      }
    });
}
} // namespace

namespace bpvtk
{

void ParticleCells::apply(vtkPolyData* output, const bp::Engine& engine)
{
  const std::size_t E = engine.elementCount();
  if (!this->Cells || this->Elements != E)
  {
    this->Elements = E; // in parallel, the count changes as elements move
    this->Cells = buildCells(engine.shape(), E, this->Kind);
    this->LinkCells = engine.links().empty()
      ? nullptr
      : buildLinkCells(engine.links(), engine.particlesPerElement());
    if (this->LinkCells && this->Kind == 1)
    {
      // Springs drawn as lines: the links join them in the one line array.
      this->Cells->Append(this->LinkCells);
    }
  }
  switch (this->Kind)
  {
    case 0:
      output->SetVerts(this->Cells);
      break;
    case 1:
      output->SetLines(this->Cells);
      break;
    default:
      output->SetPolys(this->Cells);
  }
  if (this->LinkCells && this->Kind != 1)
  {
    output->SetLines(this->LinkCells);
  }
}

void fillParticleOutput(vtkPolyData* output, const bp::Engine& engine, const bp::VectorField& field,
  const OutputFrame& frame, ParticleCells& cells, const bp::RangeRunner& run)
{
  using Id = bp::OutputArrayId;
  setPoints(output, engine, frame);
  cells.apply(output, engine);
  const vtkIdType N = vtkIdType(engine.particleCount());
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  ElementArrays byId;
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    const bool wanted = !row.optional || (row.id == Id::Vorticity && frame.computeVorticity);
    arrays.push_back(wanted ? newArray(row, N) : nullptr);
    byId[row.id] = arrays.back();
  }
  std::memcpy(floats(byId[Id::Normals]), engine.normals().data(), sizeof(float) * 3 * N);
  std::memcpy(floats(byId[Id::Force]), engine.forces().data(), sizeof(float) * N);
  bp::sampleAtPositions(field, frame.time, engine.positions().data(), std::size_t(N),
    floats(byId[Id::Velocity]), byId[Id::Vorticity] ? floats(byId[Id::Vorticity]) : nullptr, run);
  fillElementArrays(byId, engine, frame);
  vtkPointData* pd = output->GetPointData();
  for (std::size_t k = 0; k < arrays.size(); ++k)
  {
    if (arrays[k])
    {
      addToPointData(pd, bp::outputArrays()[k], arrays[k]);
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
