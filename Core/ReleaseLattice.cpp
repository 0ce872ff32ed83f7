// SPDX-License-Identifier: BSD-3-Clause
#include "ReleaseLattice.h"

#include <algorithm>
#include <cmath>

namespace bp
{

std::size_t ReleaseLattice::size() const
{
  return std::size_t(this->counts[0]) * std::size_t(this->counts[1]) *
    std::size_t(this->counts[2]);
}

std::array<float, 3> ReleaseLattice::point(std::size_t id) const
{
  const std::size_t n = this->size();
  std::size_t r = n > 0 ? id % n : 0;
  std::array<float, 3> c;
  for (int a = 0; a < 3; ++a)
  {
    const std::size_t i = r % std::size_t(this->counts[a]);
    r /= std::size_t(this->counts[a]);
    c[a] = this->origin[a] + float(i) * this->spacing[a];
  }
  return c;
}

ReleaseLattice releaseLattice(const std::array<float, 3>& emitterMin,
  const std::array<float, 3>& emitterMax, std::size_t elements, double spacing)
{
  std::array<double, 3> extent;
  double volume = 1.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = double(emitterMax[a]) - double(emitterMin[a]);
    if (extent[a] > 0.0)
    {
      volume *= extent[a];
      ++axes;
    }
  }
  double s = spacing;
  if (!(s > 0.0) && axes > 0)
  {
    s = std::pow(volume / double(std::max<std::size_t>(elements, 1)), 1.0 / axes);
  }
  ReleaseLattice lattice;
  for (int a = 0; a < 3; ++a)
  {
    if (!(extent[a] > 0.0) || !(s > 0.0))
    {
      lattice.origin[a] = emitterMin[a];
      continue;
    }
    const double n = std::min(std::max(std::round(extent[a] / s), 1.0), double(MaxLatticeCount));
    lattice.counts[a] = int(n);
    const double step = extent[a] / n;
    lattice.spacing[a] = float(step);
    lattice.origin[a] = float(double(emitterMin[a]) + 0.5 * step);
  }
  return lattice;
}

} // namespace bp
