// SPDX-License-Identifier: BSD-3-Clause
#include "ResampleGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
TEST(ResampleGrid, AboutAsManyPointsAsCellsWithCubicCells)
{
  const bp::ResampleGrid g = bp::chooseResampleGrid({ 0, 4, 0, 2, 0, 1 }, 1e6, { 0, 0, 0 });
  ASSERT_TRUE(g.error.empty()) << g.error;
  EXPECT_NEAR(double(g.pointCount()), 1e6, 0.05e6);
  // Cells close to cubes: the spacings agree within a cell's rounding.
  EXPECT_NEAR(g.spacing[0] / g.spacing[1], 1.0, 0.02);
  EXPECT_NEAR(g.spacing[0] / g.spacing[2], 1.0, 0.02);
  // The grid spans the bounds exactly.
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_DOUBLE_EQ(g.origin[a], 0.0);
  }
  EXPECT_NEAR(g.origin[0] + (g.dims[0] - 1) * g.spacing[0], 4.0, 1e-12);
  EXPECT_NEAR(g.origin[2] + (g.dims[2] - 1) * g.spacing[2], 1.0, 1e-12);
}

TEST(ResampleGrid, AFlatAxisStaysOnePointThick)
{
  // A 2D mesh in the plane z = 3 (far from 0), and one with x flat.
  const bp::ResampleGrid g = bp::chooseResampleGrid({ 0, 2, 0, 1, 3, 3 }, 20000, { 0, 0, 0 });
  ASSERT_TRUE(g.error.empty()) << g.error;
  EXPECT_EQ(g.dims[2], 1);
  EXPECT_DOUBLE_EQ(g.origin[2], 3.0);
  EXPECT_NEAR(double(g.pointCount()), 20000.0, 1000.0);
  EXPECT_NEAR(g.spacing[0] / g.spacing[1], 1.0, 0.02);
  // A requested depth does not thicken a flat axis.
  const bp::ResampleGrid x = bp::chooseResampleGrid({ 5, 5, 0, 1, 0, 1 }, 100, { 50, 0, 0 });
  ASSERT_TRUE(x.error.empty()) << x.error;
  EXPECT_EQ(x.dims[0], 1);
  // Rounding noise in a flat coordinate is flat too.
  const bp::ResampleGrid n = bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1e-12 }, 100, { 0, 0, 0 });
  EXPECT_EQ(n.dims[2], 1);
}

TEST(ResampleGrid, ASurfaceIsFlatAlongItsThinnestAxisOrRefused)
{
  // A 2D mesh with rounding noise (or a slight tilt) in y.
  const bp::ResampleGrid g =
    bp::chooseResampleGrid({ 0, 2, 0.5, 0.5005, 0, 1 }, 5000, { 0, 0, 0 }, true);
  ASSERT_TRUE(g.error.empty()) << g.error;
  EXPECT_EQ(g.dims[1], 1);
  EXPECT_DOUBLE_EQ(g.origin[1], 0.50025);
  // The same bounds as a volume mesh keep their thin axis.
  EXPECT_GT(bp::chooseResampleGrid({ 0, 2, 0.5, 0.5005, 0, 1 }, 5e7, { 0, 0, 0 }).dims[1], 1);
  // A curved or tilted surface is refused, saying what to do.
  const bp::ResampleGrid tilted =
    bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 0.5 }, 5000, { 0, 0, 0 }, true);
  EXPECT_NE(tilted.error.find("plane"), std::string::npos);
}

TEST(ResampleGrid, RequestedAxesAreKeptAndOthersChosen)
{
  const bp::ResampleGrid g = bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1 }, 1000, { 30, 0, 12 });
  ASSERT_TRUE(g.error.empty()) << g.error;
  EXPECT_EQ(g.dims[0], 30);
  EXPECT_EQ(g.dims[2], 12);
  EXPECT_EQ(g.dims[1], 10); // automatic: 1000 cells over a unit cube
  EXPECT_NEAR(g.spacing[0], 1.0 / 29.0, 1e-15);
}

TEST(ResampleGrid, CoarseMeshesGetAUsableGridAndHugeOnesACappedOne)
{
  const bp::ResampleGrid few = bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1 }, 6, { 0, 0, 0 });
  ASSERT_TRUE(few.error.empty());
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(few.dims[a], bp::MinAutomaticResampleAxisPoints);
  }
  const bp::ResampleGrid huge = bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1 }, 1e12, { 0, 0, 0 });
  ASSERT_TRUE(huge.error.empty());
  EXPECT_LE(double(huge.pointCount()), 1.01 * double(bp::MaxAutomaticResamplePoints));
  // Where memory is short, the automatic grid shrinks to what it allows.
  const bp::ResampleGrid capped =
    bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1 }, 1e12, { 0, 0, 0 }, false, 1e6);
  EXPECT_NEAR(double(capped.pointCount()), 1e6, 0.05e6);
}

TEST(ResampleGrid, AThinMeshKeepsToTheCapAndAMultipleOfItsCells)
{
  // Issue 38: a slab of 40,000 hexahedra over 1 x 1 x 1e-5 got 1587 x 1587 x 8
  // = 20.1 M points (500 times its cells, above the cap) and no word.
  const bp::ResampleGrid slab = bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1e-5 }, 40000, { 0, 0, 0 });
  ASSERT_TRUE(slab.error.empty()) << slab.error;
  EXPECT_EQ(slab.dims[2], bp::MinAutomaticResampleAxisPoints);
  EXPECT_LE(double(slab.pointCount()), 8.0 * 40000);
  EXPECT_GE(slab.dims[0], 190); // the slab's own 200 x 200 cells in the plane
  EXPECT_NEAR(slab.spacing[0] / slab.spacing[1], 1.0, 0.02);
  EXPECT_NE(slab.note.find("thin along Z"), std::string::npos) << slab.note;
  EXPECT_NE(slab.note.find("Resample Dimensions"), std::string::npos) << slab.note;
  // A mesh that is not thin chooses freely and says nothing.
  EXPECT_TRUE(bp::chooseResampleGrid({ 0, 4, 0, 2, 0, 1 }, 1e6, { 0, 0, 0 }).note.empty());

  // Every aspect ratio, thin along one, two or no axes, flat axes included,
  // small and huge meshes: within the cap, at most 8 times the cells for each
  // thin axis (or the fewest points a grid of 8 per axis has), at least 8
  // points along each axis with extent.
  const double cap = double(bp::MaxAutomaticResamplePoints);
  for (double cells : { 10.0, 4e4, 1e6, 1e8, 1e12 })
    for (double y : { 1.0, 1e-2, 1e-5, 0.0 })
      for (double z : { 1.0, 1e-3, 1e-5, 1e-8, 0.0 })
      {
        const bp::ResampleGrid g = bp::chooseResampleGrid({ 0, 1, 0, y, 0, z }, cells, { 0, 0, 0 });
        ASSERT_TRUE(g.error.empty()) << g.error;
        int thin = 0, spanning = 0;
        for (int a = 0; a < 3; ++a)
        {
          if (g.dims[a] > 1)
          {
            ++spanning;
            EXPECT_GE(g.dims[a], bp::MinAutomaticResampleAxisPoints);
            thin += g.dims[a] == bp::MinAutomaticResampleAxisPoints ? 1 : 0;
          }
        }
        const double points = double(g.pointCount());
        const double floor = std::pow(double(bp::MinAutomaticResampleAxisPoints), spanning);
        EXPECT_LE(points, std::max(cap, floor)) << cells << " cells, " << y << " x " << z;
        EXPECT_LE(points, std::max(1.1 * std::pow(8.0, thin) * std::min(cells, cap), floor))
          << cells << " cells, " << y << " x " << z;
        if (cells > cap)
        {
          EXPECT_FALSE(g.note.empty()) << "a mesh coarsened to the cap says so";
        }
      }
  // Where memory allows less, the thin slab keeps to that too.
  const bp::ResampleGrid short_ =
    bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1e-5 }, 4e6, { 0, 0, 0 }, false, 1e6);
  EXPECT_LE(double(short_.pointCount()), 1e6);
  EXPECT_NE(short_.note.find("coarsened"), std::string::npos) << short_.note;
}

TEST(ResampleGrid, UnusableBoundsAndRequestsAreRefusedWithAReason)
{
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(bp::chooseResampleGrid({ 1, 0, 1, 0, 1, 0 }, 10, { 0, 0, 0 }).error.empty());
  EXPECT_FALSE(bp::chooseResampleGrid({ 0, inf, 0, 1, 0, 1 }, 10, { 0, 0, 0 }).error.empty());
  EXPECT_FALSE(bp::chooseResampleGrid({ 2, 2, 2, 2, 2, 2 }, 10, { 0, 0, 0 }).error.empty());
  EXPECT_FALSE(bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1 }, 10, { 1, 0, 0 }).error.empty());
  const bp::ResampleGrid big =
    bp::chooseResampleGrid({ 0, 1, 0, 1, 0, 1 }, 10, { 100000, 100000, 100000 });
  EXPECT_NE(big.error.find("more than"), std::string::npos);
}
} // namespace
