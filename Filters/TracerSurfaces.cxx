// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, the Surfaces input (input 3): its gates and
// outlets and walls as the engine takes them (bp::SurfaceSet, Core/Engine/Surfaces.h;
// engine specification 2.10), cut into triangles in engine coordinates,
// each with its interaction, block and cell. See
// vtkBoundParticleTracerInternals.h.
#include "vtkBoundParticleTracerInternals.h"

#include "Surfaces.h"
#include "TracerResample.h"
#include "VectorField.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace
{
/// What the Surfaces' cells do, and what was left out, as it is gathered.
struct Gathered
{
  bp::SurfaceTriangles triangles;
  std::set<double> unknownValues; ///< values of the array that name no interaction (not NaN)
  bool unknownNaN = false;        ///< whether NaN is one of them (a std::set cannot hold it)
  std::set<std::pair<std::int32_t, vtkIdType>> unknownCells; ///< (leaf, cell) of such values
  vtkIdType nonFinitePoints = 0; ///< points that are not finite (their cells are left out)
  vtkIdType inPlane = 0;         ///< triangles in a 2D field's plane, which no step crosses
  std::vector<int> leavesWithoutArray;
  std::vector<int> leavesNotNumeric;     ///< blocks whose array is not numeric (a string array)
  std::string notNumeric;                ///< the first such array's class
  std::vector<int> leavesWithComponents; ///< blocks whose array has several components
  int components = 1;                    ///< the first such array's components
  vtkIdType lines = 0; ///< lines given where only a 2D field takes them
};

/// One triangle (world corners a, b, c) into `g`, in engine coordinates.
void addTriangle(Gathered& g, const double* a, const double* b, const double* c,
  const std::array<double, 3>& offset, std::int32_t leaf, std::int32_t cell,
  bp::SurfaceInteraction kind)
{
  for (const double* x : { a, b, c })
  {
    for (int k = 0; k < 3; ++k)
    {
      g.triangles.corners.push_back(float(x[k] - offset[std::size_t(k)]));
    }
  }
  g.triangles.surfaces.push_back(leaf);
  g.triangles.cells.push_back(cell);
  g.triangles.interaction.push_back(kind);
}

/// The interaction of `leaf`'s cell `cell`: the array's value where one is
/// given, else `every`; false for a value that names none.
bool interactionOf(vtkDataArray* values, std::int32_t leaf, vtkIdType cell,
  bp::SurfaceInteraction every, bp::SurfaceInteraction& kind, Gathered& g)
{
  if (!values || cell < 0 || cell >= values->GetNumberOfTuples())
  {
    kind = every;
    return true;
  }
  const double v = values->GetComponent(cell, 0);
  if (v == 0.0 || v == 1.0 || v == 2.0)
  {
    kind = bp::SurfaceInteraction(int(v));
    return true;
  }
  if (g.unknownValues.size() + (g.unknownNaN ? 1 : 0) < 4)
  {
    if (std::isnan(v))
    {
      g.unknownNaN = true;
    }
    else
    {
      g.unknownValues.insert(v);
    }
  }
  g.unknownCells.emplace(leaf, cell);
  return false;
}

/// `leaf`'s surface into `g`: its polygons cut into triangles; in a field
/// flat along axis `flat` (or -1), its lines made rectangles across the
/// field's plane `plane` (world), one unit each side of it.
void gatherLeaf(vtkDataSet* leaf, std::int32_t index, const std::string& arrayName,
  bp::SurfaceInteraction every, int flat, double plane, const std::array<double, 3>& offset,
  Gathered& g)
{
  vtkDataArray* values = nullptr;
  if (!arrayName.empty())
  {
    values = leaf->GetCellData()->GetArray(arrayName.c_str());
    if (!values)
    {
      // A string array is there, but no number says what a cell does.
      vtkAbstractArray* other = leaf->GetCellData()->GetAbstractArray(arrayName.c_str());
      (other ? g.leavesNotNumeric : g.leavesWithoutArray).push_back(index);
      g.notNumeric = other && g.notNumeric.empty() ? other->GetClassName() : g.notNumeric;
    }
    else if (values->GetNumberOfComponents() != 1)
    {
      g.components =
        g.leavesWithComponents.empty() ? values->GetNumberOfComponents() : g.components;
      g.leavesWithComponents.push_back(index);
    }
  }
  for (vtkIdType k = 0; k < leaf->GetNumberOfPoints(); ++k)
  {
    // The triangle filter drops a cell with such a point without a word.
    const double* x = leaf->GetPoint(k);
    g.nonFinitePoints += std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) ? 0 : 1;
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(leaf);
  surface->PassThroughCellIdsOn(); // vtkOriginalCellIds: the leaf's cell of each
  vtkNew<vtkTriangleFilter> cut;
  cut->SetInputConnection(surface->GetOutputPort());
  cut->PassVertsOff();
  cut->Update();
  vtkPolyData* mesh = cut->GetOutput();
  vtkPoints* points = mesh->GetPoints();
  auto* original =
    vtkIdTypeArray::SafeDownCast(mesh->GetCellData()->GetArray("vtkOriginalCellIds"));
  if (!points)
  {
    return;
  }
  // The triangle filter keeps the lines (split into segments) first, then the triangles.
  vtkIdType cellIndex = 0;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* lines = mesh->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(count, ids); ++cellIndex)
  {
    const vtkIdType cell = original ? original->GetValue(cellIndex) : cellIndex;
    bp::SurfaceInteraction kind;
    if (count != 2 || !interactionOf(values, index, cell, every, kind, g))
    {
      continue;
    }
    if (flat < 0)
    {
      ++g.lines;
      continue;
    }
    double p[4][3];
    points->GetPoint(ids[0], p[0]);
    points->GetPoint(ids[1], p[1]);
    std::copy(p[1], p[1] + 3, p[2]);
    std::copy(p[0], p[0] + 3, p[3]);
    p[0][flat] = p[1][flat] = plane - 1.0;
    p[2][flat] = p[3][flat] = plane + 1.0;
    addTriangle(g, p[0], p[1], p[2], offset, index, std::int32_t(cell), kind);
    addTriangle(g, p[0], p[2], p[3], offset, index, std::int32_t(cell), kind);
  }
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids); ++cellIndex)
  {
    const vtkIdType cell = original ? original->GetValue(cellIndex) : cellIndex;
    bp::SurfaceInteraction kind;
    if (count != 3 || !interactionOf(values, index, cell, every, kind, g))
    {
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids[k], p[k]);
    }
    if (flat >= 0)
    {
      const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
      const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
      const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0] };
      const double along = std::abs(n[flat]),
                   size = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      g.inPlane += along > 0.999 * size && size > 0.0 ? 1 : 0;
    }
    addTriangle(g, p[0], p[1], p[2], offset, index, std::int32_t(cell), kind);
  }
}
/// Whether any triangle with finite corners (9 floats each) overlaps `box`.
bool reachesBox(const std::vector<float>& corners, const bp::Domain& box)
{
  for (std::size_t k = 0; k + 9 <= corners.size(); k += 9)
  {
    bool overlaps = true;
    for (int a = 0; a < 3 && overlaps; ++a)
    {
      const float lo = std::min({ corners[k + a], corners[k + 3 + a], corners[k + 6 + a] });
      const float hi = std::max({ corners[k + a], corners[k + 3 + a], corners[k + 6 + a] });
      overlaps = lo <= box.upper[a] && hi >= box.lower[a];
    }
    if (overlaps)
    {
      return true;
    }
  }
  return false;
}

/// What of the Surfaces `g` holds is left out or acts nowhere (empty: all
/// of it acts); `flat` the 2D field's flat axis or -1, `box` the whole
/// field's (engine coordinates).
std::string leftOut(const Gathered& g, const bp::SurfaceSet& set, const std::string& arrayName,
  int flat, const bp::Domain& box)
{
  std::ostringstream say;
  if (!g.unknownCells.empty())
  {
    say << g.unknownCells.size() << " cells of the Surfaces have a value of '" << arrayName
        << "' that names no interaction (0 Gate, 1 Outlet, 2 Wall; such as";
    for (double v : g.unknownValues)
    {
      say << " " << v;
    }
    say << (g.unknownNaN ? " NaN" : "") << "): they are left out. ";
  }
  if (!g.leavesWithoutArray.empty())
  {
    say << g.leavesWithoutArray.size() << " block(s) of the Surfaces (the first: block "
        << g.leavesWithoutArray.front() << ") have no cell array '" << arrayName
        << "': their cells take Surface Interaction. ";
  }
  if (!g.leavesNotNumeric.empty())
  {
    say << g.leavesNotNumeric.size() << " block(s) of the Surfaces (the first: block "
        << g.leavesNotNumeric.front() << ") have a cell array '" << arrayName
        << "' that is not numeric (a " << g.notNumeric
        << "; 0 Gate, 1 Outlet, 2 Wall): their cells take Surface Interaction. ";
  }
  if (!g.leavesWithComponents.empty())
  {
    say << g.leavesWithComponents.size() << " block(s) of the Surfaces (the first: block "
        << g.leavesWithComponents.front() << ") have a cell array '" << arrayName << "' of "
        << g.components << " components: its first component is taken. ";
  }
  if (g.lines > 0)
  {
    say << "The Surfaces' " << g.lines
        << " lines are left out: lines act only in a 2D field (across its plane); in a 3D "
           "field a surface needs polygons. ";
  }
  if (g.inPlane > 0)
  {
    say << g.inPlane
        << " triangles of the Surfaces lie in this 2D field's plane, where no step "
           "crosses them: they act nowhere (a surface across a 2D field is a line: "
           "a Line source, a contour). ";
  }
  if (g.nonFinitePoints > 0)
  {
    say << g.nonFinitePoints
        << " points of the Surfaces are not finite: the cells that use "
           "them are left out. ";
  }
  if (set.droppedTriangles() > 0)
  {
    say << "Of the Surfaces' " << g.triangles.cells.size() << " triangles, "
        << set.droppedTriangles()
        << " have a corner that is not finite or no area: they are "
           "left out. ";
  }
  if (set.triangleCount() == 0 && !g.unknownCells.empty())
  {
    say << "No cell of the Surfaces is left to act on: no element passes a gate, an outlet or "
           "a wall.";
  }
  else if (set.triangleCount() == 0)
  {
    say << "The Surfaces input has no surface to act on (no polygons"
        << (flat < 0 ? " or volume with finite points" : " or lines with finite points")
        << "): no element passes a gate, an outlet or a wall.";
  }
  else if (!reachesBox(g.triangles.corners, box))
  {
    say << "No triangle of the Surfaces reaches into the field's bounds: no element passes a "
           "gate, an outlet or a wall.";
  }
  return say.str();
}

/// Where Walls act on the particles (Boundary Stick, Slip or Bounce): how
/// many Wall triangles come closer than one cell (the grid's mean spacing) to a
/// periodic side of `box`, said as a warning (empty: none). A particle's
/// step is tested before its element's periodic move, not across the seam
/// (engine specification 2.10), so it can pass such a wall.
std::string wallsNearSeam(const bp::SurfaceTriangles& t, bp::Boundary boundary,
  const bp::GridGeometry& grid, const bp::Domain& box)
{
  if (!bp::isWall(boundary))
  {
    return std::string();
  }
  std::size_t near = 0;
  int first = -1;
  for (std::size_t k = 0; k < t.interaction.size() && 9 * k + 9 <= t.corners.size(); ++k)
  {
    const float* c = t.corners.data() + 9 * k;
    for (int a = 0; a < 3 && t.interaction[k] == bp::SurfaceInteraction::Wall; ++a)
    {
      if (!box.periodic[a] || box.degenerate[a])
      {
        continue;
      }
      const double lo = std::min({ c[a], c[3 + a], c[6 + a] });
      const double hi = std::max({ c[a], c[3 + a], c[6 + a] });
      const double cell = grid.spacing[std::size_t(a)];
      const double lower = box.lower[std::size_t(a)], upper = box.upper[std::size_t(a)];
      if ((lo < lower + cell && hi > lower - cell) || (lo < upper + cell && hi > upper - cell))
      {
        ++near;
        first = first < 0 ? a : first;
        break;
      }
    }
  }
  if (near == 0)
  {
    return std::string();
  }
  const char axis = "xyz"[first];
  std::ostringstream say;
  say << near << " Wall triangles of the Surfaces lie closer than one cell to a periodic side (the "
      << "first along " << axis << "): with Boundary " << bp::enumName(boundary)
      << " a particle's step is tested before its element moves across the seam, so a particle "
         "that crosses the seam can pass a wall just past it. Keep walls farther from a periodic "
         "side than a step and an element's size (gates, outlets and walls that end elements "
         "are passed across it). ";
  return say.str();
}

} // namespace

void vtkBoundParticleTracerInternals::gatherSurfaces(const Config& config,
  vtkInformationVector** inputVector, const bp::VectorField& field, bp::Parameters& p)
{
  p.surfaces = nullptr;
  if (!config.surfaces)
  {
    return;
  }
  // The whole field's box (every process alike): a 2D field's flat axis.
  const bp::Domain& whole = this->Layout.distributed() ? this->Layout.Domain : field.domain();
  int flat = -1;
  for (int a = 0; a < 3; ++a)
  {
    flat = whole.degenerate[a] && flat < 0 ? a : flat;
  }
  const std::array<double, 3>& offset = this->Held.offset;
  const double plane = flat < 0 ? 0.0 : double(whole.lower[flat]) + offset[std::size_t(flat)];
  Gathered g;
  const std::vector<vtkDataSet*> leaves =
    bpvtk::leafDataSets(vtkDataObject::GetData(inputVector[3], 0));
  for (std::size_t b = 0; b < leaves.size(); ++b)
  {
    if (leaves[b] && leaves[b]->GetNumberOfCells() > 0)
    {
      gatherLeaf(leaves[b], std::int32_t(b), config.surfaceInteractionArray,
        config.surfaceInteraction, flat, plane, offset, g);
    }
  }
  auto set = std::make_shared<const bp::SurfaceSet>(g.triangles);
  const std::string said = leftOut(g, *set, config.surfaceInteractionArray, flat, whole) +
    wallsNearSeam(g.triangles, p.boundary, field.grid(), whole);
  if (!said.empty() && this->Said.first(bpvtk::Topic::Surfaces, said))
  {
    vtkWarningWithObjectMacro(this->Owner, << said);
  }
  if (set->triangleCount() == 0)
  {
    return;
  }
  p.surfaces = set;
}
