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
/// The automatic spacing and the axes it cuts.
struct AutomaticSpacing
{
  double spacing = 0.0;
  std::array<bool, 3> spread = { false, false, false }; ///< axes with more than one point
};

/// The spacing that cuts the box into about `elements` cells: the volume
/// (area, length) of its spread axes over `elements`, to the power of one
/// over their number. The thinnest axis that this leaves one point across
/// is as flat (one point, at its middle) and the spacing is found again
/// without it, one axis at a time, so a thin slab keeps the target instead
/// of spending it across its thickness, and a box of a few elements keeps
/// its points inside (all three axes of a cube are one point across for one
/// element: the point is the box's centre).
AutomaticSpacing spacingFor(const std::array<double, 3>& extent, std::size_t elements)
{
  AutomaticSpacing result;
  for (int a = 0; a < 3; ++a)
  {
    result.spread[a] = extent[a] > 0.0;
  }
  for (;;)
  {
    double volume = 1.0;
    int axes = 0;
    for (int a = 0; a < 3; ++a)
    {
      volume *= result.spread[a] ? extent[a] : 1.0;
      axes += result.spread[a];
    }
    if (axes == 0)
    {
      return result;
    }
    const double s = std::pow(volume / double(std::max<std::size_t>(elements, 1)), 1.0 / axes);
    result.spacing = s;
    int thinnest = -1;
    for (int a = 0; a < 3; ++a)
    {
      const bool onePoint = std::round(extent[a] / s) <= 1.0;
      if (result.spread[a] && axes > 1 && onePoint &&
        (thinnest < 0 || extent[a] < extent[std::size_t(thinnest)]))
      {
        thinnest = a;
      }
    }
    if (thinnest < 0)
    {
      return result;
    }
    result.spread[std::size_t(thinnest)] = false;
  }
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
  AutomaticSpacing cut;
  if (spacing > 0.0)
  {
    cut.spacing = spacing;
    for (int a = 0; a < 3; ++a)
    {
      cut.spread[a] = extent[a] > 0.0;
    }
  }
  else
  {
    cut = spacingFor(extent, elements);
  }
  ReleaseLattice lattice;
  for (int a = 0; a < 3; ++a)
  {
    if (!(extent[a] > 0.0))
    {
      lattice.origin[a] = emitterMin[a];
      continue;
    }
    // An axis left one point across has it at its middle.
    const double n = cut.spread[a] && cut.spacing > 0.0
      ? std::min(std::max(std::round(extent[a] / cut.spacing), 1.0), double(MaxLatticeCount))
      : 1.0;
    lattice.counts[a] = int(n);
    const double step = extent[a] / n;
    lattice.spacing[a] = float(step);
    lattice.origin[a] = float(double(emitterMin[a]) + 0.5 * step);
  }
  return lattice;
}

} // namespace bp
