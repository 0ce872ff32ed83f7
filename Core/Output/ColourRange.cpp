// SPDX-License-Identifier: BSD-3-Clause
#include "ColourRange.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bp
{

double histogramQuantile(const std::vector<double>& counts, const Range& range, double fraction)
{
  double total = 0.0;
  for (const double count : counts)
  {
    total += std::max(count, 0.0);
  }
  if (!(total > 0.0) || !std::isfinite(range[0]) || !std::isfinite(range[1]) || range[1] < range[0])
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double target = std::clamp(fraction, 0.0, 1.0) * total;
  const double width = (range[1] - range[0]) / static_cast<double>(counts.size());
  double below = 0.0;
  for (std::size_t bin = 0; bin < counts.size(); ++bin)
  {
    const double count = std::max(counts[bin], 0.0);
    if (count > 0.0 && below + count >= target)
    {
      const double within = std::clamp((target - below) / count, 0.0, 1.0);
      return range[0] + (static_cast<double>(bin) + within) * width;
    }
    below += count;
  }
  return range[1];
}

Range colourRange(const std::vector<double>& counts, const Range& range, double tail)
{
  const double share = std::clamp(tail, 0.0, 0.5);
  const Range held{ histogramQuantile(counts, range, share),
    histogramQuantile(counts, range, 1.0 - share) };
  if (!(held[1] > held[0]))
  {
    return range; // NaN (nothing counted) or most values equal
  }
  return held;
}

ColourScale colourScale(const std::vector<double>& counts, const Range& range, double tail)
{
  ColourScale scale;
  scale.range = colourRange(counts, range, tail);
  const double low = scale.range[0], high = scale.range[1];
  const double median = histogramQuantile(counts, range, 0.5);
  // Every value positive (the full range's, not the interpolated quantile):
  // a log map has no colour for zero.
  scale.logarithmic =
    range[0] > 0.0 && low > 0.0 && high >= 10.0 * low && median < low + 0.25 * (high - low);
  if (!scale.logarithmic && high - low >= ColourRangeKept * (range[1] - range[0]))
  {
    scale.range = range; // nearly the full range: nothing a user would change
  }
  return scale;
}

} // namespace bp
