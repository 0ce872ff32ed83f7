// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuDrawSamplers.h
 * @brief The display's draw shader's samplers (Shaders/bp_draw_vs_dec.glsl):
 * their uniform names and the texture each reads, the GPU engine's state
 * textures (GpuEngine::drawInputs) and the draw's own tables. No GL and no
 * VTK: the ParaView mapper (Representations/DrawSamplers.h, on VTK's texture
 * units) and the standalone step-plus-draw bench (bench/step_draw.cpp) bind
 * this one list.
 */
#ifndef BoundParticles_GpuDrawSamplers_h
#define BoundParticles_GpuDrawSamplers_h

#include "GpuEngine.h"

#include <array>

namespace bp
{

/// The draw shader's samplers, in the order of their names (drawSamplerName).
enum class DrawSampler
{
  Positions,
  Normals,
  Samples,
  Elements,
  Centers,
  Links, ///< the draw's link table (a super set's links; 0: none)
  Poses,
  Spins,
  TrailPositions, ///< bound per trail pose (0 outside a trail pose's draw)
  TrailElements,  ///< bound per trail pose (0 outside a trail pose's draw)
  Corners,        ///< the draw's corner table (trail normals; 0: none)
  StretchRest,    ///< the template's rest offsets (ElementStretch; 0: none)
  Slips,          ///< heavy particles' slips (none: reads 0)
  Count
};
constexpr int DrawSamplerCount = int(DrawSampler::Count);

/// The sampler's uniform name in Shaders/bp_draw_vs_dec.glsl ("bpPositions", ...).
const char* drawSamplerName(DrawSampler sampler);

/// The textures the draw makes itself, beside the engine's (0: none).
struct DrawTables
{
  unsigned links = 0;
  unsigned corners = 0;
  unsigned stretchRest = 0;
};

/// Each sampler's 2D texture for the element draw, in the order of
/// DrawSampler: the engine's state textures from `inputs`, the draw's tables
/// from `tables`, none (0) for the trail's two (bound per trail pose).
std::array<unsigned, DrawSamplerCount> drawSamplerTextures(
  const GpuEngine::DrawInputs& inputs, const DrawTables& tables);

} // namespace bp

#endif
