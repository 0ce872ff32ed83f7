// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleSurfaceSeeds.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkBoundParticleSurfaceSeeds);

namespace
{
bool finitePoint(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

/// Whether cell `c` of `mesh` is a surface cell (a polygon or a strip) with a
/// corner that is not finite; then its corners, as a fan of triangles.
bool nonFiniteFan(vtkPolyData* mesh, vtkIdType c, vtkIdList* ids, std::vector<double>& triangles)
{
  const int type = mesh->GetCellType(c);
  if (type != VTK_TRIANGLE && type != VTK_QUAD && type != VTK_POLYGON && type != VTK_TRIANGLE_STRIP)
  {
    return false;
  }
  mesh->GetCellPoints(c, ids);
  bool finite = true;
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    finite = finite && finitePoint(mesh->GetPoint(ids->GetId(k)));
  }
  for (vtkIdType k = 1; !finite && k + 1 < ids->GetNumberOfIds(); ++k)
  {
    for (const vtkIdType corner : { ids->GetId(0), ids->GetId(k), ids->GetId(k + 1) })
    {
      const double* x = mesh->GetPoint(corner);
      triangles.insert(triangles.end(), x, x + 3);
    }
  }
  return !finite;
}

void appendTriangles(vtkDataSet* data, std::vector<double>& triangles)
{
  if (!data || data->GetNumberOfCells() == 0)
  {
    return;
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  surface->Update();
  vtkPolyData* boundary = surface->GetOutput();
  // A cell with a corner that is not finite: the triangle filter may drop
  // it; kept as triangles that are not finite, which the weights count and
  // the tracer says.
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < boundary->GetNumberOfCells(); ++c)
  {
    nonFiniteFan(boundary, c, ids, triangles);
  }
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
  vtkIdType count = 0;
  const vtkIdType* corners = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, corners);)
  {
    double t[9];
    bool finite = count == 3; // the filter leaves only triangles; a guard all the same
    for (int k = 0; finite && k < 3; ++k)
    {
      points->GetPoint(corners[k], t + 3 * k);
      finite = finitePoint(t + 3 * k);
    }
    if (finite)
    {
      triangles.insert(triangles.end(), t, t + 9);
    }
  }
}
} // namespace

void vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(
  vtkDataObject* source, std::vector<double>& triangles)
{
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(source))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      appendTriangles(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()), triangles);
    }
    return;
  }
  appendTriangles(vtkDataSet::SafeDownCast(source), triangles);
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
