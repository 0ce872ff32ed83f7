// SPDX-License-Identifier: BSD-3-Clause
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <random>

namespace
{
/// A field whose trilinear interpolation is exact: v = (1 + x, 2y, 3z - x).
bp::FieldSlice linearSlice(const bp::GridGeometry& g, double time, float offset)
{
  auto v = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        const double x = g.origin[0] + i * g.spacing[0], y = g.origin[1] + j * g.spacing[1],
                     z = g.origin[2] + k * g.spacing[2];
        v->push_back(float(1 + x) + offset);
        v->push_back(float(2 * y));
        v->push_back(float(3 * z - x));
      }
  bp::FieldSlice s;
  s.time = time;
  s.velocity = v;
  return s;
}
} // namespace

TEST(VectorField, TrilinearIsExactOnLinearFields)
{
  const bp::GridGeometry g = bptest::grid(9);
  const bp::VectorField f(g, linearSlice(g, 0.0, 0.0f));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int n = 0; n < 200; ++n)
  {
    const float p[3] = { u(rng), u(rng), u(rng) };
    float v[3];
    f.sample(p, 0.0, v);
    EXPECT_NEAR(v[0], 1 + p[0], 1e-5);
    EXPECT_NEAR(v[1], 2 * p[1], 1e-5);
    EXPECT_NEAR(v[2], 3 * p[2] - p[0], 1e-5);
  }
}

TEST(VectorField, OutsideSamplesTheBoundary)
{
  const bp::GridGeometry g = bptest::grid(5);
  const bp::VectorField f(g, linearSlice(g, 0.0, 0.0f));
  const float p[3] = { 3.0f, -7.0f, 0.5f };
  float v[3];
  f.sample(p, 0.0, v);
  EXPECT_NEAR(v[0], 2.0, 1e-6);  // x clamped to 1
  EXPECT_NEAR(v[1], -2.0, 1e-6); // y clamped to -1
  EXPECT_NEAR(v[2], 0.5, 1e-6);  // 3 * 0.5 - 1
  EXPECT_FALSE(f.contains(p));
  const float inside[3] = { 1.0f, -1.0f, 0.0f };
  EXPECT_TRUE(f.contains(inside));
}

TEST(VectorField, SingleLayerIsAPlane)
{
  const bp::GridGeometry g = bptest::grid(5, -1, 1, 1);
  EXPECT_EQ(g.validate(), "");
  const bp::VectorField f(g, linearSlice(g, 0.0, 0.0f));
  for (float z : { -5.0f, 0.0f, 3.0f })
  {
    const float p[3] = { 0.5f, 0.25f, z };
    float v[3];
    f.sample(p, 0.0, v);
    EXPECT_NEAR(v[0], 1.5, 1e-6);
    EXPECT_NEAR(v[1], 0.5, 1e-6);
    EXPECT_NEAR(v[2], -0.5, 1e-6);
    EXPECT_TRUE(f.contains(p));
  }
  EXPECT_NEAR(g.cellLength(), 0.5, 1e-12);
}

TEST(VectorField, LinearInTimeBetweenSlices)
{
  const bp::GridGeometry g = bptest::grid(5);
  const bp::VectorField f(g, linearSlice(g, 2.0, 0.0f), linearSlice(g, 4.0, 10.0f));
  const float p[3] = { 0.1f, 0.2f, 0.3f };
  float v[3];
  f.sample(p, 3.0, v);
  EXPECT_NEAR(v[0], 1.1 + 5.0, 1e-5);
  f.sample(p, 4.0, v);
  EXPECT_NEAR(v[0], 1.1 + 10.0, 1e-5);
  f.sample(p, 9.0, v); // after the second slice: held at the second
  EXPECT_NEAR(v[0], 1.1 + 10.0, 1e-5);
  EXPECT_EQ(f.validate(), "");
}

TEST(VectorField, ValidateRejectsBadFields)
{
  bp::GridGeometry one;
  one.dims = { 1, 1, 1 };
  EXPECT_NE(one.validate().find("single point"), std::string::npos);
  bp::GridGeometry huge = bptest::grid(4);
  huge.dims[0] = (1 << 24) + 4;
  EXPECT_NE(huge.validate().find("at most"), std::string::npos);
  bp::GridGeometry empty;
  EXPECT_NE(empty.validate().find("no points"), std::string::npos);

  const bp::GridGeometry g = bptest::grid(4);
  bp::FieldSlice s = linearSlice(g, 0.0, 0.0f);
  auto bad = std::make_shared<std::vector<float>>(*s.velocity);
  (*bad)[40] = std::nanf("");
  s.velocity = bad;
  EXPECT_NE(bp::VectorField(g, s).validate().find("non-finite"), std::string::npos);

  bp::FieldSlice shortSlice;
  shortSlice.velocity = std::make_shared<std::vector<float>>(5, 0.0f);
  EXPECT_NE(bp::VectorField(g, shortSlice).validate(), "");
}

TEST(VectorField, SolidBodyRotationHasVorticityTwo)
{
  const bp::GridGeometry g = bptest::grid(17);
  const bp::VectorField f = bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, g);
  const float p[3] = { 0.3f, -0.2f, 0.1f };
  EXPECT_NEAR(f.vorticityMagnitude(p, 0.0), 2.0, 1e-4);
  EXPECT_NEAR(f.maxSpeed(), std::sqrt(2.0), 1e-5);
}
