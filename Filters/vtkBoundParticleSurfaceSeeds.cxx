// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleSurfaceSeeds.h"

#include "SurfaceRelease.h"
#include "TracerResample.h"

#include "vtkAppendFilter.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkBoundParticleSurfaceSeeds);

namespace
{
/// The cell array that carries, to each boundary triangle, whether the leaf
/// it comes from is a volume whose boundary points inward (1) or not (0).
constexpr const char* InwardArray = "vtkBoundParticleSurfaceSeedsInward";

bool finitePoint(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

/// Whether `data` has cells of three dimensions (a volume).
bool isVolume(vtkDataSet* data)
{
  vtkNew<vtkCellTypes> types;
  data->GetCellTypes(types);
  for (vtkIdType i = 0; i < types->GetNumberOfTypes(); ++i)
  {
    if (vtkCellTypes::GetDimension(types->GetCellType(i)) == 3)
    {
      return true;
    }
  }
  return false;
}

/**
 * The boundary of `data` cut into triangles, appended to `triangles` (9
 * coordinates each, in the surface's orientation; reversed where the
 * InwardArray says 1). A surface cell with a corner that is not finite is
 * left out whole and counted once, as one triangle of NaN corners (the
 * weights count it and the tracer says so).
 */
void triangulate(vtkDataSet* data, std::vector<double>& triangles)
{
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  surface->Update();
  vtkNew<vtkPolyData> boundary;
  boundary->ShallowCopy(surface->GetOutput());
  // Each boundary cell's id, so the triangles cut from a cell with a
  // corner that is not finite are known.
  vtkNew<vtkIdTypeArray> origin;
  origin->SetName("vtkBoundParticleSurfaceSeedsCell");
  origin->SetNumberOfTuples(boundary->GetNumberOfCells());
  std::vector<bool> nonFinite(std::size_t(boundary->GetNumberOfCells()), false);
  vtkNew<vtkIdList> ids;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (vtkIdType c = 0; c < boundary->GetNumberOfCells(); ++c)
  {
    origin->SetValue(c, c);
    const int type = boundary->GetCellType(c);
    if (type != VTK_TRIANGLE && type != VTK_QUAD && type != VTK_POLYGON &&
      type != VTK_TRIANGLE_STRIP)
    {
      continue;
    }
    boundary->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds() && !nonFinite[std::size_t(c)]; ++k)
    {
      nonFinite[std::size_t(c)] = !finitePoint(boundary->GetPoint(ids->GetId(k)));
    }
    if (nonFinite[std::size_t(c)])
    {
      triangles.insert(triangles.end(), 9, nan);
    }
  }
  boundary->GetCellData()->AddArray(origin);
  vtkNew<vtkTriangleFilter> cut;
  cut->SetInputData(boundary);
  cut->PassVertsOff();
  cut->PassLinesOff();
  cut->Update();
  vtkPolyData* mesh = cut->GetOutput();
  vtkCellArray* polys = mesh->GetPolys();
  vtkPoints* points = mesh->GetPoints();
  if (!polys || !points)
  {
    return;
  }
  auto* from =
    vtkIdTypeArray::SafeDownCast(mesh->GetCellData()->GetArray("vtkBoundParticleSurfaceSeedsCell"));
  vtkDataArray* inward = mesh->GetCellData()->GetArray(InwardArray);
  // The triangle filter keeps no vertices or lines: the polygons come first.
  vtkIdType count = 0, cell = 0;
  const vtkIdType* corners = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, corners); ++cell)
  {
    const vtkIdType source = from && cell < from->GetNumberOfTuples() ? from->GetValue(cell) : -1;
    if (count != 3 ||
      (source >= 0 && source < vtkIdType(nonFinite.size()) && nonFinite[std::size_t(source)]))
    {
      continue; // counted above, once for the whole cell
    }
    double t[9];
    bool finite = true;
    for (int k = 0; finite && k < 3; ++k)
    {
      points->GetPoint(corners[k], t + 3 * k);
      finite = finitePoint(t + 3 * k);
    }
    if (inward && cell < inward->GetNumberOfTuples() && inward->GetTuple1(cell) != 0.0)
    {
      std::swap_ranges(t + 3, t + 6, t + 6); // a, c, b: the other way round
    }
    if (finite)
    {
      triangles.insert(triangles.end(), t, t + 9);
    }
    else
    {
      triangles.insert(triangles.end(), 9, nan);
    }
  }
}

/// Whether the volume `data`'s boundary points inward (a left-handed grid,
/// a mirrored mesh): its signed volume, Σ ((c − o) · n) A / 3 over its
/// triangles, below 0.
bool pointsInward(vtkDataSet* data)
{
  if (!isVolume(data))
  {
    return false;
  }
  std::vector<double> triangles;
  triangulate(data, triangles);
  double o[3];
  data->GetCenter(o);
  double volume = 0.0;
  for (std::size_t i = 0; i + 9 <= triangles.size(); i += 9)
  {
    const double* t = triangles.data() + i;
    const std::array<double, 3> n = bp::triangleNormal(t), c = bp::triangleCentroid(t);
    const double a = bp::triangleArea(t);
    if (a > 0.0)
    {
      volume += ((c[0] - o[0]) * n[0] + (c[1] - o[1]) * n[1] + (c[2] - o[2]) * n[2]) * a / 3.0;
    }
  }
  return volume < 0.0;
}

/// `data`, shallow-copied, with the InwardArray on every cell.
vtkSmartPointer<vtkDataSet> marked(vtkDataSet* data)
{
  vtkSmartPointer<vtkDataSet> copy;
  copy.TakeReference(data->NewInstance());
  copy->ShallowCopy(data);
  vtkNew<vtkUnsignedCharArray> inward;
  inward->SetName(InwardArray);
  inward->SetNumberOfTuples(data->GetNumberOfCells());
  inward->FillValue(pointsInward(data) ? 1 : 0);
  copy->GetCellData()->AddArray(inward);
  return copy;
}
} // namespace

void vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(
  vtkDataObject* source, std::vector<double>& triangles)
{
  std::vector<vtkDataSet*> leaves = bpvtk::leafDataSets(source);
  leaves.erase(std::remove_if(leaves.begin(), leaves.end(),
                 [](vtkDataSet* d) { return !d || d->GetNumberOfCells() == 0; }),
    leaves.end());
  if (leaves.size() == 1)
  {
    triangulate(marked(leaves.front()), triangles);
  }
  else if (leaves.size() > 1)
  {
    // The blocks merged, their coincident points made one, so the faces
    // between blocks are inner faces and not part of the boundary.
    vtkNew<vtkAppendFilter> merge;
    merge->MergePointsOn();
    for (vtkDataSet* leaf : leaves)
    {
      merge->AddInputData(marked(leaf));
    }
    merge->Update();
    triangulate(merge->GetOutput(), triangles);
  }
}

std::string vtkBoundParticleSurfaceSeeds::DescribeUnusableParameters()
{
  std::ostringstream say;
  if (this->NumberOfPoints < 1)
  {
    say << "The Surface's Number Of Points " << this->NumberOfPoints
        << " is below 1: it has 1 point.";
  }
  return say.str();
}

void vtkBoundParticleSurfaceSeeds::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPoints: " << this->NumberOfPoints << "\n";
  os << indent << "FlipNormals: " << this->FlipNormals << "\n";
}
