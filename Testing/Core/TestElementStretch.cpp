// SPDX-License-Identifier: BSD-3-Clause
// The element stretch fit (Core/Elements/ElementStretch.h): a known linear map applied
// to every built-in template is recovered; flat templates are measured in
// their own plane; one particle, coincident particles and non-finite
// positions give finite values; the FTLE and the element's age.
#include "ElementStretch.h"
#include "Quaternion.h"
#include "TestHelpers.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
Eigen::Matrix3d rotation(float u1, float u2, float u3)
{
  const std::array<float, 4> q = bp::quaternionFromUniforms(u1, u2, u3);
  float R[9];
  bp::quaternionToMatrix(q.data(), R);
  Eigen::Matrix3d M;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      M(r, c) = R[3 * r + c];
  return M;
}

/// The template's rest positions scaled by `size`, mapped by G and moved by t.
std::vector<float> mapped(
  const bp::ElementTemplate& shape, double size, const Eigen::Matrix3d& G, Eigen::Vector3d t)
{
  std::vector<float> p;
  for (const auto& r : shape.rest)
  {
    const Eigen::Vector3d x = G * (Eigen::Vector3d(r[0], r[1], r[2]) * size) + t;
    p.insert(p.end(), { float(x[0]), float(x[1]), float(x[2]) });
  }
  return p;
}

/// An orthonormal basis of the directions the template spans, as columns
/// (from its points directly: the cross products of its differences).
Eigen::MatrixXd spanOf(const bp::ElementTemplate& shape)
{
  Eigen::MatrixXd D(3, shape.rest.size());
  for (std::size_t i = 0; i < shape.rest.size(); ++i)
    for (int k = 0; k < 3; ++k)
      D(k, Eigen::Index(i)) = shape.rest[i][std::size_t(k)] - shape.rest[0][std::size_t(k)];
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(D, Eigen::ComputeFullU);
  int rank = 0;
  for (Eigen::Index k = 0; k < svd.singularValues().size(); ++k)
    rank += svd.singularValues()[k] > 1e-6 * svd.singularValues()[0];
  return svd.matrixU().leftCols(rank);
}
} // namespace

// G = R2 diag(2, 0.5, 1.3) R1 on every built-in template: a solid one's
// stretches are 2 and 0.5; a flat or straight one's are G's singular values
// over its own span, computed here from its points with Eigen's SVD.
TEST(ElementStretch, RecoversAKnownMapOnEveryBuiltinTemplate)
{
  const Eigen::Matrix3d G = rotation(0.3f, 0.7f, 0.2f) *
    Eigen::Vector3d(2.0, 0.5, 1.3).asDiagonal() * rotation(0.9f, 0.1f, 0.6f);
  for (int s = 0; s < bp::enumCount<bp::BuiltinShape>(); ++s)
  {
    const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape(s));
    SCOPED_TRACE(shape.name);
    const double size = 0.05;
    const bp::StretchFit fit(shape.rest, size);
    const Eigen::MatrixXd U = spanOf(shape);
    EXPECT_EQ(fit.span(), int(U.cols()));
    const std::array<float, 2> got = fit.stretch(mapped(shape, size, G, { 3, -2, 7 }).data());
    if (U.cols() == 0)
    {
      EXPECT_EQ(got[0], 1.0f);
      EXPECT_EQ(got[1], 1.0f);
      continue;
    }
    const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(G * U).singularValues();
    if (U.cols() == 3)
    {
      EXPECT_NEAR(sv[0], 2.0, 1e-6);
      EXPECT_NEAR(sv[2], 0.5, 1e-6);
    }
    EXPECT_NEAR(got[0], sv[0], 1e-5 * sv[0]);
    EXPECT_NEAR(got[1], sv[U.cols() - 1], 1e-5 * sv[0]);
    // A rotation alone stretches nothing.
    const std::array<float, 2> turned =
      fit.stretch(mapped(shape, size, rotation(0.4f, 0.8f, 0.5f), { 1, 1, 1 }).data());
    EXPECT_NEAR(turned[0], 1.0, 1e-5);
    EXPECT_NEAR(turned[1], 1.0, 1e-5);
  }
}

// A flat template stretched only across its plane is not stretched at all.
TEST(ElementStretch, AFlatTemplateIgnoresWhatHappensOffItsPlane)
{
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const bp::StretchFit fit(cross.rest, 1.0);
  ASSERT_EQ(fit.span(), 2);
  const Eigen::MatrixXd U = spanOf(cross);
  const Eigen::Vector3d u0 = U.col(0), u1 = U.col(1);
  const Eigen::Vector3d normal = u0.cross(u1).normalized();
  const Eigen::Matrix3d G = Eigen::Matrix3d::Identity() + 4.0 * normal * normal.transpose();
  const std::array<float, 2> got = fit.stretch(mapped(cross, 1.0, G, { 0, 0, 0 }).data());
  EXPECT_NEAR(got[0], 1.0, 1e-5);
  EXPECT_NEAR(got[1], 1.0, 1e-5);
}

TEST(ElementStretch, DegenerateCasesStayFinite)
{
  // One particle: nothing to stretch.
  const bp::ElementTemplate point = bp::builtinTemplate(bp::BuiltinShape::Point);
  const bp::StretchFit one(point.rest, 0.1);
  const float p[3] = { 5, 6, 7 };
  EXPECT_EQ(one.stretch(p)[0], 1.0f);
  EXPECT_EQ(one.stretch(p)[1], 1.0f);
  // A template whose particles coincide spans nothing either.
  const std::vector<std::array<float, 3>> same(4, { 0.2f, 0.2f, 0.2f });
  const bp::StretchFit coincident(same, 1.0);
  EXPECT_EQ(coincident.span(), 0);
  const std::vector<float> q(12, 1.0f);
  EXPECT_EQ(coincident.stretch(q.data())[0], 1.0f);
  // An element collapsed to a point: stretches 0, and an FTLE of 0, not -inf.
  const bp::ElementTemplate tet = bp::builtinTemplate(bp::BuiltinShape::Tetrahedron);
  const bp::StretchFit fit(tet.rest, 0.1);
  const std::vector<float> collapsed(3 * tet.rest.size(), 2.0f);
  const std::array<float, 2> s = fit.stretch(collapsed.data());
  EXPECT_EQ(s[0], 0.0f);
  EXPECT_EQ(s[1], 0.0f);
  EXPECT_EQ(bp::elementFtle(s[0], 3.0), 0.0f);
  // Non-finite positions: (1, 1).
  std::vector<float> bad = mapped(tet, 0.1, Eigen::Matrix3d::Identity(), { 0, 0, 0 });
  bad[4] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(fit.stretch(bad.data())[0], 1.0f);
  EXPECT_EQ(fit.stretch(bad.data())[1], 1.0f);
}

TEST(ElementStretch, FtleIsTheLogOfTheStretchOverTheAge)
{
  EXPECT_NEAR(bp::elementFtle(std::exp(2.0f), 2.0), 1.0, 1e-6);
  EXPECT_NEAR(bp::elementFtle(0.5f, 4.0), std::log(0.5) / 4.0, 1e-7);
  EXPECT_EQ(bp::elementFtle(3.0f, 0.0), 0.0f);
  EXPECT_EQ(bp::elementFtle(3.0f, -1.0), 0.0f);
  EXPECT_EQ(bp::elementFtle(3.0f, std::numeric_limits<double>::quiet_NaN()), 0.0f);
  EXPECT_EQ(bp::elementFtle(std::numeric_limits<float>::infinity(), 1.0), 0.0f);
}

// Every element's drawn lifetime is the one it was placed with, and its age
// (drawn less remaining) grows by the steps taken, across generations.
TEST(ElementStretch, DrawnLifetimeLessTheRemainingIsTheAge)
{
  const bp::VectorField field =
    bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, bptest::grid(17));
  bp::Parameters p;
  p.numberOfElements = 64;
  p.elementSize = 0.1f;
  p.emitterMin = { -0.5f, -0.5f, -0.5f };
  p.emitterMax = { 0.5f, 0.5f, 0.5f };
  p.lifetimeMin = 0.2f;
  p.lifetimeMax = 0.6f;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Tetrahedron), p), "");
  engine.initialize(bp::serialRunner());
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
    EXPECT_EQ(engine.drawnLifetime(e), engine.lifetimes()[e]);
  const double h = 0.01;
  std::vector<int> steps(p.numberOfElements, 0);
  int renewed = 0;
  for (int s = 0; s < 100; ++s)
  {
    std::vector<std::uint32_t> before = engine.generations();
    engine.step(field, s * h, h, bp::serialRunner());
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      // A new generation is placed at the start of a step, then stepped once.
      steps[e] = engine.generations()[e] == before[e] ? steps[e] + 1 : 1;
      renewed += engine.generations()[e] != before[e];
      const double age = engine.drawnLifetime(e) - engine.lifetimes()[e];
      ASSERT_NEAR(age, steps[e] * h, 1e-5) << "element " << e << " step " << s;
    }
  }
  EXPECT_GT(renewed, int(p.numberOfElements)); // every element lived several lives
}

// What the GPU display's draw shader fits against: the rest offsets about
// their mean at the element size, and Aqq^+ (symmetric, a projector onto the
// span when multiplied by Aqq).
TEST(ElementStretch, TheFitsTablesAreTheTemplatesMoments)
{
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const double size = 0.25;
  const bp::StretchFit fit(cross.rest, size);
  ASSERT_EQ(fit.centred().size(), cross.rest.size());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d Aqq = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < cross.rest.size(); ++i)
  {
    const auto& q = fit.centred()[i];
    const Eigen::Vector3d v(q[0], q[1], q[2]);
    sum += v;
    Aqq += v * v.transpose();
  }
  EXPECT_LT(sum.norm(), 1e-12);
  // Offsets between particles are the template's, scaled.
  EXPECT_NEAR(fit.centred()[1][0] - fit.centred()[0][0],
    size * (double(cross.rest[1][0]) - double(cross.rest[0][0])), 1e-12);
  const Eigen::Matrix3d B =
    Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(fit.restMomentPseudoInverse());
  EXPECT_LT((B - B.transpose()).norm(), 1e-9 * B.norm());
  const Eigen::Matrix3d P = B * Aqq; // the projector onto the span: trace = span
  EXPECT_NEAR(P.trace(), 2.0, 1e-9);
  EXPECT_LT((P * P - P).norm(), 1e-9);
}
