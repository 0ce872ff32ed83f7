// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceRelease.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{

/// The unit square z = 0 cut into `bands` strips along x, two triangles each,
/// normals +z (counter-clockwise seen from +z).
std::vector<double> strips(int bands)
{
  std::vector<double> t;
  for (int i = 0; i < bands; ++i)
  {
    const double x0 = double(i) / bands, x1 = double(i + 1) / bands;
    t.insert(t.end(), { x0, 0, 0, x1, 0, 0, x1, 1, 0 });
    t.insert(t.end(), { x0, 0, 0, x1, 1, 0, x0, 1, 0 });
  }
  return t;
}

/// u = (0.3, 0, 1 + 3x): the flux through the square's strip [x0, x1] is
/// the integral of 1 + 3x, exact at each triangle's centroid.
bp::SurfaceVelocity linearFlow()
{
  return [](const std::array<double, 3>& x, double u[3])
  {
    u[0] = 0.3;
    u[1] = 0.0;
    u[2] = 1.0 + 3.0 * x[0];
    return true;
  };
}

TEST(SurfaceRelease, TriangleAreaNormalAndCentroid)
{
  const double t[9] = { 0, 0, 0, 2, 0, 0, 0, 3, 0 };
  EXPECT_DOUBLE_EQ(bp::triangleArea(t), 3.0);
  EXPECT_EQ(bp::triangleNormal(t), (std::array<double, 3>{ 0, 0, 1 }));
  EXPECT_EQ(bp::triangleCentroid(t), (std::array<double, 3>{ 2.0 / 3.0, 1.0, 0.0 }));
  // Its own orientation: the corners the other way round face -z.
  const double back[9] = { 0, 0, 0, 0, 3, 0, 2, 0, 0 };
  EXPECT_EQ(bp::triangleNormal(back)[2], -1.0);
  const double line[9] = { 0, 0, 0, 1, 1, 1, 2, 2, 2 };
  EXPECT_EQ(bp::triangleArea(line), 0.0);
  EXPECT_EQ(bp::triangleNormal(line), (std::array<double, 3>{ 0, 0, 0 }));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double broken[9] = { 0, 0, 0, nan, 0, 0, 0, 3, 0 };
  EXPECT_EQ(bp::triangleArea(broken), 0.0);
}

TEST(SurfaceRelease, FluxWeightIsTheNormalFlowTimesTheArea)
{
  const double t[9] = { 0, 0, 0, 2, 0, 0, 0, 3, 0 }; // area 3, normal +z
  const double along[3] = { 5, -7, 2 };
  EXPECT_DOUBLE_EQ(bp::fluxWeight(t, along, false), 6.0); // the tangential part counts nothing
  EXPECT_EQ(bp::fluxWeight(t, along, true), 0.0);         // out of the flipped side
  const double against[3] = { 0, 0, -2 };
  EXPECT_EQ(bp::fluxWeight(t, against, false), 0.0);
  EXPECT_DOUBLE_EQ(bp::fluxWeight(t, against, true), 6.0);
  const double parallel[3] = { 1, 1, 0 };
  EXPECT_EQ(bp::fluxWeight(t, parallel, false), 0.0);
  const double nan[3] = { 0, 0, std::numeric_limits<double>::quiet_NaN() };
  EXPECT_EQ(bp::fluxWeight(t, nan, false), 0.0);
}

TEST(SurfaceRelease, WeightsAndSummary)
{
  std::vector<double> t = strips(2); // 4 triangles of area 1/4
  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.insert(t.end(), { 0, 0, 0, nan, 0, 0, 0, 1, 0 }); // not finite
  t.insert(t.end(), { 0, 0, 0, 1, 0, 0, 2, 0, 0 });   // no area
  // No velocity left of x = 0.5 (outside the field there).
  const bp::SurfaceVelocity half = [](const std::array<double, 3>& x, double u[3])
  {
    u[0] = u[1] = 0.0;
    u[2] = 2.0;
    return x[0] > 0.5;
  };
  const std::vector<double> w = bp::surfaceWeights(t, half, false);
  ASSERT_EQ(w.size(), 6u);
  EXPECT_EQ(w[0], bp::NoVelocity);
  EXPECT_EQ(w[1], bp::NoVelocity);
  EXPECT_DOUBLE_EQ(w[2], 0.5);
  EXPECT_DOUBLE_EQ(w[3], 0.5);
  EXPECT_EQ(w[4], 0.0);
  EXPECT_EQ(w[5], 0.0);
  const bp::SurfaceSummary s = bp::summarizeSurface(t, w);
  EXPECT_EQ(s.triangles, 6u);
  EXPECT_EQ(s.nonFinite, 1u);
  EXPECT_EQ(s.noArea, 1u);
  EXPECT_EQ(s.noVelocity, 2u);
  EXPECT_EQ(s.crossing, 2u);
  EXPECT_DOUBLE_EQ(s.area, 1.0);
  EXPECT_DOUBLE_EQ(s.total, 1.0);
  EXPECT_EQ(bp::surfaceProblem(s, false), "");
}

TEST(SurfaceRelease, ProblemsSayWhyNothingIsReleased)
{
  auto problem = [](const std::vector<double>& t, const bp::SurfaceVelocity& v, bool flip)
  {
    std::vector<double> against;
    const std::vector<double> w = bp::surfaceWeights(t, v, flip, 0.0, {}, &against);
    return bp::surfaceProblem(bp::summarizeSurface(t, w, against), flip);
  };
  EXPECT_NE(problem({}, linearFlow(), false).find("no surface with area"), std::string::npos);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(problem({ nan, 0, 0, 1, 0, 0, 0, 1, 0 }, linearFlow(), false).find("not finite"),
    std::string::npos);
  EXPECT_NE(problem({ 0, 0, 0, 1, 0, 0, 2, 0, 0 }, linearFlow(), false).find("has no area"),
    std::string::npos);
  const bp::SurfaceVelocity none = [](const std::array<double, 3>&, double*) { return false; };
  EXPECT_NE(problem(strips(3), none, false).find("outside the field"), std::string::npos);
  // The flow leaves through the side the normals point away from.
  const std::string against = problem(strips(3), linearFlow(), true);
  EXPECT_NE(against.find("No flow crosses"), std::string::npos);
  EXPECT_NE(against.find("The flow crosses it the other way (a flux of 2.5 against its flipped "
                         "normals). Unset the Surface's Flip Normals"),
    std::string::npos);
  const bp::SurfaceVelocity along = [](const std::array<double, 3>&, double u[3])
  {
    u[0] = 1.0;
    u[1] = u[2] = 0.0;
    return true;
  };
  const std::string parallel = problem(strips(3), along, false);
  EXPECT_NE(parallel.find("each of its 6 triangles in the flow"), std::string::npos);
  EXPECT_NE(parallel.find("No flow crosses it the other way either"), std::string::npos);
  EXPECT_EQ(parallel.find("Flip Normals"), std::string::npos);
  const std::string unflipped = problem(strips(3), along, true);
  EXPECT_NE(unflipped.find("along its flipped normals"), std::string::npos);
  EXPECT_EQ(problem(strips(3), linearFlow(), false), "");
}

TEST(SurfaceRelease, PickNeverTakesATriangleOfWeightZero)
{
  const std::vector<double> cumulative = { 0, 0, 2, 2, 3, 3 }; // weights 0 0 2 0 1 0
  EXPECT_EQ(bp::pickWeighted(cumulative, 0.0), 2u);
  EXPECT_EQ(bp::pickWeighted(cumulative, 0.6), 2u);
  EXPECT_EQ(bp::pickWeighted(cumulative, 2.0 / 3.0), 4u);
  EXPECT_EQ(bp::pickWeighted(cumulative, std::nextafter(1.0, 0.0)), 4u);
  EXPECT_EQ(bp::pickWeighted(cumulative, 1.0), 4u); // rounded up to the total
  EXPECT_EQ(bp::pickWeighted({ 0, 0 }, 0.5), 2u);
  EXPECT_EQ(bp::pickWeighted({}, 0.5), 0u);
}

TEST(SurfaceRelease, PointInTriangleIsUniform)
{
  const double t[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  EXPECT_EQ(bp::pointInTriangle(t, 0.0, 0.7), (std::array<double, 3>{ 0, 0, 0 }));
  EXPECT_EQ(bp::pointInTriangle(t, 1.0, 0.0), (std::array<double, 3>{ 1, 0, 0 }));
  EXPECT_EQ(bp::pointInTriangle(t, 1.0, 1.0), (std::array<double, 3>{ 0, 1, 0 }));
  // Uniform: a quarter of the points in each of the four triangles the
  // edges' midpoints cut it into, and their mean at the centroid.
  const int n = 40000;
  int corner = 0, middle = 0;
  double mean[2] = { 0, 0 };
  for (int i = 0; i < n; ++i)
  {
    const std::array<double, 3> p = bp::pointInTriangle(
      t, bp::surfaceDraw(9, std::uint32_t(i), 1), bp::surfaceDraw(9, std::uint32_t(i), 2));
    ASSERT_GE(p[0], 0.0);
    ASSERT_GE(p[1], 0.0);
    ASSERT_LE(p[0] + p[1], 1.0 + 1e-12);
    corner += p[0] + p[1] < 0.5 ? 1 : 0;
    middle += p[0] < 0.5 && p[1] < 0.5 && p[0] + p[1] >= 0.5 ? 1 : 0;
    mean[0] += p[0] / n;
    mean[1] += p[1] / n;
  }
  // Binomial(40000, 1/4): standard deviation about 87.
  EXPECT_NEAR(corner, n / 4, 5 * 87);
  EXPECT_NEAR(middle, n / 4, 5 * 87);
  EXPECT_NEAR(mean[0], 1.0 / 3.0, 0.01);
  EXPECT_NEAR(mean[1], 1.0 / 3.0, 0.01);
}

TEST(SurfaceRelease, DrawsFollowTheFluxShare)
{
  // Ten strips, the flux through strip i the integral of 1 + 3x over it:
  // its share of the total 2.5. A chi-squared test of the draws' counts.
  const int bands = 10;
  const std::vector<double> t = strips(bands);
  const std::vector<double> w = bp::surfaceWeights(t, linearFlow(), false);
  const std::size_t n = 20000;
  const std::vector<double> xyz = bp::drawSurfacePoints(t, w, 7, n);
  ASSERT_EQ(xyz.size(), 3 * n);
  std::vector<double> counts(bands, 0.0);
  for (std::size_t p = 0; p < n; ++p)
  {
    ASSERT_EQ(xyz[3 * p + 2], 0.0); // on the surface
    ASSERT_GE(xyz[3 * p + 1], 0.0);
    ASSERT_LE(xyz[3 * p + 1], 1.0);
    counts[std::min(bands - 1, int(xyz[3 * p] * bands))] += 1.0;
  }
  double chi2 = 0.0;
  for (int i = 0; i < bands; ++i)
  {
    const double x0 = double(i) / bands, x1 = double(i + 1) / bands;
    const double share = ((x1 - x0) + 1.5 * (x1 * x1 - x0 * x0)) / 2.5;
    const double expected = share * double(n);
    chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
  }
  // 9 degrees of freedom: 27.88 is the 0.1% critical value.
  EXPECT_LT(chi2, 27.88);
  // The last strip takes 3.35 times the first's share (0.385 / 0.115).
  EXPECT_GT(counts[bands - 1], 3.0 * counts[0]);
}

TEST(SurfaceRelease, DrawsAreTheSeedsAndSkipTrianglesWithoutFlux)
{
  const std::vector<double> t = strips(4);
  std::vector<double> w = bp::surfaceWeights(t, linearFlow(), false);
  w[0] = w[1] = 0.0;     // the first strip: no flux
  w[2] = bp::NoVelocity; // half the second: no velocity
  const std::vector<double> a = bp::drawSurfacePoints(t, w, 3, 2000);
  EXPECT_EQ(a, bp::drawSurfacePoints(t, w, 3, 2000));
  EXPECT_NE(a, bp::drawSurfacePoints(t, w, 4, 2000));
  for (std::size_t p = 0; p < a.size() / 3; ++p)
  {
    const double x = a[3 * p], y = a[3 * p + 1];
    ASSERT_GE(x, 0.25);
    ASSERT_FALSE(x < 0.5 && y < x * 4.0 - 1.0 - 1e-12) << "in the triangle with no velocity";
  }
  // A first few points are the first few of more.
  const std::vector<double> few = bp::drawSurfacePoints(t, w, 3, 10);
  EXPECT_TRUE(std::equal(few.begin(), few.end(), a.begin()));
  std::fill(w.begin(), w.end(), 0.0);
  EXPECT_TRUE(bp::drawSurfacePoints(t, w, 3, 10).empty());
}

} // namespace

TEST(SurfaceRelease, SampledIntoTheFlowWhereTheCentroidHasNone)
{
  // A unit square at z = 0, normal +z; velocity only above z = 0.05 (a
  // mesh's side: the cells across it have none), none below.
  const std::vector<double> t = strips(1);
  const bp::SurfaceVelocity above = [](const std::array<double, 3>& x, double u[3])
  {
    u[0] = u[1] = 0.0;
    u[2] = 2.0;
    return x[2] > 0.05;
  };
  EXPECT_EQ(bp::surfaceSides(t, above, false, 0.0), std::vector<int>(2, bp::NoSample));
  EXPECT_EQ(bp::surfaceSides(t, above, false, 0.1), std::vector<int>(2, bp::IntoFlux));
  // Flipped, the flux's side is −z: tried first, then +z.
  EXPECT_EQ(bp::surfaceSides(t, above, true, 0.1), std::vector<int>(2, bp::AgainstFlux));
  EXPECT_DOUBLE_EQ(bp::sideShift(bp::IntoFlux, 0.1, false), 0.1);
  EXPECT_DOUBLE_EQ(bp::sideShift(bp::AgainstFlux, 0.1, true), 0.1);
  EXPECT_DOUBLE_EQ(bp::sideShift(bp::IntoFlux, 0.1, true), -0.1);
  EXPECT_EQ(bp::sideShift(bp::AtCentroid, 0.1, false), 0.0);
  EXPECT_EQ(bp::sideShift(bp::NoSample, 0.1, false), 0.0);
  std::vector<double> against;
  const std::vector<double> w = bp::surfaceWeights(t, above, false, 0.1, {}, &against);
  EXPECT_DOUBLE_EQ(w[0] + w[1], 2.0);
  EXPECT_EQ(against, std::vector<double>(2, 0.0));
  EXPECT_EQ(bp::surfaceWeights(t, above, false), std::vector<double>(2, bp::NoVelocity));
  // The points are put where the velocity was taken: 0.1 up.
  const std::vector<double> shifts(2, bp::sideShift(bp::IntoFlux, 0.1, false));
  const std::vector<double> xyz = bp::drawSurfacePoints(t, w, 3, 50, shifts);
  ASSERT_EQ(xyz.size(), 150u);
  for (std::size_t p = 0; p < 50; ++p)
  {
    EXPECT_NEAR(xyz[3 * p + 2], 0.1, 1e-12);
  }
  // The centroid is kept where it has a velocity.
  const bp::SurfaceVelocity everywhere = [](const std::array<double, 3>&, double u[3])
  {
    u[0] = u[1] = 0.0;
    u[2] = 1.0;
    return true;
  };
  EXPECT_EQ(bp::surfaceSides(t, everywhere, false, 0.1), std::vector<int>(2, bp::AtCentroid));
}

TEST(SurfaceRelease, FluxAgainstTheNormalsIsCountedAndWarned)
{
  // Two strips: along +z through one (x < 1/2), −z three times as fast
  // through the other.
  const std::vector<double> t = strips(2);
  const bp::SurfaceVelocity split = [](const std::array<double, 3>& x, double u[3])
  {
    u[0] = u[1] = 0.0;
    u[2] = x[0] < 0.5 ? 1.0 : -3.0;
    return true;
  };
  std::vector<double> against;
  const std::vector<double> w = bp::surfaceWeights(t, split, false, 0.0, {}, &against);
  const bp::SurfaceSummary s = bp::summarizeSurface(t, w, against);
  EXPECT_DOUBLE_EQ(s.total, 0.5);
  EXPECT_DOUBLE_EQ(s.against, 1.5);
  EXPECT_EQ(bp::surfaceProblem(s, false), "");
  const std::string warning = bp::surfaceWarning(s, false);
  EXPECT_NE(warning.find("a flux of 1.5 against, 0.5 along"), std::string::npos);
  EXPECT_NE(warning.find("set Flip Normals"), std::string::npos);
  // Balanced, as through a closed volume's boundary: no warning.
  const bp::SurfaceVelocity balanced = [](const std::array<double, 3>& x, double u[3])
  {
    u[0] = u[1] = 0.0;
    u[2] = x[0] < 0.5 ? 1.0 : -1.0;
    return true;
  };
  const std::vector<double> b = bp::surfaceWeights(t, balanced, false, 0.0, {}, &against);
  EXPECT_EQ(bp::surfaceWarning(bp::summarizeSurface(t, b, against), false), "");
}
