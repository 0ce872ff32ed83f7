// SPDX-License-Identifier: BSD-3-Clause
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <algorithm>
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
/// v = s (2y - z, 3x + z/2, x - 4y) at the grid's points (rectilinear axes
/// too): linear, so the trilinear interpolant and its derivatives are exact.
bp::FieldSlice scaledLinearSlice(const bp::GridGeometry& g, double time, float s)
{
  auto v = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        const double x = g.coordinate(0, i), y = g.coordinate(1, j), z = g.coordinate(2, k);
        v->push_back(s * float(2 * y - z));
        v->push_back(s * float(3 * x + 0.5 * z));
        v->push_back(s * float(x - 4 * y));
      }
  return bp::FieldSlice{ time, v };
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
  // Unit cells at 1e25: the doubles there are 2e9 apart, every point one.
  bp::GridGeometry far = bptest::grid(4);
  far.origin = { 1e25, 0, 0 };
  EXPECT_NE(far.validate().find("too far from the world origin"), std::string::npos);
  far.origin = { 6.4e6, -2e6, 1e8 }; // projected or Earth-centred coordinates are fine
  EXPECT_EQ(far.validate(), "");

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

TEST(VectorField, VorticityIsTheCurlOfTheCellsInterpolant)
{
  // v = s (2y - z, 3x + z/2, x - 4y): curl v = s (-4.5, -2, 1) everywhere, and
  // the trilinear interpolant of a linear field is the field, so its cell
  // gradient is exact in every cell: on uniform and rectilinear axes, at the
  // boundary, and between two slices (s = 1, then 2).
  bp::GridGeometry g = bptest::grid(7, -1.0, 1.0);
  g.setCoordinates(2, { -1.0, -0.9, -0.6, 0.0, 0.1, 0.7, 1.0 });
  ASSERT_EQ(g.validate(), "");
  const bp::VectorField f(g, scaledLinearSlice(g, 0.0, 1.0f), scaledLinearSlice(g, 1.0, 2.0f));
  ASSERT_EQ(f.validate(), "");
  const double curl = std::sqrt(4.5 * 4.5 + 2.0 * 2.0 + 1.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  for (int n = 0; n < 200; ++n)
  {
    const float p[3] = { coordinate(random), coordinate(random), coordinate(random) };
    for (double t : { 0.0, 0.25, 1.0 })
    {
      float v[3], sampled[3];
      const float vorticity = f.sampleWithVorticity(p, f.timeWeight(t), v);
      EXPECT_NEAR(vorticity, (1.0 + t) * curl, 2e-5 * curl);
      EXPECT_NEAR(f.vorticityMagnitude(p, t), vorticity, 0.0f);
      f.sample(p, t, sampled); // the velocity is the plain sample, bit for bit
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(v[k], sampled[k]);
    }
  }
  const float corner[3] = { 1.0f, 1.0f, 1.0f };
  EXPECT_NEAR(f.vorticityMagnitude(corner, 0.0), curl, 2e-5 * curl);
}

namespace
{
/// A stand-in for Inertia.h's SlipStepper: the direction 0.5 u + s for a
/// fixed s, and what sampleAlong hands its step kept.
struct AlongProbe
{
  float s[3] = { 0.3f, -0.7f, 1.1f };
  float dvdt[3], along[3];
  float direction(int c, float u) const { return 0.5f * u + this->s[c]; }
  void step(const float rate[3], const float d[3])
  {
    std::copy_n(rate, 3, this->dvdt);
    std::copy_n(d, 3, this->along);
  }
#if BOUNDPARTICLES_SSE2
  bp::Lanes direction(bp::Lanes u) const
  {
    return bp::Lanes(0.5f) * u + bp::Lanes::load(this->s);
  }
  void step(bp::Lanes rate, bp::Lanes d)
  {
    rate.store(this->dvdt);
    d.store(this->along);
  }
#endif
};
} // namespace

#if BOUNDPARTICLES_SSE2
TEST(VectorField, LanesLoadAndStoreThreeFloatsAtAnAddressOnlyFloatAligned)
{
  // A heavy particle's velocity sits at any float of the state (4-byte
  // aligned): Lanes::load and store move three floats there and no more.
  // The sanitized build (BOUNDPARTICLES_SANITIZE) stops on a misaligned
  // double load here, as Lanes::load once made through _mm_load_sd.
  alignas(16) float in[6] = { -1.0f, 1.5f, -2.5f, 3.25f, -9.0f, -9.0f };
  const bp::Lanes l = bp::Lanes::load(in + 1);
  alignas(16) float lanes[4];
  _mm_store_ps(lanes, l.v);
  EXPECT_EQ(lanes[0], 1.5f);
  EXPECT_EQ(lanes[1], -2.5f);
  EXPECT_EQ(lanes[2], 3.25f);
  EXPECT_EQ(lanes[3], 0.0f);
  alignas(16) float out[5] = { 7.0f, 7.0f, 7.0f, 7.0f, 7.0f };
  l.store(out + 1);
  EXPECT_EQ(out[0], 7.0f);
  EXPECT_EQ(out[1], 1.5f);
  EXPECT_EQ(out[2], -2.5f);
  EXPECT_EQ(out[3], 3.25f);
  EXPECT_EQ(out[4], 7.0f);
}
#endif

TEST(VectorField, TheDerivativeAlongADirectionIsTheCellGradients)
{
  // v = s (2y - z, 3x + z/2, x - 4y) with s = 1, then 2 (as the vorticity
  // test): the interpolant is the field, so (q . grad) v = s (2 q_y - q_z,
  // 3 q_x + q_z / 2, q_x - 4 q_y) and dv/dt = v at s = 1, on uniform and
  // rectilinear axes and on a grid whose x is a plane (the scalar path).
  for (const bool flatX : { false, true })
  {
    bp::GridGeometry g = bptest::grid(7, -1.0, 1.0);
    g.setCoordinates(2, { -1.0, -0.9, -0.6, 0.0, 0.1, 0.7, 1.0 });
    g.dims[0] = flatX ? 1 : 7;
    ASSERT_EQ(g.validate(), "");
    const bp::VectorField f(g, scaledLinearSlice(g, 0.0, 1.0f), scaledLinearSlice(g, 1.0, 2.0f));
    std::mt19937 random(11);
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    for (int n = 0; n < 100; ++n)
    {
      const float p[3] = { coordinate(random), coordinate(random), coordinate(random) };
      for (const float weight : { 0.0f, 0.25f, 1.0f })
      {
        AlongProbe probe;
        float v[3], sampled[3];
        f.sampleAlong(p, weight, probe, v);
        f.sampleWeighted(p, weight, sampled); // the velocity is the plain sample, bit for bit
        const float s = 1.0f + weight, x = flatX ? float(g.coordinate(0, 0)) : p[0];
        const float first[3] = { 2 * p[1] - p[2], 3 * x + 0.5f * p[2], x - 4 * p[1] };
        float q[3];
        for (int k = 0; k < 3; ++k)
        {
          EXPECT_EQ(v[k], sampled[k]);
          EXPECT_NEAR(probe.dvdt[k], first[k], 1e-5);
          q[k] = 0.5f * v[k] + probe.s[k];
        }
        const float qx = flatX ? 0.0f : q[0]; // nothing varies across a plane
        EXPECT_NEAR(probe.along[0], s * (2 * q[1] - q[2]), 1e-4);
        EXPECT_NEAR(probe.along[1], s * (3 * qx + 0.5f * q[2]), 1e-4);
        EXPECT_NEAR(probe.along[2], s * (qx - 4 * q[1]), 1e-4);
      }
    }
  }
}

TEST(VectorField, RectilinearAxesAreSampledExactly)
{
  // Altitude-like z layers, crowded near the ground, and a stretched x axis.
  bp::GridGeometry g = bptest::grid(6, 0.0, 1.0);
  g.setCoordinates(2, { 0.0, 0.01, 0.03, 0.07, 0.2, 0.5, 1.0, 3.0 });
  g.setCoordinates(0, { -2.0, -1.0, -0.5, 0.0, 0.25, 4.0 });
  ASSERT_EQ(g.validate(), "");
  EXPECT_EQ(g.dims[2], 8);
  EXPECT_DOUBLE_EQ(g.bounds()[5], 3.0);
  EXPECT_DOUBLE_EQ(g.spacing[2], 3.0 / 7.0);
  // u is a known function of altitude, w is linear in x: at every grid layer
  // exact, and linear between two layers.
  auto u = [](double z) { return 10.0 * std::sqrt(z) + z * z; };
  auto values = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        values->push_back(float(u(g.coordinate(2, k))));
        values->push_back(float(g.coordinate(1, j)));
        values->push_back(float(3.0 * g.coordinate(0, i)));
      }
  bp::FieldSlice s;
  s.velocity = values;
  const bp::VectorField f(g, s);
  ASSERT_EQ(f.validate(), "");
  for (int k = 0; k + 1 < g.dims[2]; ++k)
  {
    const double z0 = g.coordinate(2, k), z1 = g.coordinate(2, k + 1);
    for (double w : { 0.0, 0.3, 0.5, 0.9 })
    {
      const double z = z0 + w * (z1 - z0);
      const float p[3] = { 0.1f, 0.4f, float(z) };
      float v[3];
      f.sample(p, 0.0, v);
      const double expected = u(z0) + (z - z0) / (z1 - z0) * (u(z1) - u(z0));
      EXPECT_NEAR(v[0], expected, 2e-5 * std::max(1.0, std::abs(expected))) << "z = " << z;
      EXPECT_NEAR(v[1], 0.4, 1e-6);
      EXPECT_NEAR(v[2], 0.3, 1e-5); // linear in x on the stretched x axis
    }
  }
  // Above the top and below the ground: the boundary layers.
  const float above[3] = { 0.0f, 0.0f, 5.0f }, below[3] = { 0.0f, 0.0f, -1.0f };
  float v[3];
  f.sample(above, 0.0, v);
  EXPECT_NEAR(v[0], u(3.0), 1e-4);
  f.sample(below, 0.0, v);
  EXPECT_NEAR(v[0], 0.0, 1e-6);
  EXPECT_FALSE(f.contains(above));
  const float inside[3] = { 3.9f, 1.0f, 2.9f };
  EXPECT_TRUE(f.contains(inside));
  // The float tables both engines use.
  ASSERT_EQ(f.axisTable(2).size(), 16u);
  EXPECT_FLOAT_EQ(f.axisTable(2)[2], 0.01f);
  EXPECT_FLOAT_EQ(f.axisTable(2)[3], 50.0f); // 1 / (0.03 - 0.01)
  EXPECT_TRUE(f.axisTable(1).empty());
}

TEST(VectorField, RectilinearGridsAreValidatedMovedAndCompared)
{
  bp::GridGeometry g = bptest::grid(4, 0.0, 1.0);
  g.setCoordinates(2, { 0.0, 0.5, 0.5, 1.0 });
  EXPECT_NE(g.validate().find("strictly increasing"), std::string::npos) << g.validate();
  g.setCoordinates(2, { 0.0, 0.1, 0.4, 1.0 });
  EXPECT_EQ(g.validate(), "");
  bp::GridGeometry moved = g;
  moved.translate({ 1.0, 2.0, 3.0 });
  EXPECT_DOUBLE_EQ(moved.coordinate(2, 2), 0.4 - 3.0);
  EXPECT_DOUBLE_EQ(moved.coordinate(0, 3), 1.0 - 1.0);
  EXPECT_FALSE(moved.sameAs(g, 1e-9));
  moved.translate({ -1.0, -2.0, -3.0 });
  EXPECT_TRUE(moved.sameAs(g, 1e-9));
  bp::GridGeometry uniform = bptest::grid(4, 0.0, 1.0);
  EXPECT_FALSE(uniform.sameAs(g, 1e-9));
}

TEST(VectorField, AFlatFieldsComponentAcrossItsPlaneIsDropped)
{
  std::vector<float> v = { 1, 2, -3, 0, 0.5f, 0.25f };
  float inPlane = 0.0f;
  EXPECT_EQ(bp::dropFlatComponents(v, { false, false, true }, inPlane), 3.0f);
  EXPECT_EQ(v, (std::vector<float>{ 1, 2, 0, 0, 0.5f, 0 }));
  EXPECT_FLOAT_EQ(inPlane, std::sqrt(5.0f));
  EXPECT_EQ(bp::dropFlatComponents(v, { false, false, true }, inPlane), 0.0f);
}
