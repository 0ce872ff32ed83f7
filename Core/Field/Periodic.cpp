// SPDX-License-Identifier: BSD-3-Clause
#include "Periodic.h"

#include "VectorField.h"

#include <algorithm>
#include <cstddef>

namespace bp
{

double largestFiniteSpeed(const std::vector<float>& velocity)
{
  double fastest = 0.0;
  for (std::size_t k = 0; k + 2 < velocity.size(); k += 3)
  {
    const double s = std::sqrt(double(velocity[k]) * velocity[k] +
      double(velocity[k + 1]) * velocity[k + 1] + double(velocity[k + 2]) * velocity[k + 2]);
    fastest = std::max(fastest, std::isfinite(s) ? s : 0.0);
  }
  return fastest;
}

double periodicSeamDifference(const GridGeometry& grid, const std::vector<float>& velocity, int a)
{
  const std::array<int, 3>& d = grid.dims;
  if (d[a] < 2 || velocity.size() < 3 * grid.pointCount())
  {
    return 0.0;
  }
  // The other two axes span the planes; step along a from the first to the last.
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  const std::size_t stride[3] = { 1, std::size_t(d[0]), std::size_t(d[0]) * d[1] };
  double worst = 0.0;
  for (int j = 0; j < d[b]; ++j)
  {
    for (int k = 0; k < d[c]; ++k)
    {
      const std::size_t first = j * stride[b] + k * stride[c];
      const std::size_t last = first + std::size_t(d[a] - 1) * stride[a];
      for (int m = 0; m < 3; ++m)
      {
        const double diff = std::abs(double(velocity[3 * last + m]) - velocity[3 * first + m]);
        worst = std::max(worst, std::isfinite(diff) ? diff : 0.0);
      }
    }
  }
  return worst;
}

double periodicSeamMismatch(const GridGeometry& grid, const std::vector<float>& velocity, int a)
{
  if (grid.dims[a] < 2 || velocity.size() < 3 * grid.pointCount())
  {
    return 0.0;
  }
  const double fastest = largestFiniteSpeed(velocity);
  return fastest > 0.0 ? periodicSeamDifference(grid, velocity, a) / fastest : 0.0;
}

} // namespace bp
