// SPDX-License-Identifier: BSD-3-Clause
// Camera matrices and clipping planes for the grid-local draw (GridLocalCoordinates.h).
#include "GridLocalCoordinates.h"

#include "vtkAbstractMapper3D.h"
#include "vtkActor.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>

namespace bpvtk
{

void setGridLocalCamera(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act,
  const std::array<double, 3>& offset, vtkMatrix4x4* toWorld, vtkMatrix4x4* scratch)
{
  if (offset[0] == 0.0 && offset[1] == 0.0 && offset[2] == 0.0)
  {
    return; // grid-local is world: VTK's matrices are the ones
  }
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* norms;
  vtkMatrix4x4* vcdc;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  // VTK's key matrices are transposed (they act on row vectors: the
  // translation is the last row, and Multiply4x4(a, b) applies a first), as
  // its VBO shift and scale matrix is. The products are taken in double: the
  // offset and the camera's distance from the world origin cancel here, and
  // what reaches the shader as float is the field's position relative to
  // the camera.
  toWorld->Identity();
  for (int k = 0; k < 3; ++k)
  {
    toWorld->SetElement(3, k, offset[std::size_t(k)]);
  }
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc;
    vtkMatrix3x3* anorms;
    static_cast<vtkOpenGLActor*>(act)->GetKeyMatrices(mcwc, anorms);
    vtkMatrix4x4::Multiply4x4(toWorld, mcwc, toWorld); // normals: translation-free, as set
  }
  if (program->IsUniformUsed("MCWCMatrix"))
  {
    program->SetUniformMatrix("MCWCMatrix", toWorld);
  }
  vtkMatrix4x4::Multiply4x4(toWorld, wcdc, scratch);
  program->SetUniformMatrix("MCDCMatrix", scratch);
  if (program->IsUniformUsed("MCVCMatrix"))
  {
    vtkMatrix4x4::Multiply4x4(toWorld, wcvc, scratch);
    program->SetUniformMatrix("MCVCMatrix", scratch);
  }
}

void setGridLocalClippingPlanes(vtkShaderProgram* program, vtkAbstractMapper3D* mapper,
  vtkActor* act, const std::array<double, 3>& offset)
{
  const int planes = std::min(mapper->GetNumberOfClippingPlanes(), 6);
  const bool shifted = offset[0] != 0.0 || offset[1] != 0.0 || offset[2] != 0.0;
  if (!shifted || planes <= 0 || !program->IsUniformUsed("numClipPlanes") ||
    !program->IsUniformUsed("clipPlanes"))
  {
    return; // unshifted: the planes VTK set are the ones
  }
  float equations[6][4] = {};
  vtkNew<vtkMatrix4x4> propMatrix;
  act->GetModelToWorldMatrix(propMatrix);
  for (int k = 0; k < planes; ++k)
  {
    double plane[4];
    mapper->GetClippingPlaneInDataCoords(propMatrix, k, plane);
    equations[k][0] = float(plane[0]);
    equations[k][1] = float(plane[1]);
    equations[k][2] = float(plane[2]);
    equations[k][3] =
      float(plane[3] + plane[0] * offset[0] + plane[1] * offset[1] + plane[2] * offset[2]);
  }
  program->SetUniform4fv("clipPlanes", 6, equations);
}

} // namespace bpvtk
