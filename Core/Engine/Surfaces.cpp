// SPDX-License-Identifier: BSD-3-Clause
#include "Surfaces.h"

#include <algorithm>
#include <cmath>

namespace bp
{

namespace
{
bool finiteTriangle(const float* v)
{
  return std::all_of(v, v + 9, [](float x) { return std::isfinite(x); });
}
} // namespace

SurfaceSet::SurfaceSet(const SurfaceTriangles& triangles)
  : Given(triangles)
  , Crossings(triangles.corners, triangles.surfaces)
{
  const std::size_t count = triangles.corners.size() / 9;
  this->Given.corners.resize(9 * count);
  this->Given.surfaces.resize(count, 0);
  this->Given.interaction.resize(count, SurfaceInteraction::Gate);
  this->Given.cells.resize(count, -1);
  for (std::size_t k = 0; k < count; ++k)
  {
    // As SurfaceCrossings keeps it: finite corners (its area is checked there too).
    this->Outlets = this->Outlets ||
      (this->Given.interaction[k] == SurfaceInteraction::Outlet &&
        finiteTriangle(triangles.corners.data() + 9 * k));
  }
}

bool SurfaceSet::passages(
  const float a[3], const float b[3], std::vector<SurfaceCrossing>& out) const
{
  this->Crossings.allCrossings(a, b, out);
  const auto outlet = std::find_if(out.begin(), out.end(),
    [this](const SurfaceCrossing& c)
    { return this->Given.interaction[c.triangle] == SurfaceInteraction::Outlet; });
  if (outlet == out.end())
  {
    return false;
  }
  out.erase(outlet + 1, out.end());
  return true;
}

} // namespace bp
