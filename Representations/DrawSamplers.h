// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DrawSamplers.h
 * @brief The GPU draw shader's samplers (Shaders/bp_draw_vs_dec.glsl) on
 * the texture units they read during one draw; which sampler reads which
 * texture is bp::DrawSampler's list (Gpu/GpuDrawSamplers.h), shared with the
 * standalone step-plus-draw bench.
 *
 * Every sampler gets a unit of its own from VTK's texture unit manager, also
 * those with nothing to read (bpLinks when nothing is linked): samplers of
 * different types on one unit make a draw fail. The units are handed back
 * after the draw.
 */
#ifndef BoundParticles_DrawSamplers_h
#define BoundParticles_DrawSamplers_h

#include "GpuDrawSamplers.h"

#include <array>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace bpvtk
{

class DrawSamplers
{
public:
  using Sampler = bp::DrawSampler;
  using Textures = std::array<unsigned, bp::DrawSamplerCount>;

  DrawSamplers() { this->Units.fill(-1); }

  /// Takes a unit for every sampler and binds its 2D texture (0: none) there.
  void bindAll(vtkOpenGLRenderWindow* window, const Textures& textures);
  /// Binds `texture` on `sampler`'s unit (between bindAll and unbindAll).
  void bind(vtkOpenGLRenderWindow* window, Sampler sampler, unsigned texture);
  /// Unbinds every sampler's texture and hands its unit back.
  void unbindAll(vtkOpenGLRenderWindow* window);
  /// Sets each sampler's uniform to its unit (-1 outside a draw).
  void setUniforms(vtkShaderProgram* program) const;

private:
  std::array<int, bp::DrawSamplerCount> Units; ///< -1 outside a draw
};

} // namespace bpvtk

#endif
