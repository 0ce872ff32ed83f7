// SPDX-License-Identifier: BSD-3-Clause
#include "ResampleGrid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{

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
  // Cells close to cubes, and about as many points as the mesh has cells
  // (capped): each spanning axis gets its share of the points.
  const double cap = std::clamp(automaticCap, 1.0, double(MaxAutomaticResamplePoints));
  const double target = std::clamp(cellCount, 1.0, cap);
  const double h = std::pow(volume / target, 1.0 / spanning);
  double points = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    int n = 1;
    if (spans[a] && requested[a] > 0)
    {
      n = requested[a];
      if (n < 2)
      {
        std::ostringstream err;
        err << "Resample Dimensions asks for " << n << " point along " << "XYZ"[a]
            << ", along which the data has extent; give at least 2 (or 0: automatic).";
        g.error = err.str();
        return g;
      }
    }
    else if (spans[a])
    {
      n = std::max(MinAutomaticResampleAxisPoints, int(std::lround(extent[a] / h)));
    }
    g.dims[a] = n;
    g.origin[a] = spans[a] ? bounds[2 * a] : 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    g.spacing[a] = n > 1 ? extent[a] / double(n - 1) : 1.0;
    points *= n;
  }
  if (points > MaxResamplePoints)
  {
    std::ostringstream err;
    err << "Resample Dimensions " << g.dims[0] << " x " << g.dims[1] << " x " << g.dims[2]
        << " is " << (long long)points << " points, more than the "
        << (long long)MaxResamplePoints
        << " a resampled grid may have; choose fewer (or 0 0 0: automatic).";
    g.error = err.str();
  }
  return g;
}

} // namespace bp
