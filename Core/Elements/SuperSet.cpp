// SPDX-License-Identifier: BSD-3-Clause
#include "SuperSet.h"
#include "SuperSetLinks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace bp
{
namespace
{
constexpr double TwoPi = 6.28318530717958647692;

/// Position t in [0, 1] of index k of count along a segment (the middle for one).
double along(std::size_t k, std::size_t count)
{
  return count > 1 ? double(k) / double(count - 1) : 0.5;
}
} // namespace

std::size_t LinkTable::linkCount() const
{
  std::size_t count = 0;
  forEachLink(*this, [&count](std::size_t, std::size_t) { ++count; });
  return count;
}

namespace
{
/// The lattice width W for `elements` sites: one row for chains and rings,
/// `width` (clamped to the elements) or the smallest W with W * W >= elements
/// for sheets, tubes and tori.
std::size_t latticeWidth(Linking linking, std::size_t elements, int width)
{
  const std::size_t N = elements;
  std::size_t W = N;
  if (linking == Linking::Sheet || linking == Linking::Tube || linking == Linking::Torus)
  {
    W = width > 0 ? std::min<std::size_t>(std::size_t(width), N)
                  : std::size_t(std::ceil(std::sqrt(double(N))));
    while (W * W < N && width <= 0)
    {
      ++W; // sqrt rounding
    }
    W = std::max<std::size_t>(W, 1);
  }
  return W;
}

/// Each element's lattice site in the emitter box [lo, hi], into table.sites
/// (table.width and table.height set).
void placeSites(LinkTable& table, Linking linking, std::size_t N, const std::array<float, 3>& lo,
  const std::array<float, 3>& hi)
{
  const std::size_t W = std::size_t(table.width), H = std::size_t(table.height);
  // The box's axes by extent, longest first (ties in axis order).
  std::array<int, 3> axis = { 0, 1, 2 };
  std::stable_sort(axis.begin(), axis.end(),
    [&](int a, int b) { return double(hi[a]) - lo[a] > double(hi[b]) - lo[b]; });
  double middle[3], half[3];
  for (int a = 0; a < 3; ++a)
  {
    middle[a] = 0.5 * (double(lo[a]) + double(hi[a]));
    half[a] = 0.5 * (double(hi[a]) - double(lo[a]));
  }
  const int a0 = axis[0], a1 = axis[1], a2 = axis[2];

  table.sites.resize(3 * N);
  for (std::size_t e = 0; e < N; ++e)
  {
    const std::size_t u = e % W, v = e / W;
    double s[3] = { middle[0], middle[1], middle[2] };
    switch (linking)
    {
      case Linking::Chain:
        s[a0] = lo[a0] + along(u, W) * (double(hi[a0]) - lo[a0]);
        break;
      case Linking::Ring:
      {
        const double theta = TwoPi * double(u) / double(W);
        s[a0] = middle[a0] + half[a0] * std::cos(theta);
        s[a1] = middle[a1] + half[a1] * std::sin(theta);
        break;
      }
      case Linking::Sheet:
        s[a0] = lo[a0] + along(u, W) * (double(hi[a0]) - lo[a0]);
        s[a1] = lo[a1] + along(v, H) * (double(hi[a1]) - lo[a1]);
        break;
      case Linking::Tube:
      {
        // Rows are rings around the longest axis; columns run along it.
        const double theta = TwoPi * double(u) / double(W);
        s[a0] = lo[a0] + along(v, H) * (double(hi[a0]) - lo[a0]);
        s[a1] = middle[a1] + half[a1] * std::cos(theta);
        s[a2] = middle[a2] + half[a2] * std::sin(theta);
        break;
      }
      case Linking::Torus:
      {
        // Rows are the small circles of the tube, columns run around the big
        // ring in the plane of the two longest axes. The tube's radius is a
        // third of the ring's smaller half-extent, and at most the box's half
        // thickness across the ring's plane.
        const double theta = TwoPi * double(u) / double(W), phi = TwoPi * double(v) / double(H);
        const double r = half[a1] / 3.0;
        const double radial = r * std::cos(theta);
        s[a0] = middle[a0] + (half[a0] - r + radial) * std::cos(phi);
        s[a1] = middle[a1] + (half[a1] - r + radial) * std::sin(phi);
        s[a2] = middle[a2] + std::min(r, half[a2]) * std::sin(theta);
        break;
      }
      case Linking::None:
        break;
    }
    for (int k = 0; k < 3; ++k)
    {
      table.sites[3 * e + k] = float(s[k]);
    }
  }
}

/// Each element's neighbours along +u, -u, +v and -v and the links' rest
/// lengths (the sites' distances), from the sites; rows wrap with `wrapU`,
/// columns with `wrapV`.
void linkNeighbours(LinkTable& table, std::size_t N, bool wrapU, bool wrapV)
{
  const std::size_t W = std::size_t(table.width), H = std::size_t(table.height);
  table.neighbours.assign(LinkDirections * N, -1);
  table.rest.assign(LinkDirections * N, 0.0f);
  const auto link = [&](std::size_t e, std::size_t f, int forward)
  {
    const float* a = &table.sites[3 * e];
    const float* b = &table.sites[3 * f];
    const double d[3] = { double(a[0]) - b[0], double(a[1]) - b[1], double(a[2]) - b[2] };
    const float rest = float(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    table.neighbours[LinkDirections * e + forward] = std::int32_t(f);
    table.rest[LinkDirections * e + forward] = rest;
    table.neighbours[LinkDirections * f + forward + 1] = std::int32_t(e);
    table.rest[LinkDirections * f + forward + 1] = rest;
  };
  for (std::size_t e = 0; e < N; ++e)
  {
    const std::size_t u = e % W, v = e / W;
    if (u + 1 < W && e + 1 < N)
    {
      link(e, e + 1, 0);
    }
    else if (wrapU && u + 1 == W)
    {
      link(e, v * W, 0);
    }
    if (v + 1 < H && e + W < N)
    {
      link(e, e + W, 2);
    }
    else if (wrapV && v + 1 == H)
    {
      link(e, u, 2);
    }
  }
}
} // namespace

LinkTable makeLinkTable(Linking linking, std::size_t elements, int width,
  const std::array<float, 3>& lo, const std::array<float, 3>& hi)
{
  LinkTable table;
  if (linking == Linking::None || elements == 0)
  {
    return table;
  }
  const std::size_t N = elements;
  const std::size_t W = latticeWidth(linking, N, width);
  const std::size_t H = (N + W - 1) / W;
  table.width = int(W);
  table.height = int(H);
  // Wrapping a row of one or two sites would link the same pair twice.
  const bool wrapU =
    (linking == Linking::Ring || linking == Linking::Tube || linking == Linking::Torus) && W >= 3;
  const bool wrapV = linking == Linking::Torus && H >= 3;
  placeSites(table, linking, N, lo, hi);
  linkNeighbours(table, N, wrapU, wrapV);
  return table;
}

} // namespace bp
