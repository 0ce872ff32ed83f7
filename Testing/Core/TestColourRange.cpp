// SPDX-License-Identifier: BSD-3-Clause
#include "ColourRange.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{
/// A histogram of `values` in `bins` equal bins over their full range.
std::vector<double> histogram(const std::vector<double>& values, int bins, bp::Range& range)
{
  range = { *std::min_element(values.begin(), values.end()),
    *std::max_element(values.begin(), values.end()) };
  std::vector<double> counts(std::size_t(bins), 0.0);
  for (const double v : values)
  {
    const int bin = int((v - range[0]) / (range[1] - range[0]) * bins);
    counts[std::size_t(std::clamp(bin, 0, bins - 1))] += 1.0;
  }
  return counts;
}
} // namespace

TEST(ColourRange, HoldsTheMiddleValuesNotAFewFastOnes)
{
  // 10,000 slow speeds spread over [0, 1] and 50 points a hundred times faster:
  // the full range [0, 100] maps nine in ten values into its lowest 1%.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> slow(0.0, 1.0);
  std::vector<double> values;
  for (int i = 0; i < 10000; ++i)
    values.push_back(slow(random));
  for (int i = 0; i < 50; ++i)
    values.push_back(100.0 - i * 0.01);
  bp::Range full;
  const std::vector<double> counts = histogram(values, 4096, full);
  const bp::Range held = bp::colourRange(counts, full);
  // The exact 5% and 95% quantiles, within a bin's width.
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const double width = (full[1] - full[0]) / 4096.0;
  EXPECT_NEAR(held[0], sorted[std::size_t(0.05 * double(sorted.size()))], width);
  EXPECT_NEAR(held[1], sorted[std::size_t(0.95 * double(sorted.size()))], width);
  EXPECT_LT(held[1], 1.0);
  EXPECT_GT(held[1], 0.9);
}

TEST(ColourRange, QuantilesInterpolateWithinABin)
{
  // Two bins over [0, 2] with 1 and 3 values: a quarter lies below 1, half
  // below 1 + (0.5 - 0.25) / 0.75.
  const std::vector<double> counts{ 1.0, 3.0 };
  EXPECT_DOUBLE_EQ(bp::histogramQuantile(counts, { 0.0, 2.0 }, 0.25), 1.0);
  EXPECT_DOUBLE_EQ(bp::histogramQuantile(counts, { 0.0, 2.0 }, 0.5), 1.0 + 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(bp::histogramQuantile(counts, { 0.0, 2.0 }, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(bp::histogramQuantile(counts, { 0.0, 2.0 }, 0.0), 0.0);
}

TEST(ColourRange, KeepsTheFullRangeWhereNothingOrOneValueWasCounted)
{
  const bp::Range full{ 2.0, 5.0 };
  const bp::Range none = bp::colourRange(std::vector<double>(8, 0.0), full);
  EXPECT_EQ(none, full);
  EXPECT_EQ(bp::colourRange({}, full), full);
  EXPECT_TRUE(std::isnan(bp::histogramQuantile({}, full, 0.5)));
  // Nearly all values in the lowest bin: the range spreads within that bin.
  std::vector<double> one(8, 0.0);
  one[0] = 1000.0;
  one[7] = 1.0;
  const bp::Range held = bp::colourRange(one, full);
  EXPECT_LT(held[0], held[1]);
  EXPECT_GE(held[0], full[0]);
  EXPECT_LE(held[1], full[0] + (full[1] - full[0]) / 8.0);
  // A range that is not finite gives NaN quantiles and is kept as it is.
  const bp::Range bad{ 0.0, std::nan("") };
  const bp::Range kept = bp::colourRange(one, bad);
  EXPECT_EQ(kept[0], 0.0);
  EXPECT_TRUE(std::isnan(kept[1]));
}

TEST(ColourRange, LogarithmicWhereMostValuesCrowdTheBottom)
{
  // Speeds spread evenly over their logarithm, 1e-3 to 1: half lie below
  // 0.03, in the lowest 3% of a linear map.
  std::vector<double> values;
  for (int i = 0; i <= 10000; ++i)
    values.push_back(std::pow(10.0, -3.0 + 3.0 * i / 10000.0));
  bp::Range full;
  const std::vector<double> counts = histogram(values, 4096, full);
  const bp::ColourScale skewed = bp::colourScale(counts, full);
  EXPECT_TRUE(skewed.logarithmic);
  EXPECT_GT(skewed.range[0], 0.0);
  // Evenly spread values keep a linear map over their full range (the
  // middle 90% spans 90% of it).
  std::vector<double> even;
  for (int i = 0; i <= 10000; ++i)
    even.push_back(i / 10000.0);
  const bp::ColourScale linear = bp::colourScale(histogram(even, 4096, full), full);
  EXPECT_FALSE(linear.logarithmic);
  EXPECT_EQ(linear.range, full);
  // A few fast values among them: the middle range, still linear.
  even.insert(even.end(), 100, 10.0);
  const bp::ColourScale tail = bp::colourScale(histogram(even, 4096, full), full);
  EXPECT_FALSE(tail.logarithmic);
  EXPECT_LT(tail.range[1], 1.0);
  // Skewed values down to zero (stagnant elements) cannot be mapped by
  // their logarithm.
  std::vector<double> zeros = values;
  zeros.insert(zeros.end(), 2000, 0.0);
  EXPECT_FALSE(bp::colourScale(histogram(zeros, 4096, full), full).logarithmic);
}
