// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DrawSamplers.h
 * @brief The GPU draw shader's samplers (Shaders/bp_draw_vs_dec.glsl) and
 * the texture units they read during one draw.
 *
 * Every sampler gets a unit of its own from VTK's texture unit manager, also
 * those with nothing to read (bpLinks when nothing is linked): samplers of
 * different types on one unit make a draw fail. The units are handed back
 * after the draw.
 */
#ifndef BoundParticles_DrawSamplers_h
#define BoundParticles_DrawSamplers_h

#include <array>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace bpvtk
{

class DrawSamplers
{
public:
  /// The samplers, in the order of their names in the .cxx.
  enum Sampler
  {
    Positions,
    Normals,
    Samples,
    Elements,
    Centers,
    Links,
    Poses,
    Spins,
    TrailPositions, ///< bound per trail pose (bind)
    TrailElements,  ///< bound per trail pose (bind)
    Corners,
    StretchRest, ///< the template's rest offsets (DrawDeformation.h)
    Slips,       ///< heavy particles' slips (none: reads 0)
    Count
  };
  using Textures = std::array<unsigned, Count>;

  /// Takes a unit for every sampler and binds its 2D texture (0: none) there.
  void bindAll(vtkOpenGLRenderWindow* window, const Textures& textures);
  /// Binds `texture` on `sampler`'s unit (between bindAll and unbindAll).
  void bind(vtkOpenGLRenderWindow* window, Sampler sampler, unsigned texture);
  /// Unbinds every sampler's texture and hands its unit back.
  void unbindAll(vtkOpenGLRenderWindow* window);
  /// Sets each sampler's uniform to its unit (-1 outside a draw).
  void setUniforms(vtkShaderProgram* program) const;

private:
  int Units[Count] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 };
};

} // namespace bpvtk

#endif
