// SPDX-License-Identifier: BSD-3-Clause
#include "ReleaseLattice.h"

#include <algorithm>
#include <cmath>

namespace bp
{

std::size_t ReleaseLattice::size() const
{
  return std::size_t(this->counts[0]) * std::size_t(this->counts[1]) * std::size_t(this->counts[2]);
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

namespace
{
/// The spacing that cuts the box into about `elements` cells: the volume
/// (area, length) of its spread axes over `elements`, to the power of one
/// over their number. An axis thinner than that (one point across) is as
/// flat, and the spacing is found again without it, so a thin slab keeps
/// the target instead of spending it across its thickness.
double spacingFor(const std::array<double, 3>& extent, std::size_t elements)
{
  std::array<bool, 3> spread;
  for (int a = 0; a < 3; ++a)
  {
    spread[a] = extent[a] > 0.0;
  }
  double s = 0.0;
  for (bool again = true; again;)
  {
    double volume = 1.0;
    int axes = 0;
    for (int a = 0; a < 3; ++a)
    {
      volume *= spread[a] ? extent[a] : 1.0;
      axes += spread[a];
    }
    if (axes == 0)
    {
      return 0.0;
    }
    s = std::pow(volume / double(std::max<std::size_t>(elements, 1)), 1.0 / axes);
    again = false;
    for (int a = 0; a < 3; ++a)
    {
      if (spread[a] && axes > 1 && std::round(extent[a] / s) <= 1.0)
      {
        spread[a] = false;
        again = true;
      }
    }
  }
  return s;
}
} // namespace

ReleaseLattice releaseLattice(const std::array<float, 3>& emitterMin,
  const std::array<float, 3>& emitterMax, std::size_t elements, double spacing)
{
  std::array<double, 3> extent;
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = double(emitterMax[a]) - double(emitterMin[a]);
  }
  const double s = spacing > 0.0 ? spacing : spacingFor(extent, elements);
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
