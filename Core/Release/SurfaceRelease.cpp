// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceRelease.h"

#include "CounterHash.h"
#include "Triangles.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{

namespace
{
using triangles::doubleAreaNormal;

double length(const std::array<double, 3>& v)
{
  return std::sqrt(triangles::dot(v, v));
}
} // namespace

double triangleArea(const double t[9])
{
  const double a = 0.5 * length(doubleAreaNormal(t));
  return std::isfinite(a) ? a : 0.0;
}

std::array<double, 3> triangleNormal(const double t[9])
{
  const std::array<double, 3> m = doubleAreaNormal(t);
  const double l = length(m);
  if (!(l > 0.0) || !std::isfinite(l))
  {
    return { 0.0, 0.0, 0.0 };
  }
  return { m[0] / l, m[1] / l, m[2] / l };
}

std::array<double, 3> triangleCentroid(const double t[9])
{
  return { (t[0] + t[3] + t[6]) / 3.0, (t[1] + t[4] + t[7]) / 3.0, (t[2] + t[5] + t[8]) / 3.0 };
}

double fluxWeight(const double t[9], const double u[3], bool flip)
{
  if (!(std::isfinite(u[0]) && std::isfinite(u[1]) && std::isfinite(u[2])))
  {
    return 0.0;
  }
  const std::array<double, 3> n = triangleNormal(t);
  const double un = (flip ? -1.0 : 1.0) * (u[0] * n[0] + u[1] * n[1] + u[2] * n[2]);
  const double w = std::max(0.0, un) * triangleArea(t);
  return std::isfinite(w) ? w : 0.0;
}

double sideShift(int side, double step, bool flip)
{
  const double along = flip ? -step : step;
  return side == IntoFlux ? along : side == AgainstFlux ? -along : 0.0;
}

namespace
{
/// The velocity where `side` samples triangle t; false where there is none.
bool sampleSide(
  const double t[9], int side, double step, bool flip, const SurfaceVelocity& velocity, double u[3])
{
  std::array<double, 3> x = triangleCentroid(t);
  const std::array<double, 3> n = triangleNormal(t);
  const double shift = sideShift(side, step, flip);
  for (std::size_t a = 0; a < 3; ++a)
  {
    x[a] += shift * n[a];
  }
  u[0] = u[1] = u[2] = 0.0;
  return velocity(x, u) && std::isfinite(u[0]) && std::isfinite(u[1]) && std::isfinite(u[2]);
}
} // namespace

std::vector<int> surfaceSides(
  const std::vector<double>& triangles, const SurfaceVelocity& velocity, bool flip, double step)
{
  std::vector<int> sides(triangles.size() / 9, NoSample);
  const int last = step > 0.0 && std::isfinite(step) ? AgainstFlux : AtCentroid;
  for (std::size_t i = 0; i < sides.size(); ++i)
  {
    const double* t = triangles.data() + 9 * i;
    double u[3];
    for (int side = AtCentroid; triangleArea(t) > 0.0 && side <= last; ++side)
    {
      if (sampleSide(t, side, step, flip, velocity, u))
      {
        sides[i] = side;
        break;
      }
    }
  }
  return sides;
}

std::vector<double> surfaceWeights(const std::vector<double>& triangles,
  const SurfaceVelocity& velocity, bool flip, double step, const std::vector<int>& sides,
  std::vector<double>* against)
{
  const std::vector<int> own =
    sides.size() == triangles.size() / 9 ? sides : surfaceSides(triangles, velocity, flip, step);
  std::vector<double> weights(triangles.size() / 9, 0.0);
  if (against)
  {
    against->assign(weights.size(), 0.0);
  }
  for (std::size_t i = 0; i < weights.size(); ++i)
  {
    const double* t = triangles.data() + 9 * i;
    if (!(triangleArea(t) > 0.0))
    {
      continue; // no area, or a corner not finite: 0
    }
    double u[3];
    const bool has = own[i] != NoSample && sampleSide(t, own[i], step, flip, velocity, u);
    weights[i] = has ? fluxWeight(t, u, flip) : NoVelocity;
    if (against)
    {
      (*against)[i] = has ? fluxWeight(t, u, !flip) : NoVelocity;
    }
  }
  return weights;
}

SurfaceSummary summarizeSurface(const std::vector<double>& triangles,
  const std::vector<double>& weights, const std::vector<double>& against)
{
  SurfaceSummary s;
  s.triangles = std::min(triangles.size() / 9, weights.size());
  for (std::size_t i = 0; i < s.triangles; ++i)
  {
    const double* t = triangles.data() + 9 * i;
    const double area = triangleArea(t);
    if (!triangles::finite(t))
    {
      ++s.nonFinite;
    }
    else if (!(area > 0.0))
    {
      ++s.noArea;
    }
    else if (!(weights[i] >= 0.0))
    {
      ++s.noVelocity;
    }
    else if (weights[i] > 0.0)
    {
      ++s.crossing;
      s.total += weights[i];
    }
    if (i < against.size() && against[i] > 0.0)
    {
      s.against += against[i];
    }
    s.area += area;
  }
  return s;
}

std::string surfaceProblem(const SurfaceSummary& s, bool flip)
{
  std::ostringstream out;
  const std::string nothing = ": Seed Type Surface releases nothing.";
  if (s.triangles == 0)
  {
    out << "The Seed Source has no surface with area (no cells, or only points and lines)"
        << nothing << " Connect a surface or a volume (a Plane, a data set's boundary), or use "
        << "the Line or Point Cloud Seed Type.";
  }
  else if (s.nonFinite == s.triangles)
  {
    out << "Every one of the Seed Source's " << s.triangles
        << " surface triangles has a corner that is not finite (NaN or Inf)" << nothing;
  }
  else if (s.nonFinite + s.noArea == s.triangles)
  {
    out << "The Seed Source's surface has no area (its " << s.triangles - s.nonFinite
        << " finite triangles are degenerate)" << nothing;
  }
  else if (s.nonFinite + s.noArea + s.noVelocity == s.triangles)
  {
    out << "The Seed Source's surface lies outside the field (or only in cells outside the "
           "flow's domain) at the trace's start"
        << nothing << " Move it into the field.";
  }
  else if (!(s.total > 0.0))
  {
    out << "No flow crosses the Seed Source's surface along its " << (flip ? "flipped " : "")
        << "normals at the trace's start (max(0, u·n) is 0 on each of its "
        << s.triangles - s.nonFinite - s.noArea - s.noVelocity << " triangles in the flow)"
        << nothing << " ";
    if (s.against > 0.0)
    {
      out << "The flow crosses it the other way (a flux of " << s.against << " against its "
          << (flip ? "flipped " : "") << "normals). " << (flip ? "Unset" : "Set")
          << " the Surface's Flip Normals.";
    }
    else
    {
      out << "No flow crosses it the other way either: it runs along the surface. Move the "
             "surface across the flow, or use another Seed Type.";
    }
  }
  return out.str();
}

std::string surfaceWarning(const SurfaceSummary& s, bool flip)
{
  std::ostringstream out;
  if (s.total > 0.0 && s.against > AgainstFluxRatio * s.total)
  {
    out << "Most of the flow through the Seed Source's surface crosses it against its "
        << (flip ? "flipped " : "") << "normals (a flux of " << s.against << " against, " << s.total
        << " along): the Surface releases only where it crosses along them. The "
        << "surface's normals may be inconsistent, or " << (flip ? "unset" : "set")
        << " Flip Normals.";
  }
  return out.str();
}

double surfaceDraw(std::uint32_t seed, std::uint32_t point, std::uint32_t draw)
{
  // 27 + 26 bits: every double of [0, 1) on a 2^-53 step.
  const std::uint32_t hi = counterHash(seed, point, SurfaceLane, 2 * draw) >> 5u;
  const std::uint32_t lo = counterHash(seed, point, SurfaceLane, 2 * draw + 1) >> 6u;
  return (double(hi) * 67108864.0 + double(lo)) / 9007199254740992.0;
}

std::array<double, 3> pointInTriangle(const double t[9], double r1, double r2)
{
  const double s = std::sqrt(r1);
  const double wa = 1.0 - s, wb = s * (1.0 - r2), wc = s * r2;
  return { wa * t[0] + wb * t[3] + wc * t[6], wa * t[1] + wb * t[4] + wc * t[7],
    wa * t[2] + wb * t[5] + wc * t[8] };
}

std::size_t pickWeighted(const std::vector<double>& cumulative, double r)
{
  if (cumulative.empty() || !(cumulative.back() > 0.0))
  {
    return cumulative.size();
  }
  const double target = r * cumulative.back();
  // The first running sum above the target: a weight of 0 repeats the sum
  // before it, which is never above a target it did not pass.
  std::size_t i = std::size_t(
    std::upper_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin());
  if (i >= cumulative.size())
  {
    // r · total rounded up to total: the last triangle with weight.
    i = cumulative.size() - 1;
    while (i > 0 && cumulative[i - 1] == cumulative[i])
    {
      --i;
    }
  }
  return i;
}

std::vector<double> drawSurfacePoints(const std::vector<double>& triangles,
  const std::vector<double>& weights, std::uint32_t seed, std::size_t count,
  const std::vector<double>& shifts)
{
  const std::size_t n = std::min(triangles.size() / 9, weights.size());
  std::vector<double> cumulative(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    sum += std::max(0.0, std::isfinite(weights[i]) ? weights[i] : 0.0);
    cumulative[i] = sum;
  }
  std::vector<double> xyz;
  if (!(sum > 0.0) || !std::isfinite(sum))
  {
    return xyz;
  }
  xyz.reserve(3 * count);
  for (std::size_t p = 0; p < count; ++p)
  {
    const std::uint32_t point = std::uint32_t(p);
    const std::size_t i = pickWeighted(cumulative, surfaceDraw(seed, point, 0));
    const double* t = triangles.data() + 9 * i;
    std::array<double, 3> x =
      pointInTriangle(t, surfaceDraw(seed, point, 1), surfaceDraw(seed, point, 2));
    if (i < shifts.size() && shifts[i] != 0.0 && std::isfinite(shifts[i]))
    {
      const std::array<double, 3> n = triangleNormal(t);
      for (std::size_t a = 0; a < 3; ++a)
      {
        x[a] += shifts[i] * n[a];
      }
    }
    xyz.insert(xyz.end(), x.begin(), x.end());
  }
  return xyz;
}

} // namespace bp
