// SPDX-License-Identifier: BSD-3-Clause
#include "ValueRanges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace
{
/// VTK's rules, one value at a time: NaN never counts, the finite ranges also
/// skip infinities, the magnitude is the root of the float squared sum.
struct Naive
{
  std::vector<bp::Range> component, finiteComponent;
  bp::Range magnitude, finiteMagnitude;
};

Naive naive(const std::vector<float>& values, int components)
{
  const double big = std::numeric_limits<double>::max();
  Naive r;
  r.component.assign(std::size_t(components), { big, -big });
  r.finiteComponent = r.component;
  r.magnitude = r.finiteMagnitude = { big, -big };
  auto add = [](bp::Range& range, double v)
  {
    if (std::isnan(v))
      return;
    range[0] = std::min(range[0], v);
    range[1] = std::max(range[1], v);
  };
  for (std::size_t i = 0; i < values.size() / std::size_t(components); ++i)
  {
    float squared = 0.0f;
    for (int c = 0; c < components; ++c)
    {
      const float v = values[i * std::size_t(components) + std::size_t(c)];
      add(r.component[std::size_t(c)], v);
      if (!std::isinf(v))
        add(r.finiteComponent[std::size_t(c)], v);
      squared += v * v;
    }
    add(r.magnitude, squared);
    if (!std::isinf(squared))
      add(r.finiteMagnitude, squared);
  }
  for (bp::Range* m : { &r.magnitude, &r.finiteMagnitude })
    *m = { std::sqrt((*m)[0]), std::sqrt((*m)[1]) };
  return r;
}
} // namespace

TEST(ValueRanges, MatchVtksRulesOnAnyRunner)
{
  std::mt19937 random(3);
  std::normal_distribution<float> value(0.0f, 10.0f);
  std::vector<float> values(3 * 10007);
  for (float& v : values)
    v = value(random);
  values[5] = std::numeric_limits<float>::quiet_NaN();
  values[300] = std::numeric_limits<float>::infinity();
  values[301] = -std::numeric_limits<float>::infinity();
  values[9000] = 1e30f; // its square is infinite in float: out of the finite magnitude
  const Naive expected = naive(values, 3);
  for (const bp::RangeRunner& run : { bp::serialRunner(), bp::poolRunner(3) })
  {
    const bp::ValueRanges r = bp::valueRanges(values.data(), values.size() / 3, 3, run);
    ASSERT_EQ(r.component.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c)
    {
      EXPECT_EQ(r.component[c], expected.component[c]) << c;
      EXPECT_EQ(r.finiteComponent[c], expected.finiteComponent[c]) << c;
    }
    // values[300] is component 0 of tuple 100, values[301] its component 1
    EXPECT_EQ(r.component[0][1], std::numeric_limits<float>::infinity());
    EXPECT_EQ(r.component[1][0], -std::numeric_limits<float>::infinity());
    EXPECT_TRUE(std::isfinite(r.finiteComponent[0][1]));
    EXPECT_TRUE(std::isfinite(r.finiteComponent[1][0]));
    EXPECT_EQ(r.magnitude, expected.magnitude);
    EXPECT_EQ(r.finiteMagnitude, expected.finiteMagnitude);
    EXPECT_TRUE(std::isinf(r.magnitude[1]));
  }
}

TEST(ValueRanges, IntegersAndEmptyArrays)
{
  const std::vector<long long> ids = { 7, -3, 12, 0 };
  const bp::ValueRanges r = bp::valueRanges(ids.data(), ids.size(), 1, bp::serialRunner());
  EXPECT_EQ(r.component[0], (bp::Range{ -3.0, 12.0 }));
  EXPECT_EQ(r.finiteComponent[0], (bp::Range{ -3.0, 12.0 }));
  const bp::ValueRanges none = bp::valueRanges(ids.data(), 0, 1, bp::serialRunner());
  EXPECT_GT(none.component[0][0], none.component[0][1]); // nothing counted
}

TEST(ValueRanges, EveryComponentCountMatchesVtksRules)
{
  // 1 to 4 components take the register path, 5 the general one; an odd
  // tuple count leaves one tuple past the last pair.
  std::mt19937 random(5);
  std::normal_distribution<float> value(0.0f, 3.0f);
  for (int components = 1; components <= 5; ++components)
  {
    SCOPED_TRACE(components);
    std::vector<float> values(std::size_t(components) * 1001);
    for (float& v : values)
      v = value(random);
    values[7] = std::numeric_limits<float>::quiet_NaN();
    values.back() = 99.0f; // in the last, unpaired tuple
    const Naive expected = naive(values, components);
    const bp::ValueRanges r = bp::valueRanges(
      values.data(), values.size() / std::size_t(components), components, bp::serialRunner());
    for (std::size_t c = 0; c < std::size_t(components); ++c)
    {
      EXPECT_EQ(r.component[c], expected.component[c]) << c;
      EXPECT_EQ(r.finiteComponent[c], expected.finiteComponent[c]) << c;
    }
    if (components > 1)
    {
      EXPECT_EQ(r.magnitude, expected.magnitude);
    }
  }
}

TEST(ValueRanges, WrittenBlockByBlockAsIfWrittenFirst)
{
  // 10,007 elements of 7 particles: blocks of whole elements, the last one
  // short, on every runner, the pool included.
  const std::size_t align = 7, tuples = align * 10007;
  std::mt19937 random(11);
  std::normal_distribution<float> value(0.0f, 5.0f);
  std::vector<float> source(3 * tuples);
  for (float& v : source)
    v = value(random);
  source[40] = std::numeric_limits<float>::quiet_NaN();
  source[41] = std::numeric_limits<float>::infinity();
  const Naive expected = naive(source, 3);
  for (const bp::RangeRunner& run : { bp::serialRunner(), bp::poolRunner(3), bp::poolRunner(2) })
  {
    std::vector<float> out(source.size(), -1.0f);
    std::vector<int> writes(tuples, 0);
    std::atomic<bool> aligned(true); // written from every chunk's thread
    const bp::ValueRanges r = bp::writeWithRanges(out.data(), tuples, align, 3, run,
      [&](std::size_t begin, std::size_t end)
      {
        if (!(begin % align == 0 && end % align == 0 && begin < end))
        {
          aligned = false;
        }
        for (std::size_t i = begin; i < end; ++i)
        {
          ++writes[i];
          std::copy_n(source.data() + 3 * i, 3, out.data() + 3 * i);
        }
      });
    EXPECT_TRUE(aligned);
    EXPECT_EQ(std::count(writes.begin(), writes.end(), 1), std::ptrdiff_t(tuples));
    EXPECT_EQ(0, std::memcmp(out.data(), source.data(), sizeof(float) * out.size()));
    for (std::size_t c = 0; c < 3; ++c)
    {
      EXPECT_EQ(r.component[c], expected.component[c]) << c;
      EXPECT_EQ(r.finiteComponent[c], expected.finiteComponent[c]) << c;
    }
    EXPECT_EQ(r.magnitude, expected.magnitude);
    EXPECT_EQ(r.finiteMagnitude, expected.finiteMagnitude);
  }
}

TEST(ValueRanges, MergedRangesCoverBothParts)
{
  std::vector<float> values = { 1, 2, -4, 8, 3, 0.5f };
  const bp::ValueRanges whole = bp::valueRanges(values.data(), 3, 2, bp::serialRunner());
  bp::ValueRanges merged = bp::valueRanges(values.data(), 2, 2, bp::serialRunner());
  bp::mergeRanges(merged, bp::valueRanges(values.data() + 4, 1, 2, bp::serialRunner()));
  EXPECT_EQ(merged.component, whole.component);
  EXPECT_EQ(merged.finiteComponent, whole.finiteComponent);
  EXPECT_EQ(merged.magnitude, whole.magnitude);
  // An empty part changes nothing.
  bp::mergeRanges(merged, bp::valueRanges(values.data(), 0, 2, bp::serialRunner()));
  EXPECT_EQ(merged.component, whole.component);
  EXPECT_EQ(merged.magnitude, whole.magnitude);
}

TEST(ValueRanges, TheSameEndsWhateverOrderTheRangesEndIn)
{
  // -0 and 0 compare equal, so the one an end keeps depends on which came
  // first: the ranges' parts are merged in the ranges' order, not the order
  // the threads finished them in.
  std::vector<float> values(4096, 1.0f);
  values[10] = -0.0f;
  values[3000] = 0.0f;
  const bp::RangeRunner forwards = [](std::size_t count, const bp::RangeFunction& f)
  {
    for (std::size_t c = 0; c < 4; ++c)
      f(count * c / 4, count * (c + 1) / 4);
  };
  const bp::RangeRunner backwards = [](std::size_t count, const bp::RangeFunction& f)
  {
    for (std::size_t c = 4; c-- > 0;)
      f(count * c / 4, count * (c + 1) / 4);
  };
  const bp::ValueRanges a = bp::valueRanges(values.data(), values.size(), 1, forwards);
  const bp::ValueRanges b = bp::valueRanges(values.data(), values.size(), 1, backwards);
  EXPECT_EQ(std::signbit(a.component[0][0]), std::signbit(b.component[0][0]));
  EXPECT_EQ(std::signbit(a.finiteComponent[0][0]), std::signbit(b.finiteComponent[0][0]));
}

TEST(Parallel, APoolCalledFromItsOwnJobRunsTheInnerCallOnItsCaller)
{
  // The output's writers run inside pool jobs; a nested call must neither
  // deadlock nor lose a range.
  const bp::RangeRunner run = bp::poolRunner(2);
  std::vector<int> hits(1000, 0);
  run(10,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        run(100,
          [&, k](std::size_t b, std::size_t e)
          {
            for (std::size_t i = b; i < e; ++i)
              ++hits[k * 100 + i];
          });
      }
    });
  EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), 1000);
}
