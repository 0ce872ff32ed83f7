// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceCrossings.h"

#include "Triangles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace bp
{
namespace
{
using triangles::cross;
using triangles::dot;
using triangles::sub;
using Vec = triangles::Vec;

/// How far outside a triangle's edges a hit may lie, in barycentric units,
/// and still count: a segment through a shared edge, computed from either
/// triangle, must not fall between them by a rounding.
constexpr double EdgeSlack = 1e-9;

/// Where the segment a + t d, t in (0, 1], meets triangle v (9 doubles);
/// NaN where it does not (Moller-Trumbore, closed on the edges).
double meet(const double* v, const double a[3], const Vec& d)
{
  const Vec e1 = sub(v + 3, v), e2 = sub(v + 6, v);
  const Vec p = cross(d, e2);
  const double det = dot(e1, p);
  if (det == 0.0 || !std::isfinite(det))
  {
    return std::nan("");
  }
  const Vec s = sub(a, v);
  const double u = dot(s, p) / det;
  if (!(u >= -EdgeSlack && u <= 1.0 + EdgeSlack))
  {
    return std::nan("");
  }
  const Vec q = cross(s, e1);
  const double w = dot(d, q) / det;
  if (!(w >= -EdgeSlack && u + w <= 1.0 + EdgeSlack))
  {
    return std::nan("");
  }
  const double t = dot(e2, q) / det;
  return t > 0.0 && t <= 1.0 ? t : std::nan("");
}

/// Whether x lies within `distance` of triangle v's plane (9 doubles), its
/// foot on the plane within the triangle (edges closed).
bool near(const double* v, const double x[3], double distance)
{
  const Vec e1 = sub(v + 3, v), e2 = sub(v + 6, v), n = cross(e1, e2);
  const double area2 = dot(n, n);
  const Vec s = sub(x, v);
  const double height = dot(s, n) / std::sqrt(area2);
  if (!(std::abs(height) <= distance))
  {
    return false;
  }
  // The foot's barycentric coordinates: (s x e2).n and (e1 x s).n over |n|^2.
  const double u = dot(cross(s, e2), n) / area2;
  const double w = dot(cross(e1, s), n) / area2;
  return u >= -EdgeSlack && w >= -EdgeSlack && u + w <= 1.0 + EdgeSlack;
}

bool finite3(const float p[3])
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
} // namespace

SurfaceCrossings::SurfaceCrossings(
  const std::vector<float>& corners, const std::vector<std::int32_t>& surfaces)
{
  const std::size_t given = corners.size() / 9;
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
  for (std::size_t k = 0; k < given; ++k)
  {
    double v[9];
    std::copy(
      corners.begin() + std::ptrdiff_t(9 * k), corners.begin() + std::ptrdiff_t(9 * k + 9), v);
    const Vec n = triangles::doubleAreaNormal(v);
    if (!triangles::finite(v) || !(dot(n, n) > 0.0) || !std::isfinite(dot(n, n)))
    {
      ++this->Dropped;
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      for (int a = 0; a < 3; ++a)
      {
        const double x = v[3 * c + a];
        const bool first = this->Surface.empty() && c == 0;
        lo[a] = first ? x : std::min(lo[a], x);
        hi[a] = first ? x : std::max(hi[a], x);
      }
    }
    this->Corners.insert(this->Corners.end(), v, v + 9);
    this->Surface.push_back(surfaces.size() == given ? surfaces[k] : 0);
    this->Original.push_back(std::uint32_t(k));
  }
  const std::size_t T = this->Surface.size();
  // About sqrt(T) buckets along the longest side (one triangle a bucket
  // column of a flat surface), at most 256, and at most 4 T + 64 in all.
  const double longest = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  double size =
    longest > 0.0 ? longest / std::min(256.0, std::max(1.0, std::ceil(std::sqrt(double(T))))) : 1.0;
  for (;;)
  {
    double total = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      this->Buckets[a] = std::max(1, int(std::ceil((hi[a] - lo[a]) / size)));
      total *= this->Buckets[a];
    }
    if (total <= 4.0 * double(T) + 64.0)
    {
      break;
    }
    size *= std::cbrt(total / (4.0 * double(T) + 64.0)) * 1.01;
  }
  for (int a = 0; a < 3; ++a)
  {
    this->Lower[a] = lo[a];
    this->Upper[a] = hi[a];
    this->BucketSize[a] = size;
  }
  this->fillBuckets();
}

void SurfaceCrossings::fillBuckets()
{
  const std::size_t T = this->Surface.size();
  // Each triangle in every bucket its box touches (a counting sort).
  const std::size_t B = std::size_t(this->Buckets[0]) * this->Buckets[1] * this->Buckets[2];
  std::vector<std::uint32_t> count(B + 1, 0);
  // A long thin triangle (a fan's sliver) touches many buckets: past
  // MaxBucketsPerTriangle it is kept apart (Large) and tested by every step
  // instead, so the buckets' entries stay at most that many a triangle.
  auto range = [this](std::size_t k, int f[3], int l[3])
  {
    const double* v = &this->Corners[9 * k];
    double blo[3], bhi[3];
    for (int a = 0; a < 3; ++a)
    {
      blo[a] = std::min({ v[a], v[3 + a], v[6 + a] });
      bhi[a] = std::max({ v[a], v[3 + a], v[6 + a] });
    }
    this->bucketRange(blo, bhi, f, l);
    return double(l[0] - f[0] + 1) * double(l[1] - f[1] + 1) * double(l[2] - f[2] + 1);
  };
  std::vector<bool> large(T, false);
  for (std::size_t k = 0; k < T; ++k)
  {
    int f[3], l[3];
    large[k] = range(k, f, l) > double(MaxBucketsPerTriangle);
    if (large[k])
    {
      this->Large.push_back(std::uint32_t(k));
    }
  }
  auto visit = [&](auto&& act)
  {
    for (std::size_t k = 0; k < T; ++k)
    {
      int f[3], l[3];
      if (large[k])
      {
        continue;
      }
      range(k, f, l);
      for (int z = f[2]; z <= l[2]; ++z)
        for (int y = f[1]; y <= l[1]; ++y)
          for (int x = f[0]; x <= l[0]; ++x)
            act((std::size_t(z) * this->Buckets[1] + y) * this->Buckets[0] + x, k);
    }
  };
  visit([&](std::size_t b, std::size_t) { ++count[b + 1]; });
  for (std::size_t b = 0; b < B; ++b)
  {
    count[b + 1] += count[b];
  }
  this->Start = count;
  this->Members.resize(count[B]);
  visit([&](std::size_t b, std::size_t k) { this->Members[count[b]++] = std::uint32_t(k); });
}

void SurfaceCrossings::bucketRange(
  const double lo[3], const double hi[3], int first[3], int last[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    const double f = std::floor((lo[a] - this->Lower[a]) / this->BucketSize[a]);
    const double l = std::floor((hi[a] - this->Lower[a]) / this->BucketSize[a]);
    const double top = this->Buckets[a] - 1;
    // The grid's last bucket holds the upper bound itself (closed).
    first[a] = int(std::clamp(f, 0.0, top));
    last[a] = int(std::clamp(l, 0.0, top));
    if (hi[a] < this->Lower[a] || lo[a] > this->Upper[a])
    {
      last[a] = first[a] - 1; // the box misses the triangles' bounds: no bucket
    }
  }
}

template <typename Visit>
bool SurfaceCrossings::meetAlong(const float a[3], const float b[3], Visit&& visit) const
{
  if (this->Surface.empty() || !finite3(a) || !finite3(b))
  {
    return false;
  }
  const double da[3] = { a[0], a[1], a[2] };
  const Vec d = { double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2] };
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = std::min<double>(a[k], b[k]);
    hi[k] = std::max<double>(a[k], b[k]);
  }
  int f[3], l[3];
  this->bucketRange(lo, hi, f, l);
  for (int z = f[2]; z <= l[2]; ++z)
    for (int y = f[1]; y <= l[1]; ++y)
      for (int x = f[0]; x <= l[0]; ++x)
      {
        const std::size_t bucket = (std::size_t(z) * this->Buckets[1] + y) * this->Buckets[0] + x;
        for (std::uint32_t m = this->Start[bucket]; m < this->Start[bucket + 1]; ++m)
        {
          const std::uint32_t k = this->Members[m];
          const double t = meet(&this->Corners[9 * std::size_t(k)], da, d);
          if (std::isfinite(t))
          {
            visit(k, t);
          }
        }
      }
  for (const std::uint32_t k : this->Large)
  {
    const double t = meet(&this->Corners[9 * std::size_t(k)], da, d);
    if (std::isfinite(t))
    {
      visit(k, t);
    }
  }
  return true;
}

SurfaceCrossing SurfaceCrossings::crossingAt(
  const float a[3], const float b[3], std::uint32_t k, double t) const
{
  const double* v = &this->Corners[9 * std::size_t(k)];
  const Vec n = cross(sub(v + 3, v), sub(v + 6, v));
  const double length = std::sqrt(dot(n, n));
  const Vec d = { double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2] };
  SurfaceCrossing crossing;
  crossing.t = t;
  for (int c = 0; c < 3; ++c)
  {
    crossing.point[std::size_t(c)] = float(double(a[c]) + t * d[std::size_t(c)]);
    crossing.normal[std::size_t(c)] = float(n[std::size_t(c)] / length);
  }
  crossing.direction = dot(d, n) > 0.0 ? 1 : -1;
  crossing.surface = this->Surface[k];
  crossing.triangle = this->Original[k];
  return crossing;
}

bool SurfaceCrossings::lies(const float p[3], double distance) const
{
  if (this->Surface.empty() || !finite3(p))
  {
    return false;
  }
  const double x[3] = { p[0], p[1], p[2] };
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = x[k] - distance;
    hi[k] = x[k] + distance;
  }
  int f[3], l[3];
  this->bucketRange(lo, hi, f, l);
  for (int z = f[2]; z <= l[2]; ++z)
    for (int y = f[1]; y <= l[1]; ++y)
      for (int w = f[0]; w <= l[0]; ++w)
      {
        const std::size_t bucket = (std::size_t(z) * this->Buckets[1] + y) * this->Buckets[0] + w;
        for (std::uint32_t m = this->Start[bucket]; m < this->Start[bucket + 1]; ++m)
        {
          if (near(&this->Corners[9 * std::size_t(this->Members[m])], x, distance))
          {
            return true;
          }
        }
      }
  return std::any_of(this->Large.begin(), this->Large.end(),
    [&](std::uint32_t k) { return near(&this->Corners[9 * std::size_t(k)], x, distance); });
}

bool SurfaceCrossings::firstCrossing(
  const float a[3], const float b[3], SurfaceCrossing& crossing) const
{
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t bestTriangle = 0;
  this->meetAlong(a, b,
    [&](std::uint32_t k, double t)
    {
      if (t < best || (t == best && k < bestTriangle))
      {
        best = t;
        bestTriangle = k;
      }
    });
  if (!std::isfinite(best))
  {
    return false;
  }
  crossing = this->crossingAt(a, b, bestTriangle, best);
  return true;
}

void SurfaceCrossings::allCrossings(
  const float a[3], const float b[3], std::vector<SurfaceCrossing>& crossings) const
{
  crossings.clear();
  // (t, kept triangle) of every triangle met; a triangle in several buckets is met in each.
  std::vector<std::pair<double, std::uint32_t>> met;
  this->meetAlong(a, b, [&](std::uint32_t k, double t) { met.emplace_back(t, k); });
  std::sort(met.begin(), met.end());
  met.erase(std::unique(met.begin(), met.end(),
              [](const auto& x, const auto& y) { return x.second == y.second; }),
    met.end());
  for (const auto& [t, k] : met)
  {
    SurfaceCrossing c = this->crossingAt(a, b, k, t);
    // Through an edge or a corner that triangles of one surface share, the
    // same way: one crossing, the first (the smallest t, then triangle, as
    // firstCrossing takes).
    const auto same = std::find_if(crossings.begin(), crossings.end(),
      [&](const SurfaceCrossing& x)
      {
        return x.surface == c.surface && x.direction == c.direction &&
          std::abs(x.t - c.t) <= SharedEdgeT;
      });
    if (same == crossings.end())
    {
      crossings.push_back(c);
    }
  }
}

} // namespace bp
