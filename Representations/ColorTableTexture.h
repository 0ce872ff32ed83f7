// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ColorTableTexture.h
 * @brief The display's lookup table sampled into a texture for the draw
 * shader.
 *
 * The GPU draw colours by a scalar it computes per vertex from the engine's
 * textures, so VTK's own scalar colouring (which maps an input array) does
 * not apply: the lookup table's colours and opacities over its range are
 * sampled here into a 256 x 1 RGBA texture, made again only when the table
 * or its range changes.
 */
#ifndef BoundParticles_ColorTableTexture_h
#define BoundParticles_ColorTableTexture_h

#include "vtkNew.h"           // for vtkNew
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>
#include "vtkType.h"          // for vtkMTimeType

class vtkOpenGLRenderWindow;
class vtkScalarsToColors;
class vtkWindow;

namespace bpvtk
{

class ColorTableTexture
{
public:
  /// Texels of the table (the shader's bpColorTableSize).
  static constexpr int Size = 256;

  /// Samples `lut` over its range into the texture if the table, its range
  /// or the texture itself changed since the last time.
  void update(vtkScalarsToColors* lut, vtkOpenGLRenderWindow* window);
  /// The range the texture spans (the lookup table's at the last update).
  const double* range() const { return this->Range; }
  vtkTextureObject* texture() { return this->Texture; }
  void release(vtkWindow* window);

private:
  vtkNew<vtkTextureObject> Texture;
  vtkMTimeType Time = 0;
  double Range[2] = { 0, 1 };
};

} // namespace bpvtk

#endif
