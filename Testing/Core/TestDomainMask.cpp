// SPDX-License-Identifier: BSD-3-Clause
// Points outside the flow's domain (vtkValidPointMask 0, NaN vectors): the
// cells they spoil, and what the engine does with elements there and with
// releases where the flow stands still.
#include "DomainMask.h"
#include "Engine.h"
#include "TestHelpers.h"

#include <cstdint>
#include <gtest/gtest.h>

#include <cmath>

namespace
{
std::size_t pointId(const bp::GridGeometry& g, int i, int j, int k)
{
  return std::size_t(i) + std::size_t(g.dims[0]) * (std::size_t(j) + std::size_t(g.dims[1]) * k);
}

std::vector<float> uniformVelocity(const bp::GridGeometry& g, float vx)
{
  std::vector<float> v(3 * g.pointCount(), 0.0f);
  for (std::size_t i = 0; i < g.pointCount(); ++i)
    v[3 * i] = vx;
  return v;
}

bp::Parameters oneElementAt(float x)
{
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.2f;
  p.emitterMin = { x, 0, 0 };
  p.emitterMax = { x, 0, 0 };
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = 1000.0f;
  return p;
}
} // namespace

TEST(DomainMask, MarksEveryCellAroundAnOutsidePointAndZeroesIt)
{
  bp::GridGeometry g;
  g.dims = { 4, 3, 2 };
  std::vector<float> v(3 * g.pointCount(), 1.0f);
  v[3 * pointId(g, 2, 1, 1) + 1] = NAN;
  std::vector<std::uint8_t> valid(g.pointCount(), 1);
  valid[pointId(g, 0, 0, 0)] = 0;
  const bp::DomainMask mask = bp::maskOutsidePoints(g, v, valid.data());
  EXPECT_EQ(mask.outsidePoints, 2u);
  EXPECT_EQ(mask.nonFinitePoints, 1u);
  ASSERT_TRUE(mask.outsideCells);
  // Point (2, 1, 1) is a corner of the cells starting at x 1-2, y 0-1, z 0;
  // point (0, 0, 0) of the cell starting there.
  std::size_t marked = 0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
      {
        const bool expected =
          (i >= 1 && i <= 2 && j <= 1 && k == 0) || (i == 0 && j == 0 && k == 0);
        EXPECT_EQ((*mask.outsideCells)[pointId(g, i, j, k)], expected ? 1 : 0) << i << j << k;
        marked += expected;
      }
  EXPECT_EQ(marked, 5u);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(v[3 * pointId(g, 2, 1, 1) + c], 0.0f);
    EXPECT_EQ(v[3 * pointId(g, 0, 0, 0) + c], 0.0f);
  }
  EXPECT_EQ(v[3 * pointId(g, 1, 1, 1)], 1.0f);
}

TEST(DomainMask, NothingOutsideGivesNoMask)
{
  bp::GridGeometry g = bptest::grid(3);
  std::vector<float> v(3 * g.pointCount(), 0.5f);
  const bp::DomainMask mask = bp::maskOutsidePoints(g, v, nullptr);
  EXPECT_FALSE(mask.outsideCells);
  EXPECT_EQ(mask.outsidePoints, 0u);
}

TEST(DomainMask, APlaneMarksItsOneLayerOfCells)
{
  bp::GridGeometry g = bptest::grid(5, -1.0, 1.0, 1); // z flat
  std::vector<float> v(3 * g.pointCount(), 1.0f);
  v[3 * pointId(g, 4, 4, 0)] = INFINITY;
  const bp::DomainMask mask = bp::maskOutsidePoints(g, v, nullptr);
  ASSERT_TRUE(mask.outsideCells);
  EXPECT_EQ((*mask.outsideCells)[pointId(g, 3, 3, 0)], 1);
  const bp::VectorField field(
    g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(v), mask.outsideCells });
  const float corner[3] = { 0.9f, 0.9f, 0.0f }, middle[3] = { 0.0f, 0.0f, 0.0f };
  EXPECT_TRUE(field.outsideCellAt(corner, 0.0f));
  EXPECT_FALSE(field.outsideCellAt(middle, 0.0f));
}

TEST(DomainMask, AMaskWithOneValidPointOrFlippingHalvesLeavesNoCell)
{
  const bp::GridGeometry g = bptest::grid(4);
  auto field = [&](const std::vector<std::uint8_t>& first, const std::vector<std::uint8_t>& second)
  {
    bp::FieldSlice slices[2];
    const std::vector<std::uint8_t>* valid[2] = { &first, &second };
    for (int s = 0; s < 2; ++s)
    {
      std::vector<float> v = uniformVelocity(g, 1.0f);
      const bp::DomainMask mask = bp::maskOutsidePoints(g, v, valid[s]->data());
      slices[s] =
        bp::FieldSlice{ double(s), std::make_shared<std::vector<float>>(v), mask.outsideCells };
    }
    return bp::VectorField(g, slices[0], slices[1]);
  };
  auto leavesNoCell = [&](const bp::VectorField& f) {
    return bp::leavesNoCell(bp::ReleaseMask{ g, bp::releaseUnfitCells(f, 0.0f) });
  };
  std::vector<std::uint8_t> all(g.pointCount(), 1), one(g.pointCount(), 0);
  one[pointId(g, 1, 1, 1)] = 1;
  EXPECT_FALSE(leavesNoCell(field(all, all)));
  EXPECT_TRUE(leavesNoCell(field(one, one)));
  // Valid in the lower half of x, then in the upper: no cell in both.
  std::vector<std::uint8_t> lower(g.pointCount(), 0), upper(g.pointCount(), 0);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        (i < 2 ? lower : upper)[pointId(g, i, j, k)] = 1;
  EXPECT_FALSE(leavesNoCell(field(lower, lower)));
  EXPECT_TRUE(leavesNoCell(field(lower, upper)));
}

TEST(VectorField, TheSecondTimeStepsOutsideCellsCountOnlyWhereItWeighs)
{
  bp::GridGeometry g = bptest::grid(5);
  auto plain = std::make_shared<std::vector<float>>(uniformVelocity(g, 1.0f));
  auto holed = std::make_shared<std::vector<float>>(*plain);
  (*holed)[3 * pointId(g, 2, 2, 2)] = NAN;
  const bp::DomainMask mask = bp::maskOutsidePoints(g, *holed, nullptr);
  const bp::VectorField field(
    g, bp::FieldSlice{ 0.0, plain, nullptr }, bp::FieldSlice{ 1.0, holed, mask.outsideCells });
  const float nearHole[3] = { 0.1f, 0.1f, 0.1f };
  EXPECT_FALSE(field.outsideCellAt(nearHole, 0.0f));
  EXPECT_TRUE(field.outsideCellAt(nearHole, 0.25f));
  float v[3];
  field.sample(nearHole, 1.0, v);
  EXPECT_TRUE(std::isfinite(v[0]));
}

TEST(Engine, AnElementEnteringACellOutsideTheDomainIsReleasedAgain)
{
  // Uniform flow along +x on [-1, 1]^3 with the points at x = 1 outside:
  // the last layer of cells (x from 0.5) is outside the domain.
  bp::GridGeometry g = bptest::grid(5);
  auto v = std::make_shared<std::vector<float>>(uniformVelocity(g, 1.0f));
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      (*v)[3 * pointId(g, 4, j, k)] = NAN;
  const bp::DomainMask mask = bp::maskOutsidePoints(g, *v, nullptr);
  const bp::VectorField field(g, bp::FieldSlice{ 0.0, v, mask.outsideCells });
  bp::Engine engine;
  ASSERT_EQ(
    engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), oneElementAt(0.0f)), "");
  engine.initialize(bp::serialRunner());
  int steps = 0;
  while (!engine.resetFlags()[0] && steps < 200)
  {
    engine.step(field, steps * 0.01, 0.01, bp::serialRunner());
    ++steps;
  }
  // The centre left at x = 0.5, well before the grid's bound at x = 1.
  EXPECT_NEAR(steps * 0.01, 0.5, 0.011);
}

TEST(Engine, ReleasesWhereTheFlowStandsStillAreReleasedAgain)
{
  bp::GridGeometry g = bptest::grid(5);
  const bp::VectorField still(
    g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(uniformVelocity(g, 0.0f)) });
  const bp::VectorField moving(
    g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(uniformVelocity(g, 0.1f)) });
  for (const float minimum : { 0.0f, 0.05f })
  {
    bp::Parameters p = oneElementAt(-0.5f);
    p.releaseMinSpeed = minimum;
    bp::Engine atRest, carried;
    ASSERT_EQ(atRest.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
    ASSERT_EQ(carried.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
    atRest.initialize(bp::serialRunner());
    carried.initialize(bp::serialRunner());
    for (int s = 0; s < 3; ++s)
    {
      atRest.step(still, s * 0.01, 0.01, bp::serialRunner());
      carried.step(moving, s * 0.01, 0.01, bp::serialRunner());
      // In still flow every release is retried at the next step; in flow
      // faster than the minimum, none is.
      EXPECT_EQ(atRest.resetFlags()[0], minimum > 0.0f ? 1 : 0) << "step " << s;
      EXPECT_EQ(atRest.generations()[0], minimum > 0.0f ? std::uint32_t(s) : 0u);
      EXPECT_EQ(carried.resetFlags()[0], 0);
    }
  }
}

TEST(Engine, OnlyTheFirstStepAfterAReleaseIsTestedForStagnation)
{
  // A flow that stops after the element's first step does not release it again.
  bp::GridGeometry g = bptest::grid(5);
  const bp::VectorField moving(
    g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(uniformVelocity(g, 0.1f)) });
  const bp::VectorField still(
    g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(uniformVelocity(g, 0.0f)) });
  bp::Parameters p = oneElementAt(-0.5f);
  p.releaseMinSpeed = 0.05f;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.initialize(bp::serialRunner());
  engine.step(moving, 0.0, 0.01, bp::serialRunner());
  for (int s = 1; s < 4; ++s)
  {
    engine.step(still, s * 0.01, 0.01, bp::serialRunner());
    EXPECT_EQ(engine.resetFlags()[0], 0) << "step " << s;
  }
}

TEST(DomainMask, ReleasesAvoidCellsOutsideTheDomainAndStagnantOnes)
{
  // x < 0 still, x >= 0 moving; the points at x = 1 outside.
  bp::GridGeometry g = bptest::grid(5);
  auto v = std::make_shared<std::vector<float>>(3 * g.pointCount(), 0.0f);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 2; i < 5; ++i)
        (*v)[3 * pointId(g, i, j, k)] = i == 4 ? NAN : 1.0f;
  const bp::DomainMask mask = bp::maskOutsidePoints(g, *v, nullptr);
  const bp::VectorField field(g, bp::FieldSlice{ 0.0, v, mask.outsideCells });
  const auto unfit = bp::releaseUnfitCells(field, 0.5f);
  ASSERT_TRUE(unfit);
  for (int i = 0; i < 4; ++i)
  {
    // Cell 0 has no moving corner; cell 1 has (x = 0); cell 3 touches x = 1.
    const bool expected = i == 0 || i == 3;
    EXPECT_EQ((*unfit)[pointId(g, i, 2, 2)], expected ? 1 : 0) << "cell " << i;
  }
  EXPECT_FALSE(bp::releaseUnfitCells(
    bp::VectorField(
      g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(uniformVelocity(g, 1.0f)) }),
    0.5f));

  // Every release lands in a fit cell: x in [-0.5, 0.5).
  bp::Parameters p;
  p.numberOfElements = 500;
  p.elementSize = 0.1f;
  p.emitterMin = { -1, -1, -1 };
  p.emitterMax = { 1, 1, 1 };
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.setReleaseMask(g, unfit);
  engine.initialize(bp::serialRunner());
  int outsideFit = 0;
  for (std::size_t e = 0; e < 500; ++e)
  {
    const float x = engine.initialCenters()[3 * e];
    outsideFit += !(x >= -0.5f && x <= 0.5f);
  }
  EXPECT_EQ(outsideFit, 0);
  // Without the mask, three quarters of the box would take them.
  engine.setReleaseMask(g, nullptr);
  engine.initialize(bp::serialRunner());
  int spread = 0;
  for (std::size_t e = 0; e < 500; ++e)
    spread += std::abs(engine.initialCenters()[3 * e]) > 0.5f;
  EXPECT_GT(spread, 150);
}
