// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuStateLayout.h
 * @brief The GPU engine's per-element state as a list (ElementTexture) and
 * the kernels' declarations of it, apart from the textures (GpuState.h), so
 * that the shader assembly (ShaderSource) and the passes (GpuPasses) read
 * the list without the state that uses them.
 */
#ifndef BoundParticles_GpuStateLayout_h
#define BoundParticles_GpuStateLayout_h

#include "ParticleLayout.h"

#include <string>

namespace bp
{

/**
 * The GPU engine's per-element state, the one list (as
 * Engine::forEachElementArray is the CPU engine's): one RGBA32F texture pair
 * each, element e at texel (e % W, e / W). GpuState makes, saves and
 * restores every row's pair by it, and the passes' GLSL gets each row's
 * sampler (ElementTextureSamplers) and, in the fused step, its image (the
 * sampler's name + "Out") declared from it (elementStateDeclarations). A
 * new row is a line here and its sampler's name below; the kernels that
 * read and write it are the physics.
 */
enum class ElementTexture
{
  State,        ///< lifetime, generation, reset flag, non-finite flag
  Centers,      ///< the generation's initial centre; w: hidden (placed outside the release window)
  Orientations, ///< rotation as placed, then as fitted: a quaternion
  Poses,        ///< Engine::poses(): a quaternion
  Spins,        ///< Engine::spins(): angular velocity, SpinVorticityRatio
  Count
};
constexpr int ElementTextureCount = int(ElementTexture::Count);
static_assert(ElementTextureCount == GpuElementTextureRows,
  "Core's gpuCheckpointBytes counts the per-element rows (ParticleLayout.h)");

/// Each row's sampler in the kernels' GLSL (Shaders/), in ElementTexture's order.
constexpr const char* ElementTextureSamplers[ElementTextureCount] = { "bpElementState", "bpCenters",
  "bpOrientations", "bpPoses", "bpSpins" };

/// The GLSL declarations of the per-element state: a sampler per row, and
/// with `images` also a write-only image per row, `<sampler>Out` at image
/// unit 1 + row (unit 0: the particle state's, bpParticlesOut).
std::string elementStateDeclarations(bool images);

} // namespace bp

#endif
