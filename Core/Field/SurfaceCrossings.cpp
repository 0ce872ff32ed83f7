// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceCrossings.h"

#include "Triangles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
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

/// At most the corners of a triangle clipped to two slabs (one more a side).
constexpr int MaxClipped = 8;

/// The part of convex polygon p (n corners) on the side of x[a] = bound
/// where sign (x[a] - bound) >= 0, into q; its corner count.
int clipSide(const Vec* p, int n, int a, double bound, double sign, Vec* q)
{
  int m = 0;
  for (int i = 0; i < n; ++i)
  {
    const Vec& c = p[i];
    const Vec& d = p[(i + 1) % n];
    const double dc = sign * (c[std::size_t(a)] - bound), dd = sign * (d[std::size_t(a)] - bound);
    if (dc >= 0.0)
    {
      q[m++] = c;
    }
    if ((dc >= 0.0) != (dd >= 0.0))
    {
      const double t = dc / (dc - dd);
      Vec x = { c[0] + t * (d[0] - c[0]), c[1] + t * (d[1] - c[1]), c[2] + t * (d[2] - c[2]) };
      x[std::size_t(a)] = bound;
      q[m++] = x;
    }
  }
  return m;
}

/// The part of convex polygon p (n corners) with lo <= x[a] <= hi, into q
/// (MaxClipped corners); its corner count.
int clipToSlab(const Vec* p, int n, int a, double lo, double hi, Vec* q)
{
  Vec above[MaxClipped];
  return clipSide(above, clipSide(p, n, a, lo, 1.0, above), a, hi, -1.0, q);
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
  this->sizeGrid(lo, hi);
  this->fillBuckets();
}

void SurfaceCrossings::sizeGrid(const double lo[3], const double hi[3])
{
  const std::size_t T = this->Surface.size();
  double extent[3];
  for (int a = 0; a < 3; ++a)
  {
    this->Lower[a] = lo[a];
    this->Upper[a] = hi[a];
    extent[a] = hi[a] - lo[a];
  }
  auto total = [&extent](const double s[3])
  {
    double n = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      n *= std::max(1.0, std::ceil(extent[a] / s[a]));
    }
    return n;
  };
  // Cubes: about sqrt(T) buckets along the longest side (one triangle a
  // bucket column of a flat surface), at most 256, and at most 4 T + 64 in all.
  const double longest = std::max({ extent[0], extent[1], extent[2] });
  double size =
    longest > 0.0 ? longest / std::min(256.0, std::max(1.0, std::ceil(std::sqrt(double(T))))) : 1.0;
  for (;;)
  {
    const double cube[3] = { size, size, size };
    const double n = total(cube);
    if (n <= 4.0 * double(T) + 64.0)
    {
      break;
    }
    size *= std::cbrt(n / (4.0 * double(T) + 64.0)) * 1.01;
  }
  // Along an axis the triangles span far (long slivers: a pipe cut along its
  // axis), a bucket is a quarter of their median extent long at least, and
  // the other axes are cut finer, to as many buckets as the cubes in all.
  double median[3] = { 0, 0, 0 };
  std::vector<double> spans(T);
  for (int a = 0; a < 3 && T > 0; ++a)
  {
    for (std::size_t k = 0; k < T; ++k)
    {
      const double* v = &this->Corners[9 * k];
      spans[k] = std::max({ v[a], v[3 + a], v[6 + a] }) - std::min({ v[a], v[3 + a], v[6 + a] });
    }
    std::nth_element(spans.begin(), spans.begin() + std::ptrdiff_t(T / 2), spans.end());
    median[a] = spans[T / 2];
  }
  auto sizes = [&](double s, double out[3])
  {
    for (int a = 0; a < 3; ++a)
    {
      out[a] = std::max({ s, median[a] / 4.0, extent[a] / 256.0 });
    }
  };
  double chosen[3] = { size, size, size };
  if (std::max({ median[0], median[1], median[2] }) / 4.0 > size)
  {
    const double cubes = total(chosen);
    double fine = size / 1024.0, coarse = size; // total(sizes(coarse)) <= cubes
    for (int i = 0; i < 40; ++i)
    {
      const double middle = std::sqrt(fine * coarse);
      double s[3];
      sizes(middle, s);
      (total(s) <= cubes ? coarse : fine) = middle;
    }
    sizes(coarse, chosen);
  }
  for (int a = 0; a < 3; ++a)
  {
    this->BucketSize[a] = chosen[a];
    this->Buckets[a] = int(std::max(1.0, std::ceil(extent[a] / chosen[a])));
  }
}

template <typename Act>
std::size_t SurfaceCrossings::touchedBuckets(std::size_t k, std::size_t cap, Act&& act) const
{
  const double* v = &this->Corners[9 * k];
  double lo[3], hi[3], margin[3], scale = 0.0, span = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::min({ v[a], v[3 + a], v[6 + a] });
    hi[a] = std::max({ v[a], v[3 + a], v[6 + a] });
    span = std::max(span, hi[a] - lo[a]);
    scale = std::max({ scale, std::abs(this->Lower[a]), std::abs(this->Upper[a]) });
  }
  // A hair wider than the buckets and the triangle: more than the crossings'
  // EdgeSlack and the roundings, so no crossing a step's box finds is lost.
  for (int a = 0; a < 3; ++a)
  {
    margin[a] = 1e-6 * (this->BucketSize[a] + span) + 1e-12 * scale;
    lo[a] -= margin[a];
    hi[a] += margin[a];
  }
  int f[3], l[3];
  this->bucketRange(lo, hi, f, l);
  // The bucket range [first, last] along axis a of the polygon p's span (wider by the margin).
  auto cells = [&](int a, const Vec* p, int n, int& first, int& last)
  {
    double pl = p[0][std::size_t(a)], ph = pl;
    for (int i = 1; i < n; ++i)
    {
      pl = std::min(pl, p[i][std::size_t(a)]);
      ph = std::max(ph, p[i][std::size_t(a)]);
    }
    first =
      std::max(f[a], int(std::floor((pl - margin[a] - this->Lower[a]) / this->BucketSize[a])));
    last = std::min(l[a], int(std::floor((ph + margin[a] - this->Lower[a]) / this->BucketSize[a])));
  };
  // The slab of buckets i along axis a, wider by the margin (the outer ones unbounded).
  auto slab = [&](int a, int i, const Vec* p, int n, Vec* q)
  {
    const double inf = std::numeric_limits<double>::infinity();
    const double s = this->BucketSize[a], o = this->Lower[a];
    return clipToSlab(p, n, a, i == 0 ? -inf : o + i * s - margin[a],
      i == this->Buckets[a] - 1 ? inf : o + (i + 1) * s + margin[a], q);
  };
  const Vec triangle[3] = { { v[0], v[1], v[2] }, { v[3], v[4], v[5] }, { v[6], v[7], v[8] } };
  std::size_t count = 0;
  for (int z = f[2]; z <= l[2]; ++z)
  {
    Vec inSlab[MaxClipped], inRow[MaxClipped];
    const int n = slab(2, z, triangle, 3, inSlab);
    int fy = 0, ly = -1;
    if (n > 0)
    {
      cells(1, inSlab, n, fy, ly);
    }
    for (int y = fy; y <= ly; ++y)
    {
      const int m = slab(1, y, inSlab, n, inRow);
      int fx = 0, lx = -1;
      if (m > 0)
      {
        cells(0, inRow, m, fx, lx);
      }
      for (int x = fx; x <= lx; ++x)
      {
        if (++count > cap)
        {
          return count;
        }
        act((std::size_t(z) * this->Buckets[1] + y) * this->Buckets[0] + x);
      }
    }
  }
  return count;
}

void SurfaceCrossings::fillBuckets()
{
  const std::size_t T = this->Surface.size();
  const std::size_t B = std::size_t(this->Buckets[0]) * this->Buckets[1] * this->Buckets[2];
  // Each triangle in every bucket it touches (a counting sort), within a
  // budget of entries linear in the triangles and the buckets: the triangles
  // that touch the fewest buckets first; the rest (a fan's long slivers) are
  // kept apart (Large) and tested by every step instead.
  std::vector<std::uint32_t> touches(T);
  for (std::size_t k = 0; k < T; ++k)
  {
    touches[k] = std::uint32_t(this->touchedBuckets(k, MaxBucketsPerTriangle, [](std::size_t) {}));
  }
  std::vector<std::uint32_t> order(T);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
    [&touches](std::uint32_t x, std::uint32_t y) { return touches[x] < touches[y]; });
  std::vector<bool> apart(T, false);
  const std::size_t budget = EntriesPerTriangle * T + B;
  std::size_t spent = 0;
  for (std::size_t i = 0; i < T; ++i)
  {
    const std::size_t n = touches[order[i]];
    if (n > MaxBucketsPerTriangle || spent + n > budget)
    {
      std::for_each(order.begin() + std::ptrdiff_t(i), order.end(),
        [&apart](std::uint32_t k) { apart[k] = true; });
      break;
    }
    spent += n;
  }
  std::vector<std::uint32_t> count(B + 1, 0);
  for (std::size_t k = 0; k < T; ++k)
  {
    if (apart[k])
    {
      this->Large.push_back(std::uint32_t(k));
    }
    else
    {
      this->touchedBuckets(k, MaxBucketsPerTriangle, [&](std::size_t b) { ++count[b + 1]; });
    }
  }
  for (std::size_t b = 0; b < B; ++b)
  {
    count[b + 1] += count[b];
  }
  this->Start = count;
  this->Members.resize(count[B]);
  for (std::size_t k = 0; k < T; ++k)
  {
    if (!apart[k])
    {
      this->touchedBuckets(k, MaxBucketsPerTriangle,
        [&](std::size_t b) { this->Members[count[b]++] = std::uint32_t(k); });
    }
  }
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
