// SPDX-License-Identifier: BSD-3-Clause
// Tests of Core/Base/CounterHash.h: the counter-based draws every release hashes.
#include "CounterHash.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

TEST(CounterHash, UniformsCoverTheUnitInterval)
{
  double sum = 0.0;
  float lo = 1.0f, hi = 0.0f;
  const int n = 100000;
  for (int i = 0; i < n; ++i)
  {
    const float u = bp::uniformDraw(1, std::uint32_t(i), 0, 0);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  EXPECT_NEAR(sum / n, 0.5, 0.01);
  EXPECT_LT(lo, 0.001f);
  EXPECT_GT(hi, 0.999f);
  // Each counter matters.
  const std::uint32_t h = bp::counterHash(1, 2, 3, 4);
  EXPECT_NE(h, bp::counterHash(2, 2, 3, 4));
  EXPECT_NE(h, bp::counterHash(1, 3, 3, 4));
  EXPECT_NE(h, bp::counterHash(1, 2, 4, 4));
  EXPECT_NE(h, bp::counterHash(1, 2, 3, 5));
}
