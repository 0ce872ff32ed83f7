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

/// `given` filled in to one entry a triangle.
SurfaceTriangles filledIn(SurfaceTriangles given)
{
  const std::size_t count = given.corners.size() / 9;
  given.corners.resize(9 * count);
  given.surfaces.resize(count, 0);
  given.interaction.resize(count, SurfaceInteraction::Gate);
  given.cells.resize(count, -1);
  return given;
}

/// The corners and surfaces of the Wall triangles of `given`, with each
/// one's index as given in `index`.
SurfaceCrossings wallsOf(const SurfaceTriangles& given, std::vector<std::uint32_t>& index)
{
  std::vector<float> corners;
  std::vector<std::int32_t> surfaces;
  for (std::size_t k = 0; k < given.interaction.size(); ++k)
  {
    if (given.interaction[k] == SurfaceInteraction::Wall)
    {
      corners.insert(corners.end(), given.corners.begin() + std::ptrdiff_t(9 * k),
        given.corners.begin() + std::ptrdiff_t(9 * k + 9));
      surfaces.push_back(given.surfaces[k]);
      index.push_back(std::uint32_t(k));
    }
  }
  return SurfaceCrossings(corners, surfaces);
}
} // namespace

float surfaceWallOffset(const Domain& box)
{
  float extent = 0.0f;
  for (int a = 0; a < 3; ++a)
  {
    extent = box.degenerate[a] ? extent : std::max(extent, box.upper[a] - box.lower[a]);
  }
  return std::isfinite(extent) && extent > 0.0f ? 1e-5f * extent : 1e-5f;
}

SurfaceSet::SurfaceSet(const SurfaceTriangles& triangles)
  : Given(filledIn(triangles))
  , Passing(Given.corners, Given.surfaces)
  , Walls(wallsOf(Given, WallIndex))
{
  for (std::size_t k = 0; k < this->Given.cells.size(); ++k)
  {
    const float* corners = this->Given.corners.data() + 9 * k;
    if (this->Given.interaction[k] == SurfaceInteraction::Outlet && keptTriangle(corners))
    {
      this->OutletCorners.insert(this->OutletCorners.end(), corners, corners + 9);
    }
    if (this->Given.interaction[k] == SurfaceInteraction::Wall && keptTriangle(corners))
    {
      this->WallCorners.insert(this->WallCorners.end(), corners, corners + 9);
    }
  }
}

void SurfaceSet::crossingsAcrossSeam(const float a[3], const float b[3], const Domain* box,
  const float* seam, std::vector<SurfaceCrossing>& out) const
{
  this->Passing.allCrossings(a, b, out);
  if (!box || !seam || (seam[0] == 0.0f && seam[1] == 0.0f && seam[2] == 0.0f))
  {
    return;
  }
  // Within the box (closed) along each axis the seam moves the step.
  const auto within = [box, seam](const SurfaceCrossing& c)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      if (seam[k] != 0.0f && !(c.point[k] >= box->lower[k] && c.point[k] <= box->upper[k]))
      {
        return false;
      }
    }
    return true;
  };
  out.erase(
    std::remove_if(out.begin(), out.end(), [&](const SurfaceCrossing& c) { return !within(c); }),
    out.end());
  // The step translated by each part of the seam (the whole of it, and
  // where it moves along two or three axes, each one alone and each pair:
  // the piece of a step through a corner between its two seams).
  thread_local std::vector<SurfaceCrossing> beyond;
  for (unsigned part = 1; part < 8; ++part)
  {
    float s[3] = { 0, 0, 0 };
    bool picked = true;
    for (std::size_t k = 0; k < 3; ++k)
    {
      const bool in = (part >> k) & 1u;
      picked = picked && (!in || seam[k] != 0.0f);
      s[k] = in ? seam[k] : 0.0f;
    }
    if (!picked)
    {
      continue;
    }
    const float shiftedA[3] = { a[0] + s[0], a[1] + s[1], a[2] + s[2] };
    const float shiftedB[3] = { b[0] + s[0], b[1] + s[1], b[2] + s[2] };
    this->Passing.allCrossings(shiftedA, shiftedB, beyond);
    for (const SurfaceCrossing& c : beyond)
    {
      // A triangle met within the box by two of them is met on a seam itself
      // (its points a period apart): one passage, the first found.
      const bool met = std::any_of(out.begin(), out.end(),
        [&](const SurfaceCrossing& x) { return x.triangle == c.triangle; });
      if (within(c) && !met)
      {
        out.push_back(c);
      }
    }
  }
  std::stable_sort(out.begin(), out.end(),
    [](const SurfaceCrossing& x, const SurfaceCrossing& y) { return x.t < y.t; });
}

bool SurfaceSet::passages(const float a[3], const float b[3], bool wallsEnd,
  std::vector<SurfaceCrossing>& out, const Domain* box, const float* seam) const
{
  this->crossingsAcrossSeam(a, b, box, seam, out);
  // A particle-level Wall (Slip, Bounce) is no passage of the centre.
  out.erase(std::remove_if(out.begin(), out.end(),
              [&](const SurfaceCrossing& c) {
                return !wallsEnd && this->Given.interaction[c.triangle] == SurfaceInteraction::Wall;
              }),
    out.end());
  const auto ends = std::find_if(out.begin(), out.end(),
    [this](const SurfaceCrossing& c)
    { return this->Given.interaction[c.triangle] != SurfaceInteraction::Gate; });
  if (ends == out.end())
  {
    return false;
  }
  out.erase(ends + 1, out.end());
  return true;
}

bool SurfaceSet::wallCrossing(const float a[3], const float b[3], SurfaceCrossing& crossing) const
{
  if (!this->Walls.firstCrossing(a, b, crossing))
  {
    return false;
  }
  crossing.triangle = this->WallIndex[crossing.triangle];
  return true;
}

} // namespace bp
