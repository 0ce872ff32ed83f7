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

} // namespace bp
