// SPDX-License-Identifier: BSD-3-Clause
#include "Surfaces.h"

#include "Triangles.h"

#include <algorithm>
#include <cmath>

namespace bp
{

namespace
{
/// Whether SurfaceCrossings keeps the triangle: finite corners and an area.
bool keptTriangle(const float* corners)
{
  double v[9];
  std::copy(corners, corners + 9, v);
  const triangles::Vec n = triangles::doubleAreaNormal(v);
  const double squared = triangles::dot(n, n);
  return triangles::finite(v) && squared > 0.0 && std::isfinite(squared);
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
    const float* corners = this->Given.corners.data() + 9 * k;
    if (this->Given.interaction[k] == SurfaceInteraction::Outlet && keptTriangle(corners))
    {
      this->OutletCorners.insert(this->OutletCorners.end(), corners, corners + 9);
    }
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
