// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParticleLayout.h
 * @brief The GPU engine's texture layout and its size check, here in Core/
 * (not Gpu/) so the filter can check a system against a GPU's texture limit
 * before it asks for one.
 */
#ifndef BoundParticles_ParticleLayout_h
#define BoundParticles_ParticleLayout_h

#include "ElementTemplate.h"
#include "EngineState.h"

#include <cstddef>
#include <string>

namespace bp
{

/// The most texels a row of the GPU engine's template lists (springs,
/// triangles; GpuTemplate) holds: a longer list takes further rows.
constexpr long long ListTextureWidth = 4096;

/**
 * The GPU engine's texture layout (thesis §3.5.1, generalised): elements in a
 * near-square W x H grid, one such block per template particle index, blocks
 * bx per row, so the particle texture is near square. Here, not in Gpu/, so
 * the filter can check a system against a GPU's texture limit before it asks
 * for one.
 */
struct ParticleLayout
{
  long long elementGrid[2] = { 0, 0 }; ///< W, H
  long long blocksPerRow = 0;          ///< bx
  long long width = 0, height = 0;     ///< the particle texture
  static ParticleLayout of(std::size_t elements, std::size_t particlesPerElement);
};

/**
 * Empty when every texture of the GPU engine for `elements` elements of
 * `shape` fits a GPU whose textures are at most `maxSize` texels wide and
 * high: the particle state (ParticleLayout), and the template's tables (rest
 * positions and particle info n wide, the Gauss-Seidel spring table 2n wide,
 * the spring and triangle lists ListTextureWidth wide). Otherwise which one does not.
 */
std::string gpuTextureError(const ElementTemplate& shape, std::size_t elements, long long maxSize);

/// The most Outlet triangles the GPU engine takes (SurfaceSet::outletCorners):
/// its test kernel tests each element's step against every one (engine
/// specification 2.10), and keeps them in one texture (7).
constexpr std::size_t GpuMaxOutletTriangles = 4096;

/// Empty when the GPU engine takes `outletTriangles` Outlet triangles (at
/// most GpuMaxOutletTriangles), otherwise why not.
std::string gpuOutletError(std::size_t outletTriangles);

/// The most Wall triangles the GPU engine takes (SurfaceSet::wallCorners):
/// it tests each particle's step, and each element's with Release Again or
/// Terminate, against every one (engine specification 2.10).
constexpr std::size_t GpuMaxWallTriangles = 4096;

/// Empty when the GPU engine takes `wallTriangles` Wall triangles (at most
/// GpuMaxWallTriangles), otherwise why not.
std::string gpuWallError(std::size_t wallTriangles);

/// The GPU engine's per-element state textures (Gpu/GpuStateLayout.h's
/// ElementTexture rows; a static_assert there keeps the two equal).
constexpr int GpuElementTextureRows = 5;

/**
 * The bytes of one checkpoint of the GPU engine (GpuEngine::keepCheckpoint):
 * RGBA32F copies of the particle texture, the slips (the particle texture's
 * size with inertia, one texel without), every per-element row, and with a
 * motion trail every slot's particle and element texture; the textures'
 * padding included. `inertial`: bp::carriesInertia.
 */
double gpuCheckpointBytes(
  std::size_t elements, std::size_t particlesPerElement, int trailLength, bool inertial);

/// The largest generation the GPU engine holds exactly: its element state
/// keeps the generation in a float (GpuStateLayout.h's ElementTexture::State).
constexpr std::uint32_t GpuMaxGeneration = 1u << 24;

/**
 * What keeps `state`, which checkEngineState found whole for its engine, from
 * loading into the GPU engine of `elements` elements (GpuEngine::loadState):
 * not every element of the system (the GPU engine holds them all, ids 0 to
 * elements - 1), a generation, or a trail pose's, above GpuMaxGeneration,
 * an element whose Along Flow turn is pending (AlignPending: the GPU engine
 * has no such flag). Empty when it can.
 */
std::string gpuStateRefusal(const EngineState& state, std::size_t elements);

} // namespace bp

#endif
