// SPDX-License-Identifier: BSD-3-Clause
// Release Pattern = Lattice and Release Weights on the CPU engine: where
// releases land (Engine::releaseCenter), against independent expectations.
#include "DomainMask.h"
#include "Engine.h"
#include "ReleaseWeights.h"
#include "Stepper.h"
#include "TestHelpers.h"
#include "TraceSettings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace
{

/// A grid over [0, 1] along x (`nx` points) and [0, 1] along y and z.
bp::GridGeometry unitGrid(int nx, int nz = 2)
{
  bp::GridGeometry g;
  g.dims = { nx, 2, nz };
  g.spacing = { 1.0 / (nx - 1), 1.0, 1.0 };
  return g;
}

bp::Parameters latticeParameters(const bp::ReleaseLattice& lattice)
{
  bp::Parameters p;
  p.releasePattern = bp::ReleasePattern::Lattice;
  p.lattice = lattice;
  p.numberOfElements = lattice.size();
  p.elementSize = 0.05f;
  p.lifetimeMin = 0.5f;
  p.lifetimeMax = 1.5f;
  return p;
}

TEST(ReleasePatterns, LatticeReleasesEveryElementOnItsPoint)
{
  const bp::ReleaseLattice lattice = bp::releaseLattice({ 0, 0, 0 }, { 1, 1, 1 }, 64, 0.0);
  ASSERT_EQ(lattice.size(), 64u);
  bp::Parameters p = latticeParameters(lattice);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  // A uniform drift: elements leave the field and are released again.
  const bp::GridGeometry g = bptest::grid(9, 0.0, 1.0);
  std::vector<float> drift(3 * g.pointCount(), 0.0f);
  for (std::size_t q = 0; q < g.pointCount(); ++q)
    drift[3 * q] = 0.5f, drift[3 * q + 1] = 0.3f;
  const bp::VectorField field(
    g, bp::FieldSlice{ 0.0, std::make_shared<std::vector<float>>(drift), nullptr });
  engine.setReleaseMask(field.grid(), nullptr);
  engine.initialize(bp::serialRunner(), 0.0, &field);
  // 4 x 4 x 4 cells of 0.25: points at 0.125 + 0.25 i.
  for (std::size_t e = 0; e < 64; ++e)
  {
    const float* c = engine.initialCenters().data() + 3 * e;
    const std::size_t i[3] = { e % 4, (e / 4) % 4, e / 16 };
    for (int a = 0; a < 3; ++a)
      EXPECT_FLOAT_EQ(c[a], 0.125f + 0.25f * float(i[a])) << e;
    EXPECT_EQ(engine.resetFlags()[e], 0) << e;
    // One generation, released together: one lifetime.
    EXPECT_EQ(engine.lifetimes()[e], engine.lifetimes()[0]);
  }
  EXPECT_GE(engine.lifetimes()[0], 0.5f);
  // Steps through several lives (resets as elements leave and die): every
  // release is on its element's point again.
  for (int s = 0; s < 40; ++s)
    engine.step(field, 0.1 * s, 0.1, bp::serialRunner());
  int released = 0;
  for (std::size_t e = 0; e < 64; ++e)
  {
    released += engine.generations()[e] > 0;
    const auto x = lattice.point(e);
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(engine.initialCenters()[3 * e + a], x[a]) << e;
  }
  EXPECT_GT(released, 32);
  std::cout << released << " of 64 elements released again\n";
}

TEST(ReleasePatterns, LatticeHidesPointsInUnfitCellsAndOutsideTheWindow)
{
  // Cells with x < 0.5 are unfit.
  const bp::GridGeometry g = unitGrid(5);
  auto unfit = std::make_shared<std::vector<std::uint8_t>>(g.pointCount(), 0);
  for (std::size_t q = 0; q < g.pointCount(); ++q)
    (*unfit)[q] = q % 5 < 2;
  const bp::ReleaseLattice lattice = bp::releaseLattice({ 0, 0, 0 }, { 1, 1, 1 }, 8 * 8 * 8, 0.0);
  bp::Parameters p = latticeParameters(lattice);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.setReleaseMask(g, unfit);
  engine.initialize(bp::serialRunner());
  int hidden = 0;
  for (std::size_t e = 0; e < lattice.size(); ++e)
  {
    const bool masked = lattice.point(e)[0] < 0.5f;
    EXPECT_EQ((engine.resetFlags()[e] & bp::ReleaseHidden) != 0, masked) << e;
    hidden += masked;
  }
  EXPECT_EQ(hidden, 256);
  // Outside the release window every element is placed hidden.
  p.releaseStart = 5.0;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.setReleaseMask(g, nullptr);
  engine.initialize(bp::serialRunner(), 0.0);
  for (std::size_t e = 0; e < lattice.size(); ++e)
    EXPECT_TRUE(engine.resetFlags()[e] & bp::ReleaseHidden) << e;
}

TEST(ReleasePatterns, SettingsMakeAFlatLatticeOnAFlatField)
{
  bp::TraceSettings s;
  s.numberOfElements = 100;
  s.engine.releasePattern = bp::ReleasePattern::Lattice;
  bp::FieldFacts f;
  f.bounds = { 0, 2, 0, 1, 0.5, 0.5 };
  f.dims = { 21, 11, 1 };
  s.emitterSize = { -1, -1, 3 }; // a box off the plane: the lattice stays on it
  bp::Resolution r = bp::resolveSettings(s, f);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.parameters.lattice.counts, (std::array<int, 3>{ 14, 7, 1 }));
  EXPECT_EQ(r.parameters.numberOfElements, 98u);
  EXPECT_EQ(r.parameters.lattice.point(57)[2], 0.5f);
  // A set spacing decides the count.
  s.latticeSpacing = 0.5;
  r = bp::resolveSettings(s, f);
  EXPECT_EQ(r.parameters.numberOfElements, 8u);
  EXPECT_TRUE(r.warnings.empty());
  // A spacing that makes the lattice 100 times the count asked or more is said.
  s.latticeSpacing = 0.01;
  r = bp::resolveSettings(s, f);
  EXPECT_EQ(r.parameters.numberOfElements, 200u * 100u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(
    r.warnings[0].find("LatticeSpacing 0.01 gives a lattice of 20000 points (200 x 100 x 1)"),
    std::string::npos)
    << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("200 times Number Of Elements (100)"), std::string::npos);
  s.latticeSpacing = 0.5;
  // Seed points win, with a warning.
  s.seeded = true;
  r = bp::resolveSettings(s, f);
  EXPECT_EQ(r.parameters.releasePattern, bp::ReleasePattern::Random);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("Lattice is not used"), std::string::npos);
  // Too fine a lattice, and a lattice with Linking, are refused by name.
  s.seeded = false;
  s.latticeSpacing = 1e-4;
  r = bp::resolveSettings(s, f);
  ASSERT_EQ(r.error, "");
  const std::string tooFine =
    bp::Engine::validate(bp::builtinTemplate(bp::BuiltinShape::Strip4), r.parameters);
  EXPECT_NE(tooFine.find("LatticeSpacing"), std::string::npos) << tooFine;
  s.latticeSpacing = 0.0;
  s.engine.linking = bp::Linking::Sheet;
  r = bp::resolveSettings(s, f);
  EXPECT_NE(bp::Engine::validate(bp::builtinTemplate(bp::BuiltinShape::Strip4), r.parameters)
              .find("Linking"),
    std::string::npos);
}

/// Chi-square of 10 bins along x of the release centres against `expected` fractions.
double chiSquare(const bp::Engine& engine, const std::vector<double>& expected)
{
  std::vector<double> counts(10, 0.0);
  const std::size_t n = engine.elementCount();
  for (std::size_t e = 0; e < n; ++e)
  {
    const float x = engine.initialCenters()[3 * e];
    counts[std::size_t(std::min(std::max(int(x * 10.0f), 0), 9))] += 1.0;
  }
  double chi = 0.0;
  for (int b = 0; b < 10; ++b)
  {
    const double m = expected[b] * double(n);
    chi += (counts[b] - m) * (counts[b] - m) / m;
  }
  return chi;
}

TEST(ReleasePatterns, WeightsDrawReleasesInProportion)
{
  // w = x - 0.5 on 11 points over [0, 1]: |w| is linear either side of 0.5,
  // so bin b (of 0.1) takes a share proportional to the integral of |x - 0.5|.
  const bp::GridGeometry g = unitGrid(11);
  auto values = std::make_shared<std::vector<float>>(g.pointCount());
  for (std::size_t q = 0; q < g.pointCount(); ++q)
    (*values)[q] = float(q % 11) * 0.1f - 0.5f;
  std::vector<double> expected(10);
  for (int b = 0; b < 10; ++b)
  {
    auto F = [](double x)
    { return x < 0.5 ? -0.5 * (0.5 - x) * (0.5 - x) : 0.5 * (x - 0.5) * (x - 0.5); };
    expected[b] = (F(0.1 * (b + 1)) - F(0.1 * b)) / 0.25;
  }
  bp::Parameters p;
  p.numberOfElements = 20000;
  p.elementSize = 0.01f;
  bp::FieldSlice slice;
  slice.velocity = std::make_shared<std::vector<float>>(3 * g.pointCount(), 1.0f);
  slice.releaseWeights = std::make_shared<std::vector<float>>(bp::releaseWeightValues(*values, 1));
  bp::CpuStepper stepper(bp::serialRunner());
  ASSERT_EQ(stepper.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  ASSERT_EQ(stepper.setField(bp::VectorField(g, slice)), "");
  stepper.initialize(0.0);
  const bp::Engine& engine = *stepper.particles();
  // 9 degrees of freedom: 99.9% of fair draws stay below 27.9.
  const double weighted = chiSquare(engine, expected);
  std::cout << "chi-square against the weights " << weighted << ", against uniform "
            << chiSquare(engine, std::vector<double>(10, 0.1)) << "\n";
  EXPECT_LT(weighted, 27.9);
  const std::vector<double> uniform(10, 0.1);
  EXPECT_GT(chiSquare(engine, uniform), 1000.0);
  // The same draws without weights: uniform, and as weighted fails there.
  slice.releaseWeights = nullptr;
  slice.velocity = std::make_shared<std::vector<float>>(3 * g.pointCount(), 1.0f);
  ASSERT_EQ(stepper.setField(bp::VectorField(g, slice)), "");
  stepper.initialize(0.0);
  EXPECT_LT(chiSquare(*stepper.particles(), uniform), 27.9);
  EXPECT_GT(chiSquare(*stepper.particles(), expected), 1000.0);
}

TEST(ReleasePatterns, WeightsOfZeroTakeNoReleaseAndBadValuesCountAsZero)
{
  // Weight 0 for x <= 0.4 (NaN and Inf there too), 3 for x >= 0.5.
  const bp::GridGeometry g = unitGrid(11);
  std::vector<float> raw(2 * g.pointCount());
  for (std::size_t q = 0; q < g.pointCount(); ++q)
  {
    const int i = int(q % 11);
    raw[2 * q] = i <= 4 ? (i == 1 ? NAN : i == 2 ? INFINITY : 0.0f) : 3.0f;
    raw[2 * q + 1] = i <= 4 ? 0.0f : 4.0f; // magnitude 5 above
  }
  const auto values = bp::releaseWeightValues(raw, 2);
  EXPECT_EQ(values[1], 0.0f);
  EXPECT_EQ(values[2], 0.0f);
  EXPECT_FLOAT_EQ(values[7], 5.0f);
  const auto weights = bp::releaseWeightsOf(g, std::make_shared<const std::vector<float>>(values));
  ASSERT_TRUE(weights);
  EXPECT_FLOAT_EQ(weights->maximum(), 5.0f);
  bp::Parameters p;
  p.numberOfElements = 5000;
  p.elementSize = 0.01f;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.setReleaseMask(g, nullptr, weights);
  engine.initialize(bp::serialRunner());
  int inZero = 0;
  for (std::size_t e = 0; e < 5000; ++e)
    inZero += engine.initialCenters()[3 * e] < 0.4f;
  EXPECT_EQ(inZero, 0);
  // Every weight 0 (or none finite): no weights, releases uniform.
  EXPECT_FALSE(
    bp::releaseWeightsOf(g, std::make_shared<const std::vector<float>>(g.pointCount(), 0.0f)));
  EXPECT_FALSE(bp::releaseWeightsOf(g, std::make_shared<const std::vector<float>>(3, 1.0f)));
}

TEST(ReleasePatterns, ASmallRegionOfInterestTakesItsReleases)
{
  // A mask of interest: weight 1 at 2 x 2 x 2 points of a 101 x 101 x 101
  // grid over the unit cube (its cells hold about 1e-5 of the box), 0
  // elsewhere. Drawn in the whole box, 64 candidates would all miss it;
  // drawn where the weights may be above 0, every release lands in it.
  bp::GridGeometry g;
  g.dims = { 101, 101, 101 };
  g.spacing = { 0.01, 0.01, 0.01 };
  std::vector<float> values(g.pointCount(), 0.0f);
  for (int k = 60; k <= 61; ++k)
    for (int j = 30; j <= 31; ++j)
      for (int i = 20; i <= 21; ++i)
        values[std::size_t(i + 101 * (j + 101 * k))] = 1.0f;
  const auto weights = bp::releaseWeightsOf(g, std::make_shared<const std::vector<float>>(values));
  ASSERT_TRUE(weights);
  EXPECT_FLOAT_EQ(weights->supportMin()[0], 0.19f);
  EXPECT_FLOAT_EQ(weights->supportMax()[2], 0.62f);
  bp::Parameters p;
  p.numberOfElements = 4000;
  p.elementSize = 0.005f;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.setReleaseMask(g, nullptr, weights);
  engine.initialize(bp::serialRunner());
  int outside = 0;
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
    outside += weights->at(engine.initialCenters().data() + 3 * e) <= 0.0f;
  EXPECT_EQ(outside, 0) << "releases where the weight is 0";
  // An emitter box that misses the weights: drawn in the emitter box.
  float lo[3], hi[3];
  bp::weightedBox({ 0.7f, 0, 0 }, { 0.9f, 1, 1 }, *weights, lo, hi);
  EXPECT_EQ(lo[0], 0.7f);
  EXPECT_EQ(hi[0], 0.9f);
  bp::weightedBox({ 0, 0, 0 }, { 0.2f, 1, 1 }, *weights, lo, hi);
  EXPECT_FLOAT_EQ(lo[0], 0.19f);
  EXPECT_EQ(hi[0], 0.2f);
}

TEST(ReleasePatterns, WeightsHonourTheMask)
{
  // Still flow (speed 0) at x <= 0.4, speed 1 beyond; MinimumReleaseSpeed
  // 0.5 makes cells [0, 0.4] unfit. Weights above 0 only at x <= 0.3: they
  // reach no fit cell, so they are dropped and releases are uniform, over
  // fit cells only (they all landed in the still flow).
  const bp::GridGeometry g = unitGrid(11);
  bp::FieldSlice slice;
  auto velocity = std::make_shared<std::vector<float>>(3 * g.pointCount(), 0.0f);
  std::vector<float> values(g.pointCount(), 0.0f);
  for (std::size_t q = 0; q < g.pointCount(); ++q)
  {
    (*velocity)[3 * q] = q % 11 <= 4 ? 0.0f : 1.0f;
    values[q] = q % 11 <= 3 ? 1.0f : 0.0f;
  }
  slice.velocity = velocity;
  slice.releaseWeights = std::make_shared<const std::vector<float>>(values);
  const bp::VectorField field(g, slice);
  const bp::ReleaseMask mask = bp::releaseMaskOf(field, 0.5f);
  ASSERT_TRUE(mask.unfit);
  EXPECT_FALSE(bp::weightsReachFitCells(g, values, mask.unfit.get()));
  EXPECT_TRUE(bp::weightsReachFitCells(g, values, nullptr));
  EXPECT_FALSE(mask.weights) << "weights only where releases may not land are not used";
  bp::Parameters p;
  p.numberOfElements = 2000;
  p.elementSize = 0.01f;
  p.releaseMinSpeed = 0.5f;
  bp::CpuStepper stepper(bp::serialRunner());
  ASSERT_EQ(stepper.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  ASSERT_EQ(stepper.setField(field), "");
  stepper.initialize(0.0);
  int inStill = 0;
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
    inStill += stepper.particles()->initialCenters()[3 * e] < 0.4f;
  EXPECT_EQ(inStill, 0);
  // One more point of weight reaches a fit cell: the weights are used.
  values[4] = values[15] = values[26] = values[37] = 1.0f; // x = 0.4, every y and z
  EXPECT_TRUE(bp::weightsReachFitCells(g, values, mask.unfit.get()));
}

TEST(ReleasePatterns, AWeightedReleaseWithNoFitCandidateWaitsHidden)
{
  // Weights everywhere, but the emitter box over unfit cells only: no
  // candidate fits, and the element is hidden (due again) instead of shown
  // where the mask forbids.
  const bp::GridGeometry g = unitGrid(11);
  auto unfit = std::make_shared<std::vector<std::uint8_t>>(g.pointCount(), std::uint8_t(0));
  for (int i = 0; i <= 4; ++i)
    (*unfit)[std::size_t(i)] = 1; // cells [0, 0.5] (one cell along y and z)
  const auto weights = bp::releaseWeightsOf(
    g, std::make_shared<const std::vector<float>>(g.pointCount(), 1.0f), unfit.get());
  ASSERT_TRUE(weights);
  bp::Parameters p;
  p.numberOfElements = 200;
  p.elementSize = 0.01f;
  p.emitterMin = { 0.0f, 0.0f, 0.0f };
  p.emitterMax = { 0.3f, 1.0f, 1.0f };
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.setReleaseMask(g, unfit, weights);
  engine.initialize(bp::serialRunner());
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
    EXPECT_TRUE(engine.resetFlags()[e] & bp::ReleaseHidden) << e;
}

TEST(ReleasePatterns, WeightsBeyondFloatScaleByAPowerOfTwo)
{
  EXPECT_EQ(bp::releaseWeightScale(1.0), 1.0);
  EXPECT_EQ(bp::releaseWeightScale(1e18), 1.0);
  EXPECT_EQ(bp::releaseWeightScale(0.0), 1.0);
  EXPECT_EQ(bp::releaseWeightScale(std::numeric_limits<double>::quiet_NaN()), 1.0);
  for (double largest : { 1e39, 1e300, 1e-50, 1e-300 })
  {
    const double scale = bp::releaseWeightScale(largest);
    EXPECT_EQ(std::exp2(std::round(std::log2(scale))), scale) << largest; // a power of two
    EXPECT_GE(largest * scale, 1.0) << largest;
    EXPECT_LT(largest * scale, 2.0) << largest;
    EXPECT_TRUE(std::isfinite(float(largest * scale))) << largest;
  }
}

} // namespace
