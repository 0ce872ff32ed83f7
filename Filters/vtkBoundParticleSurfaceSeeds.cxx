// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleSurfaceSeeds.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <sstream>

vtkStandardNewMacro(vtkBoundParticleSurfaceSeeds);

namespace
{
void appendTriangles(vtkDataSet* data, std::vector<double>& triangles)
{
  if (!data || data->GetNumberOfCells() == 0)
  {
    return;
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  vtkNew<vtkTriangleFilter> cut;
  cut->SetInputConnection(surface->GetOutputPort());
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
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count != 3)
    {
      continue; // the filter leaves only triangles; a guard all the same
    }
    for (int k = 0; k < 3; ++k)
    {
      double x[3];
      points->GetPoint(ids[k], x);
      triangles.insert(triangles.end(), x, x + 3);
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
