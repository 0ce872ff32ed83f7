// SPDX-License-Identifier: BSD-3-Clause
// The display's element draw without VTK, for the step-plus-draw bench
// (step_draw.cpp): the draw shader's own pieces (Shaders/bp_draw_vs_dec.glsl,
// bp_draw_vs_impl.glsl, bp_draw_fs_dec.glsl, bp_draw_fs_impl.glsl, embedded
// as bpShaderDrawVSDec and so on) under a minimal main of each stage, in
// place of VTK's polydata shaders that the ParaView mapper splices them into
// (Representations/DrawShaders.h): the vertex shader runs the fetch from the
// engine's state textures (vertex texture fetch), clips hidden elements and
// projects by one view-projection matrix; the fragment shader colours by the
// lookup table as the display does and lights with a headlight. The engine's
// textures are bound by the mapper's own list (bp::drawSamplerTextures,
// Gpu/GpuDrawSamplers.h). One instance per element, one vertex per template
// particle, the template's triangles from an index buffer, as the mapper
// draws (glDrawElementsInstanced), into an offscreen framebuffer: RGBA8
// colour and a 24-bit depth.
#ifndef BoundParticles_bench_element_draw_h
#define BoundParticles_bench_element_draw_h

#include "ElementTemplate.h"
#include "GpuEngine.h"

#include <array>
#include <cstddef>
#include <string>

namespace bench
{

class ElementDraw
{
public:
  /// Compiles the program, uploads the template's triangles and a colour
  /// table, makes the framebuffer; the context must be current. Empty on
  /// success, otherwise why not (a compile log).
  std::string create(const bp::ElementTemplate& shape, int width, int height);
  /// Looks from `eye` at `center` (y up, a 30-degree view angle, as
  /// ParaView's camera), in the engine's coordinates.
  void setCamera(const std::array<float, 3>& eye, const std::array<float, 3>& center);
  /// Clears the framebuffer and draws the engine's elements into it,
  /// coloured by Force over [0, forceMax]; leaves the default framebuffer,
  /// no program and no vertex array bound.
  void draw(const bp::GpuEngine::DrawInputs& inputs, float forceMax = 1.0f);
  /// Reads the framebuffer back: how many pixels differ from the clear colour.
  std::size_t drawnPixels() const;
  /// Deletes the GL objects; the context must be current.
  void release();

private:
  /// The uniforms every frame may change: their locations, looked up once.
  struct FrameLocations
  {
    int viewProjection = -1;
    int normalMatrix = -1;
    int elementGrid = -1;
    int blocksPerRow = -1;
    int trailHalfPeriods = -1;
    int scalarRange = -1;
  };
  /// Sets what no frame changes and keeps FrameLocations (after linking).
  void setConstantUniforms();

  FrameLocations Locations;
  unsigned Program = 0;
  unsigned VertexArray = 0;
  unsigned Indices = 0;
  int IndexCount = 0;
  unsigned ColorTable = 0;
  unsigned Framebuffer = 0;
  unsigned Color = 0;
  unsigned Depth = 0;
  int Width = 0;
  int Height = 0;
  std::array<float, 16> ViewProjection{};
  std::array<float, 9> NormalMatrix{};
};

} // namespace bench

#endif
