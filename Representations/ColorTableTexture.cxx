// SPDX-License-Identifier: BSD-3-Clause
// The lookup table as a texture for the GPU draw (ColorTableTexture.h).
#include "ColorTableTexture.h"

#include "vtkDoubleArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

namespace bpvtk
{

void ColorTableTexture::update(vtkScalarsToColors* lut, vtkOpenGLRenderWindow* window)
{
  const double* range = lut->GetRange();
  if (this->Texture->GetHandle() && lut->GetMTime() <= this->Time && range[0] == this->Range[0] &&
    range[1] == this->Range[1])
  {
    return;
  }
  vtkNew<vtkDoubleArray> ramp;
  ramp->SetNumberOfValues(Size);
  for (int k = 0; k < Size; ++k)
  {
    ramp->SetValue(k, range[0] + (range[1] - range[0]) * k / double(Size - 1));
  }
  vtkUnsignedCharArray* rgba = lut->MapScalars(ramp, VTK_COLOR_MODE_MAP_SCALARS, -1);
  this->Texture->SetContext(window);
  this->Texture->Create2DFromRaw(Size, 1, 4, VTK_UNSIGNED_CHAR, rgba->GetVoidPointer(0));
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  rgba->Delete();
  this->Time = lut->GetMTime();
  this->Range[0] = range[0];
  this->Range[1] = range[1];
}

void ColorTableTexture::release(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
}

} // namespace bpvtk
