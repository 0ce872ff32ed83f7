// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ColourRange.h
 * @brief The colour range a user would set by hand for an array: the range
 * holding most of its values, read from a histogram, not its extremes.
 *
 * A few fast points set a speed's full range; mapped over it, most elements
 * share the colour of its lowest part. The GUI's first Apply colours the
 * tracer's display over the range between two quantiles instead, and by
 * the logarithm where most values crowd the bottom of that range.
 */
#ifndef BoundParticles_ColourRange_h
#define BoundParticles_ColourRange_h

#include "ValueRanges.h"

#include <vector>

namespace bp
{

/// The share of the values below the colour range and above it: 5% each,
/// the range of the middle 90% of the values.
constexpr double ColourRangeTail = 0.05;

/**
 * The value under which `fraction` (0 to 1) of the values counted in
 * `counts`, a histogram of equal bins over `range`, lie: linear within its
 * bin. NaN where nothing was counted or `range` is not finite.
 */
double histogramQuantile(const std::vector<double>& counts, const Range& range, double fraction);

/**
 * The colour range for values counted in `counts` (equal bins over `range`,
 * the values' full range): from the `tail` quantile to the 1 - `tail`
 * quantile. `range` itself where that range would be empty (most values
 * equal) or nothing was counted.
 */
Range colourRange(
  const std::vector<double>& counts, const Range& range, double tail = ColourRangeTail);

/// How a colour map spreads a range: linearly or by the values' logarithm.
struct ColourScale
{
  Range range{ 0.0, 0.0 };
  bool logarithmic = false;
};

/// A colour range of this share of the full range or more (on a linear
/// scale) leaves the full range: the values spread over it already.
constexpr double ColourRangeKept = 0.8;

/**
 * colourRange(), and whether to map it by the logarithm: where every value
 * is positive (`range[0]` > 0), the colour range spans a decade or more and
 * half the values lie in its lowest quarter (speeds whose many slow values a
 * linear map would leave one colour). The full `range` where the colour
 * range is linear and spans `ColourRangeKept` of it or more.
 */
ColourScale colourScale(
  const std::vector<double>& counts, const Range& range, double tail = ColourRangeTail);

} // namespace bp

#endif
