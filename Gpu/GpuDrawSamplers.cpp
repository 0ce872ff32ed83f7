// SPDX-License-Identifier: BSD-3-Clause
// The draw shader's samplers and their textures (GpuDrawSamplers.h).
#include "GpuDrawSamplers.h"

namespace bp
{
namespace
{
/// The uniforms' names in Shaders/bp_draw_vs_dec.glsl, in the order of DrawSampler.
const char* const Names[DrawSamplerCount] = { "bpPositions", "bpNormals", "bpSamples", "bpElements",
  "bpCenters", "bpLinks", "bpPoses", "bpSpins", "bpTrailPositions", "bpTrailElements",
  "bpAdjacency", "bpStretchRest", "bpSlips" };
} // namespace

const char* drawSamplerName(DrawSampler sampler)
{
  const int k = int(sampler);
  return k >= 0 && k < DrawSamplerCount ? Names[k] : "";
}

std::array<unsigned, DrawSamplerCount> drawSamplerTextures(
  const GpuEngine::DrawInputs& inputs, const DrawTables& tables)
{
  return { inputs.positions, inputs.normals, inputs.samples, inputs.elements, inputs.centers,
    tables.links, inputs.poses, inputs.spins, 0u, 0u, tables.corners, tables.stretchRest,
    inputs.slips };
}

} // namespace bp
