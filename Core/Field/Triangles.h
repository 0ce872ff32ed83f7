// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Triangles.h
 * @brief The small vector helpers triangles are computed with, a triangle
 * being 9 doubles (corners a, b, c): shared by the surface crossings
 * (SurfaceCrossings.h: gates, outlets, walls) and the surface releases
 * (Release/SurfaceRelease.h: inlets).
 */
#ifndef BoundParticles_Triangles_h
#define BoundParticles_Triangles_h

#include <algorithm>
#include <array>
#include <cmath>

namespace bp
{
namespace triangles
{
using Vec = std::array<double, 3>;

/// a − b.
inline Vec sub(const double* a, const double* b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

inline Vec cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Whether every coordinate of triangle `t` is finite.
inline bool finite(const double t[9])
{
  return std::all_of(t, t + 9, [](double x) { return std::isfinite(x); });
}

/// (b − a) × (c − a): the normal of `t`, twice its area long; zero where a
/// corner is not finite.
inline Vec doubleAreaNormal(const double t[9])
{
  return finite(t) ? cross(sub(t + 3, t), sub(t + 6, t)) : Vec{ 0.0, 0.0, 0.0 };
}
} // namespace triangles
} // namespace bp

#endif
