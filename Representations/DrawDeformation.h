// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DrawDeformation.h
 * @brief What the draw shader needs to colour by ElementStretch and
 * ElementFTLE (Shaders/bp_draw_vs_dec.glsl, bpStretchOf and bpFtleOf): the
 * template's part of the fit, made once per configuration by the CPU's own
 * bp::StretchFit, and the lifetime draw's settings, for the age.
 *
 * The fit's template side does not change while the engine steps: the rest
 * offsets about their mean (a float texture, a texel per template particle)
 * and Aqq^+ (a uniform matrix) are uploaded once; the shader fetches the
 * element's particles and makes the rest of the fit per vertex, only when
 * the display colours by one of the two arrays.
 */
#ifndef BoundParticles_DrawDeformation_h
#define BoundParticles_DrawDeformation_h

#include "vtkNew.h"           // for vtkNew
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>

#include <cstdint>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

namespace bp
{
struct ElementTemplate;
struct Parameters;
}

namespace bpvtk
{

/**
 * @class DeformationTable
 * @brief The template's side of the stretch fit and the lifetime draw's
 * settings, for the draw shader.
 */
class DeformationTable
{
public:
  DeformationTable();
  ~DeformationTable();
  DeformationTable(const DeformationTable&) = delete;
  DeformationTable& operator=(const DeformationTable&) = delete;

  /// The fit of `shape` at `p`'s element size, and `p`'s lifetime draw.
  void set(const bp::ElementTemplate& shape, const bp::Parameters& p);

  /// Uploads the rest offsets if they are not on the GPU yet. Where they do
  /// not fit a texture of `maxSize` texels a side (a template of more than
  /// maxSize^2 particles), the colouring reads (1, 1).
  void upload(vtkOpenGLRenderWindow* window, int maxSize);
  /// The uploaded texture of rest offsets; 0 when there is none.
  unsigned handle() const;
  /// Sets the shader's uniforms; the program must be bound.
  void setUniforms(vtkShaderProgram* program) const;
  void release(vtkWindow* window);

private:
  std::vector<float> Rest; ///< 4 floats a template particle: rest - mean, 0
  float Inverse[9] = {};   ///< Aqq^+, row-major (symmetric)
  int Span = 0;
  int Width = 0; ///< texels a row of the uploaded texture; 0: none
  bool Uploaded = false;
  std::uint32_t Seed = 0;
  float LifetimeMin = 0.0f;
  float LifetimeMax = 0.0f;
  float FtleMinimumAge = 0.0f; ///< bp::Parameters::ftleMinimumAge
  bool Linked = false;
  bool Lattice = false;
  vtkNew<vtkTextureObject> Texture;
};

} // namespace bpvtk

#endif
