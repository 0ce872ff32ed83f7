// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's texture layout and whether a system fits it (ParticleLayout.h).
#include "ParticleLayout.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{

std::string gpuTextureError(const ElementTemplate& shape, std::size_t elements, long long maxSize)
{
  std::ostringstream err;
  const std::size_t n = shape.particleCount();
  const ParticleLayout layout = ParticleLayout::of(elements, n);
  if (layout.width > maxSize || layout.height > maxSize)
  {
    err << elements << " elements of " << n << " particles need a " << layout.width << " x "
        << layout.height << " state texture, beyond this GPU's GL_MAX_TEXTURE_SIZE of " << maxSize;
    return err.str();
  }
  const long long tableWidth = 2 * (long long)n;
  const long long listRows =
    (4 * (long long)shape.springs.size() + ListTextureWidth - 1) / ListTextureWidth;
  const long long triangleRows =
    (3 * (long long)shape.triangles.size() + ListTextureWidth - 1) / ListTextureWidth;
  if (tableWidth > maxSize || listRows > maxSize || triangleRows > maxSize)
  {
    err << "the element template's " << n << " particles, " << shape.springs.size()
        << " springs and " << shape.triangles.size() << " triangles need template tables of up to "
        << std::max({ tableWidth, listRows, triangleRows })
        << " texels along one side, beyond this GPU's GL_MAX_TEXTURE_SIZE of " << maxSize
        << "; the GPU engine takes templates of at most " << maxSize / 2 << " particles";
    return err.str();
  }
  return std::string();
}

std::string gpuOutletError(std::size_t outletTriangles)
{
  if (outletTriangles <= GpuMaxOutletTriangles)
  {
    return std::string();
  }
  return "the Surfaces hold " + std::to_string(outletTriangles) +
    " Outlet triangles; the GPU engine tests each element's step against every one and takes "
    "at most " +
    std::to_string(GpuMaxOutletTriangles);
}

std::string gpuWallError(std::size_t wallTriangles)
{
  if (wallTriangles <= GpuMaxWallTriangles)
  {
    return std::string();
  }
  return "the Surfaces hold " + std::to_string(wallTriangles) +
    " Wall triangles; the GPU engine tests each particle's step against every one and takes "
    "at most " +
    std::to_string(GpuMaxWallTriangles);
}

ParticleLayout ParticleLayout::of(std::size_t elements, std::size_t particlesPerElement)
{
  ParticleLayout l;
  l.elementGrid[0] = std::max<long long>(1, (long long)std::ceil(std::sqrt(double(elements))));
  l.elementGrid[1] = (long long)((elements + l.elementGrid[0] - 1) / l.elementGrid[0]);
  const double n = double(particlesPerElement);
  l.blocksPerRow = (long long)std::ceil(std::sqrt(n * l.elementGrid[1] / l.elementGrid[0]));
  l.blocksPerRow = std::max<long long>(1, std::min<long long>(l.blocksPerRow, (long long)n));
  l.width = l.blocksPerRow * l.elementGrid[0];
  l.height = (((long long)n + l.blocksPerRow - 1) / l.blocksPerRow) * l.elementGrid[1];
  return l;
}

double gpuCheckpointBytes(
  std::size_t elements, std::size_t particlesPerElement, int trailLength, bool inertial)
{
  const ParticleLayout layout = ParticleLayout::of(elements, particlesPerElement);
  const double particleTexels = double(layout.width) * double(layout.height);
  const double elementTexels = double(layout.elementGrid[0]) * double(layout.elementGrid[1]);
  const double slots = double(std::max(trailLength, 0));
  const double texels = particleTexels + (inertial ? particleTexels : 1.0) +
    GpuElementTextureRows * elementTexels + slots * (particleTexels + elementTexels);
  return 16.0 * texels; // RGBA32F
}

std::string gpuStateRefusal(const EngineState& state, std::size_t elements)
{
  const std::size_t E = state.elementCount();
  if (E != elements)
  {
    return "the GPU engine resumes a whole state, all " + std::to_string(elements) +
      " elements; this one holds " + std::to_string(E);
  }
  // Each array's first word in a record, by name.
  std::size_t generations = 0, flags = 0, trail = 0, trailSlots = 0, offset = 0;
  bool found[2] = { false, false };
  for (const StateArray& array : state.layout)
  {
    if (array.name == "Generations")
    {
      generations = offset;
      found[0] = true;
    }
    else if (array.name == "ResetFlags")
    {
      flags = offset;
      found[1] = true;
    }
    else if (array.name == "TrailGenerations")
    {
      trail = offset;
      trailSlots = array.components;
    }
    offset += array.components;
  }
  if (!found[0] || !found[1])
  {
    return "the state holds no Generations or ResetFlags";
  }
  for (std::size_t e = 0; e < E; ++e)
  {
    const std::uint32_t* record = state.records.data() + e * state.recordWords;
    std::uint32_t highest = record[generations];
    for (std::size_t s = 0; s < trailSlots; ++s)
    {
      const std::uint32_t g = record[trail + s];
      highest = g == NoTrailPose ? highest : std::max(highest, g);
    }
    if (highest > GpuMaxGeneration)
    {
      return "element " + std::to_string(record[0]) + " is in its generation " +
        std::to_string(highest) + ", beyond the " + std::to_string(GpuMaxGeneration) +
        " the GPU engine holds exactly (a float); resume it with Engine CPU";
    }
    if (record[flags] & AlignPending)
    {
      return "element " + std::to_string(record[0]) +
        " waits for its Along Flow turn (a state saved inside a distributed step), which the GPU "
        "engine does not hold";
    }
  }
  return std::string();
}

} // namespace bp
