// SPDX-License-Identifier: BSD-3-Clause
#include "ResampleGrid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{
namespace
{
/// The grid's points: the product of the counts.
double product(const std::array<int, 3>& n)
{
  return double(n[0]) * double(n[1]) * double(n[2]);
}

/// The names of the axes flagged, "X", "X and Z" or "X, Y and Z".
std::string axisNames(const std::array<bool, 3>& flagged)
{
  std::string names;
  const int count = int(flagged[0]) + int(flagged[1]) + int(flagged[2]);
  int seen = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (flagged[a])
    {
      names += seen == 0 ? "" : seen + 1 == count ? " and " : ", ";
      names += "XYZ"[a];
      ++seen;
    }
  }
  return names;
}

/**
 * Lowers the counts of the axes still `open` together (cells stay close to
 * cubes), never below the minimum, until the grid has at most `limit`
 * points; an axis that reaches the minimum closes.
 */
void shrinkTo(double limit, std::array<int, 3>& n, std::array<bool, 3>& open)
{
  for (int round = 0; round < 4 && product(n) > limit; ++round)
  {
    double openPoints = 1.0, others = 1.0;
    int count = 0;
    for (int a = 0; a < 3; ++a)
    {
      (open[a] ? openPoints : others) *= n[a];
      count += open[a] ? 1 : 0;
    }
    if (count == 0)
    {
      return;
    }
    const double scale = std::pow(limit / others / openPoints, 1.0 / count);
    for (int a = 0; a < 3; ++a)
    {
      if (open[a])
      {
        n[a] = std::max(MinAutomaticResampleAxisPoints, int(std::floor(n[a] * scale)));
        open[a] = n[a] > MinAutomaticResampleAxisPoints;
      }
    }
  }
  // Rounding's last points: one at a time off the open axis with the most.
  while (product(n) > limit)
  {
    int widest = -1;
    for (int a = 0; a < 3; ++a)
    {
      if (open[a] && n[a] > MinAutomaticResampleAxisPoints && (widest < 0 || n[a] > n[widest]))
      {
        widest = a;
      }
    }
    if (widest < 0)
    {
      return;
    }
    --n[widest];
  }
}

/// What the automatic choice gave up, said in a warning (ResampleGrid::note).
std::string describeChoice(const std::array<int, 3>& n, double cellCount, double cap,
  const std::array<bool, 3>& thin, bool capped, double limit)
{
  std::ostringstream say;
  say << "Resample Dimensions (automatic) chose a grid of " << n[0] << " x " << n[1] << " x "
      << n[2] << " = " << (long long)product(n) << " points for the mesh's " << (long long)cellCount
      << " cells";
  if (thin[0] || thin[1] || thin[2])
  {
    say << "; the mesh is thin along " << axisNames(thin) << " (the fewest points an axis "
        << "takes there: " << MinAutomaticResampleAxisPoints << ")";
  }
  if (capped)
  {
    say << "; the other axes were coarsened to keep within " << (long long)limit << " points ("
        << (limit >= cap ? "the automatic grid's limit, or what this process can allocate"
                         : "8 times the cells for each thin axis")
        << ")";
  }
  else if (cellCount > cap)
  {
    say << ": fewer than the cells (the automatic grid's limit, or what this process can "
           "allocate), so the grid is coarser than the mesh";
  }
  say << ". Set Resample Dimensions to choose otherwise.";
  return say.str();
}
} // namespace

ResampleGrid chooseResampleGrid(const std::array<double, 6>& bounds, double cellCount,
  const std::array<int, 3>& requested, bool surface, double automaticCap)
{
  ResampleGrid g;
  std::array<double, 3> extent{};
  double largest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = bounds[2 * a + 1] - bounds[2 * a];
    if (!std::isfinite(bounds[2 * a]) || !std::isfinite(bounds[2 * a + 1]) || extent[a] < 0.0)
    {
      g.error = "The input has no points to resample (its bounds are empty or not finite).";
      return g;
    }
    largest = std::max(largest, extent[a]);
  }
  if (largest <= 0.0)
  {
    g.error = "The input's points all lie at one position: there is no volume or surface to "
              "resample a flow onto.";
    return g;
  }
  // The axes with extent; the others are planes of one point. A surface's
  // thinnest axis is one of those.
  const int thinnest = int(std::min_element(extent.begin(), extent.end()) - extent.begin());
  if (surface && extent[thinnest] > MaxSurfaceThickness * largest)
  {
    g.error = "The input is a surface mesh (2D cells) that does not lie in a plane of constant "
              "X, Y or Z; Bound Particle Tracer resamples a surface onto such a plane. Rotate "
              "it into one (Transform), or give the tracer the volume mesh the vectors live on.";
    return g;
  }
  std::array<bool, 3> spans{};
  double volume = 1.0;
  int spanning = 0;
  for (int a = 0; a < 3; ++a)
  {
    spans[a] = extent[a] > 1e-9 * largest && !(surface && a == thinnest);
    if (spans[a])
    {
      volume *= extent[a];
      ++spanning;
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    if (spans[a] && requested[a] > 0 && requested[a] < 2)
    {
      std::ostringstream err;
      err << "Resample Dimensions asks for " << requested[a] << " point along "
          << "XYZ"[a] << ", along which the data has extent; give at least 2 (or 0: automatic).";
      g.error = err.str();
      return g;
    }
  }
  g.dims = automaticDimensions(extent, spans, requested, cellCount, volume, spanning,
    std::clamp(automaticCap, 1.0, double(MaxAutomaticResamplePoints)), g.note);
  for (int a = 0; a < 3; ++a)
  {
    g.origin[a] = spans[a] ? bounds[2 * a] : 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    g.spacing[a] = g.dims[a] > 1 ? extent[a] / double(g.dims[a] - 1) : 1.0;
  }
  if (product(g.dims) > MaxResamplePoints)
  {
    std::ostringstream err;
    err << "Resample Dimensions " << g.dims[0] << " x " << g.dims[1] << " x " << g.dims[2] << " is "
        << (long long)product(g.dims) << " points, more than the " << (long long)MaxResamplePoints
        << " a resampled grid may have; choose fewer (or 0 0 0: automatic).";
    g.error = err.str();
  }
  return g;
}

std::array<int, 3> automaticDimensions(const std::array<double, 3>& extent,
  const std::array<bool, 3>& spans, const std::array<int, 3>& requested, double cellCount,
  double volume, int spanning, double cap, std::string& note)
{
  // Cells close to cubes, and about as many points as the mesh has cells
  // (capped): each spanning axis gets its share of the points.
  const double target = std::clamp(cellCount, 1.0, cap);
  const double h = std::pow(volume / target, 1.0 / spanning);
  std::array<int, 3> n = { 1, 1, 1 };
  std::array<bool, 3> open{}, thin{};
  bool anyRequested = false;
  int thinAxes = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (spans[a] && requested[a] > 0)
    {
      n[a] = requested[a];
      anyRequested = true;
    }
    else if (spans[a])
    {
      // A thin axis (a slab, a rod) gets the fewest points an axis takes;
      // the others are not refined to make up for it.
      const long natural = std::lround(extent[a] / h);
      thin[a] = natural < MinAutomaticResampleAxisPoints;
      thinAxes += thin[a] ? 1 : 0;
      n[a] = thin[a] ? MinAutomaticResampleAxisPoints : int(std::min(natural, long(1) << 30));
      open[a] = !thin[a];
    }
  }
  // At most the cap, and with thin axes at most 8 times the cells for each
  // (a slab's in-plane axes then get about as many points as its cells).
  double limit = cap;
  if (!anyRequested && thinAxes > 0)
  {
    limit = std::min(cap, std::pow(double(MinAutomaticResampleAxisPoints), thinAxes) * target);
  }
  const double before = product(n);
  shrinkTo(limit, n, open);
  const bool capped = product(n) < before;
  if (capped || (cellCount > cap && (open[0] || open[1] || open[2])))
  {
    note = describeChoice(n, cellCount, cap, thin, capped, limit);
  }
  return n;
}

} // namespace bp
