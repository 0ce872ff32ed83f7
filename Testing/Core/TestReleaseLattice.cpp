// SPDX-License-Identifier: BSD-3-Clause
#include "ReleaseLattice.h"

#include <gtest/gtest.h>

namespace
{

TEST(ReleaseLattice, FillsTheBoxAtCellCentres)
{
  const bp::ReleaseLattice l = bp::releaseLattice({ 0, 0, 0 }, { 2, 1, 1 }, 2 * 10 * 10 * 10, 0.0);
  EXPECT_EQ(l.counts, (std::array<int, 3>{ 20, 10, 10 }));
  EXPECT_EQ(l.size(), 2000u);
  EXPECT_FLOAT_EQ(l.spacing[0], 0.1f);
  EXPECT_FLOAT_EQ(l.origin[0], 0.05f);
  const auto first = l.point(0), last = l.point(l.size() - 1);
  EXPECT_FLOAT_EQ(first[1], 0.05f);
  EXPECT_NEAR(last[0], 1.95f, 1e-6f);
  EXPECT_NEAR(last[2], 0.95f, 1e-6f);
  // x fastest, then y, then z; ids cycle.
  EXPECT_NEAR(l.point(20)[1], 0.15f, 1e-6f);
  EXPECT_NEAR(l.point(200)[2], 0.15f, 1e-6f);
  EXPECT_EQ(l.point(l.size() + 3), l.point(3));
}

TEST(ReleaseLattice, FlatAxisHasOnePointOnThePlane)
{
  const bp::ReleaseLattice l = bp::releaseLattice({ 0, 0, 0.5f }, { 2, 1, 0.5f }, 200, 0.0);
  EXPECT_EQ(l.counts, (std::array<int, 3>{ 20, 10, 1 }));
  EXPECT_EQ(l.spacing[2], 0.0f);
  for (std::size_t id : { 0u, 57u, 199u })
    EXPECT_EQ(l.point(id)[2], 0.5f);
}

TEST(ReleaseLattice, SetSpacingRoundsEachAxis)
{
  const bp::ReleaseLattice l = bp::releaseLattice({ -1, 0, 0 }, { 1, 0.5f, 0 }, 7, 0.26);
  EXPECT_EQ(l.counts, (std::array<int, 3>{ 8, 2, 1 }));
  EXPECT_FLOAT_EQ(l.spacing[0], 0.25f);
  EXPECT_FLOAT_EQ(l.origin[0], -0.875f);
}

TEST(ReleaseLattice, DegenerateBoxesGiveOnePointOrACappedCount)
{
  const bp::ReleaseLattice point = bp::releaseLattice({ 1, 2, 3 }, { 1, 2, 3 }, 500, 0.0);
  EXPECT_EQ(point.size(), 1u);
  EXPECT_EQ(point.point(9), (std::array<float, 3>{ 1, 2, 3 }));
  const bp::ReleaseLattice tiny = bp::releaseLattice({ 0, 0, 0 }, { 1, 1, 1 }, 1, 1e-30);
  EXPECT_EQ(tiny.counts[0], bp::MaxLatticeCount);
  const bp::ReleaseLattice one = bp::releaseLattice({ 0, 0, 0 }, { 1, 1, 1 }, 0, 0.0);
  EXPECT_EQ(one.size(), 1u);
}

TEST(ReleaseLattice, AFewElementsStayInsideTheBox)
{
  // One element: the box's centre, not its lowest corner.
  const bp::ReleaseLattice one = bp::releaseLattice({ 0, 0, 0 }, { 1, 2, 4 }, 1, 0.0);
  EXPECT_EQ(one.size(), 1u);
  EXPECT_EQ(one.point(0), (std::array<float, 3>{ 0.5f, 1, 2 }));
  // Two or three in a cube: a row of two or a square of four about the centre.
  for (std::size_t elements : { 2u, 3u })
  {
    const bp::ReleaseLattice few = bp::releaseLattice({ -1, -1, -1 }, { 1, 1, 1 }, elements, 0.0);
    EXPECT_GE(few.size(), elements);
    EXPECT_LE(few.size(), 2 * elements);
    std::array<double, 3> mean = { 0, 0, 0 };
    for (std::size_t e = 0; e < few.size(); ++e)
    {
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_GT(few.point(e)[a], -1.0f);
        EXPECT_LT(few.point(e)[a], 1.0f);
        mean[a] += few.point(e)[a] / double(few.size());
      }
    }
    EXPECT_NEAR(mean[0], 0.0, 1e-6);
    EXPECT_NEAR(mean[1], 0.0, 1e-6);
    EXPECT_NEAR(mean[2], 0.0, 1e-6);
  }
}

TEST(ReleaseLattice, AThinSlabKeepsTheTarget)
{
  // 1000 over a 2 x 1 x 0.01 slab: the slab is one point thick, and the
  // target is spent in its plane (45 x 22), not across it (58 x 58 x 1).
  const bp::ReleaseLattice slab = bp::releaseLattice({ 0, 0, 0 }, { 2, 1, 0.01f }, 1000, 0.0);
  EXPECT_EQ(slab.counts, (std::array<int, 3>{ 45, 22, 1 }));
  EXPECT_FLOAT_EQ(slab.origin[2], 0.005f);
  // A box thin on two axes: a line of points.
  const bp::ReleaseLattice line = bp::releaseLattice({ 0, 0, 0 }, { 4, 0.01f, 0.01f }, 100, 0.0);
  EXPECT_EQ(line.counts, (std::array<int, 3>{ 100, 1, 1 }));
}

} // namespace
