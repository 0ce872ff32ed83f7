// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLKeptCellsMapper.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"

vtkStandardNewMacro(vtkOpenGLKeptCellsMapper);

void vtkOpenGLKeptCellsMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->CellsState.Clear(); // the index buffers are gone with the context
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLKeptCellsMapper::BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* poly)
{
  // What the superclass's own check would hold without the polydata's time.
  vtkStateStorage state;
  vtkCellArray* prims[4] = { poly->GetVerts(), poly->GetLines(), poly->GetPolys(),
    poly->GetStrips() };
  for (vtkCellArray* cells : prims)
  {
    state.Append(cells, "cells");
    state.Append(cells->GetNumberOfCells() ? cells->GetMTime() : 0, "cells mtime");
  }
  vtkProperty* property = actor->GetProperty();
  state.Append(property->GetRepresentation(), "representation");
  state.Append(property->GetEdgeVisibility(), "edge visibility");
  vtkDataArray* edgeFlags = poly->GetPointData()->GetAttribute(vtkDataSetAttributes::EDGEFLAG);
  state.Append(edgeFlags ? edgeFlags->GetMTime() : 0, "edge flags mtime");
  if (state != this->CellsState)
  {
    this->CellsState = state;
    this->Superclass::BuildIBO(renderer, actor, poly);
  }
}

void vtkOpenGLKeptCellsMapper::ComputeBounds()
{
  vtkPolyData* input = this->GetInput();
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  if (!points || points->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return;
  }
  for (int c = 0; c < 3; ++c)
  {
    points->GetData()->GetRange(this->Bounds + 2 * c, c); // cached while unmodified
  }
}
