// SPDX-License-Identifier: BSD-3-Clause
// The physics suite: checks that assert numbers about how elements move, each
// run on the CPU engine and on the GPU engine (in a headless EGL context).
#include "AnalyticFlows.h"
#include "Engine.h"
#include "GpuStepper.h"
#include "PhysicsSystem.h"
#include "Quaternion.h"
#include "SharedContext.h"
#include "Stepper.h"

#include <cstdint>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace
{
constexpr double Pi = 3.14159265358979323846;
using bptest::System;

bp::VectorField steady(bp::AnalyticFlow flow, std::array<int, 3> dims, std::array<double, 6> box)
{
  bp::GridGeometry g;
  g.dims = dims;
  for (int a = 0; a < 3; ++a)
  {
    g.origin[a] = box[2 * a];
    g.spacing[a] = (box[2 * a + 1] - box[2 * a]) / (dims[a] - 1);
  }
  bp::FieldSlice s;
  s.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, 0.0));
  return bp::VectorField(g, s);
}

bp::Parameters placed(
  std::size_t elements, float size, std::array<float, 3> lo, std::array<float, 3> hi)
{
  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = size;
  p.emitterMin = lo;
  p.emitterMax = hi;
  p.lifetimeMin = p.lifetimeMax = 1000.0f;
  p.seed = 3;
  return p;
}

/// Angle of the vector from particle a to particle b in the plane of axes (u, v).
double angleOf(const std::vector<float>& x, std::size_t base, int a, int b, int u, int v)
{
  const float* pa = &x[3 * (base + a)];
  const float* pb = &x[3 * (base + b)];
  return std::atan2(pb[u] - pa[u], pb[v] - pa[v]);
}

double unwrap(double delta)
{
  while (delta > Pi)
    delta -= 2 * Pi;
  while (delta < -Pi)
    delta += 2 * Pi;
  return delta;
}

/// The mean of element e's n particles.
std::array<float, 3> centerOf(const std::vector<float>& x, std::size_t e, std::size_t n)
{
  std::array<float, 3> c = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      c[std::size_t(k)] += x[3 * (e * n + i) + std::size_t(k)] / float(n);
  return c;
}

/// The rotation (x, y, z, w) by `angle` about z after `q`.
std::array<double, 4> turnedAboutZ(const float* q, double angle)
{
  const double s = std::sin(0.5 * angle), c = std::cos(0.5 * angle);
  return { c * q[0] - s * q[1], c * q[1] + s * q[0], c * q[2] + s * q[3], c * q[3] - s * q[2] };
}

/// 1 - |q . r|: 0 for the same rotation (q and -q are one).
double rotationDistance(const float* q, const std::array<double, 4>& r)
{
  return 1.0 - std::abs(q[0] * r[0] + q[1] * r[1] + q[2] * r[2] + q[3] * r[3]);
}

class Physics : public bptest::OnEachEngine
{
};
} // namespace

// Solid-body rotation: every element keeps its edge lengths within 1% and turns
// at the field's angular velocity within 2% after one revolution.
TEST_P(Physics, SolidBodyRotationKeepsShapesAndTurnsWithTheField)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::SolidBodyRotation, { 33, 33, 9 }, { -1, 1, -1, 1, -1, 1 });
  bp::Parameters p = placed(40, 0.25f, { -0.5f, -0.5f, -0.5f }, { 0.5f, 0.5f, 0.5f });
  p.orientation = bp::Orientation::Fixed; // flat in the plane of rotation
  p.integrator = bp::Integrator::RK4;
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  System system(GetParam(), cross, p, field);
  const int steps = 400, every = 10;
  const double dt = 2 * Pi / steps; // unit angular velocity: one revolution
  std::vector<double> turned(p.numberOfElements, 0.0), last(p.numberOfElements);
  std::vector<float> x = system.positions();
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
    last[e] = angleOf(x, e * 12, 9, 4, 1, 0); // left tip to right tip, angle in x-y
  double worstStrain = 0.0;
  for (int s = 0; s < steps; ++s)
  {
    system.step(s * dt, dt);
    if ((s + 1) % every)
      continue;
    x = system.positions();
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      const double now = angleOf(x, e * 12, 9, 4, 1, 0);
      turned[e] += unwrap(now - last[e]);
      last[e] = now;
      for (const bp::Spring& sp : cross.springs)
      {
        const float* a = &x[3 * (e * 12 + sp.a)];
        const float* b = &x[3 * (e * 12 + sp.b)];
        const double length = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
        worstStrain = std::max(worstStrain, std::abs(length / (sp.restLength * p.elementSize) - 1));
      }
    }
  }
  EXPECT_LT(worstStrain, 0.01);
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
    EXPECT_NEAR(turned[e], 2 * Pi, 0.02 * 2 * Pi) << "element " << e;
}

namespace
{
/// The shear layer u(z) = 1.25 - z^2 on z in [-1, 1] over a long box:
/// vorticity du/dz = -2z about +y.
bp::VectorField shearLayer()
{
  return steady(bp::AnalyticFlow::ShearLayer, { 65, 9, 41 }, { 0, 8, 0, 1, -1, 1 });
}

/// 20 paddlewheels at height `level` of the shear layer, their axes along y,
/// under shape matching and RK4, their poses tracked.
bp::Parameters wheelsAcrossTheShearLayer(float level)
{
  bp::Parameters p = placed(20, 0.2f, { 0.5f, 0.4f, level }, { 1.5f, 0.6f, level });
  p.orientation = bp::Orientation::Fixed;
  p.frame = bp::rotationFromDegrees(90, 0, 0); // paddle axis along y
  p.restoration = bp::Restoration::ShapeMatching;
  p.integrator = bp::Integrator::RK4;
  p.trackPoses = true;
  return p;
}
} // namespace

// Shear layer (thesis Fig. 4.2): paddlewheels above and below mid-depth turn in
// opposite senses; with shape matching at half the local vorticity, within 10%.
TEST_P(Physics, ShearLayerPaddlewheelsTurnAtHalfTheVorticity)
{
  const bp::VectorField field = shearLayer();
  for (float level : { 0.5f, -0.5f })
  {
    bp::Parameters p = wheelsAcrossTheShearLayer(level);
    System system(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Paddlewheel), p, field);
    const int steps = 100;
    const double dt = 0.01;
    std::vector<float> x = system.positions();
    std::vector<double> turned(p.numberOfElements, 0.0), last(p.numberOfElements);
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
      last[e] = angleOf(x, e * 8, 0, 3, 0, 2); // a diagonal in the x-z plane
    for (int s = 0; s < steps; ++s)
    {
      system.step(s * dt, dt);
      x = system.positions();
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
      {
        const double now = angleOf(x, e * 8, 0, 3, 0, 2);
        turned[e] += unwrap(now - last[e]);
        last[e] = now;
      }
    }
    double mean = 0.0;
    for (double t : turned)
      mean += t / (steps * dt) / turned.size();
    const double halfVorticity = -level; // (du/dz) / 2 = -z
    std::printf(
      "%s: paddlewheels at z = %+.1f turn at %+.4f rad/time; half the vorticity is %+.4f\n",
      GetParam() ? "GPU" : "CPU", level, mean, halfVorticity);
    EXPECT_GT(mean * halfVorticity, 0.0) << "turns the wrong way at z = " << level;
    EXPECT_NEAR(mean, halfVorticity, 0.1 * std::abs(halfVorticity)) << "at z = " << level;
    // The pose fit's spin over the last step is half the vorticity vector
    // (the field's curl at the centre, about +y), and the meter reads 1.
    const std::vector<float> spins = system.spins();
    double worstSpin = 0.0, lowRatio = 2.0, highRatio = -2.0;
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      const std::array<float, 3> c = centerOf(x, e, 8);
      float v[3], curl[3];
      field.sampleWithCurl(c.data(), 0.0f, v, curl);
      const float* w = &spins[4 * e];
      const double off =
        std::hypot(w[0] - 0.5 * curl[0], w[1] - 0.5 * curl[1], w[2] - 0.5 * curl[2]);
      worstSpin = std::max(worstSpin, off / (0.5 * std::hypot(curl[0], curl[1], curl[2])));
      lowRatio = std::min(lowRatio, double(w[3]));
      highRatio = std::max(highRatio, double(w[3]));
    }
    std::printf("  spins within %.2f%% of half the curl; SpinVorticityRatio in [%.4f, %.4f]\n",
      100 * worstSpin, lowRatio, highRatio);
    EXPECT_LT(worstSpin, 0.1) << "at z = " << level;
    EXPECT_GE(lowRatio, 0.9) << "at z = " << level;
    EXPECT_LE(highRatio, 1.1) << "at z = " << level;
  }
}

// Solid-body rotation at unit rate about z turns every element, however it
// lies, at the spin (0, 0, 1), half the vorticity (0, 0, 2): the vorticity
// meter reads 1, and the pose is the placed one turned by the time elapsed.
TEST_P(Physics, SolidBodyRotationSpinsEveryElementAtTheFieldsRate)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::SolidBodyRotation, { 33, 33, 9 }, { -1, 1, -1, 1, -1, 1 });
  // A flat element held by springs, and a solid one by shape matching.
  for (auto shape : { bp::BuiltinShape::Cross, bp::BuiltinShape::Paddlewheel })
  {
    const bp::ElementTemplate element = bp::builtinTemplate(shape);
    SCOPED_TRACE(element.name);
    bp::Parameters p = placed(40, 0.25f, { -0.5f, -0.5f, -0.5f }, { 0.5f, 0.5f, 0.5f });
    p.integrator = bp::Integrator::RK4; // randomly oriented
    p.trackPoses = true;
    if (shape == bp::BuiltinShape::Paddlewheel)
      p.restoration = bp::Restoration::ShapeMatching;
    System system(GetParam(), element, p, field);
    const std::vector<float> start = system.poses();
    const int steps = 100;
    const double dt = 2 * Pi / 400;
    double worstSpin = 0.0, worstRatio = 0.0;
    for (int s = 0; s < steps; ++s)
    {
      system.step(s * dt, dt);
      if ((s + 1) % 10)
        continue;
      const std::vector<float> spins = system.spins();
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
      {
        const float* w = &spins[4 * e];
        worstSpin = std::max(worstSpin, std::hypot(w[0], w[1], w[2] - 1.0));
        worstRatio = std::max(worstRatio, std::abs(w[3] - 1.0));
      }
    }
    const std::vector<float> poses = system.poses();
    double worstPose = 0.0;
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
      worstPose = std::max(
        worstPose, rotationDistance(&poses[4 * e], turnedAboutZ(&start[4 * e], steps * dt)));
    std::printf("%s %s: spins within %.2e of (0, 0, 1), ratios within %.2e of 1, poses within "
                "%.2e\n",
      GetParam() ? "GPU" : "CPU", element.name.c_str(), worstSpin, worstRatio, worstPose);
    EXPECT_LE(worstSpin, 0.02);
    EXPECT_LE(worstRatio, 0.02);
    EXPECT_LT(worstPose, 1e-4);
  }
}

// Anchor = Centre in solid-body rotation: an element released off the axis
// keeps its centre where it was placed (to float rounding) and still turns
// at the field's rate, its spin (0, 0, 1) as a free element's; its pose is
// the placed one turned by the time elapsed.
TEST_P(Physics, AnchoredElementsKeepTheirCentresAndSpinAtTheFieldsRate)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::SolidBodyRotation, { 33, 33, 9 }, { -1, 1, -1, 1, -1, 1 });
  for (auto shape : { bp::BuiltinShape::Cross, bp::BuiltinShape::Paddlewheel })
  {
    const bp::ElementTemplate element = bp::builtinTemplate(shape);
    SCOPED_TRACE(element.name);
    const std::size_t n = element.particleCount();
    // Off the axis: centres 0.3 to 0.6 from it, where a free element would
    // travel 0.5 to 0.9 in the quarter turn below.
    bp::Parameters p = placed(20, 0.25f, { 0.3f, -0.2f, -0.3f }, { 0.6f, 0.2f, 0.3f });
    p.integrator = bp::Integrator::RK4; // randomly oriented
    p.trackPoses = true;
    p.anchor = bp::Anchor::Centre;
    if (shape == bp::BuiltinShape::Paddlewheel)
      p.restoration = bp::Restoration::ShapeMatching;
    System system(GetParam(), element, p, field);
    const std::vector<float> x0 = system.positions();
    const std::vector<float> start = system.poses();
    const int steps = 100;
    const double dt = 2 * Pi / 400;
    double worstShift = 0.0, worstSpin = 0.0;
    for (int s = 0; s < steps; ++s)
    {
      system.step(s * dt, dt);
      const std::vector<float> x = system.positions();
      const std::vector<float> spins = system.spins();
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
      {
        const std::array<float, 3> c = centerOf(x, e, n), c0 = centerOf(x0, e, n);
        worstShift =
          std::max(worstShift, double(std::hypot(c[0] - c0[0], c[1] - c0[1], c[2] - c0[2])));
        const float* w = &spins[4 * e];
        worstSpin = std::max(worstSpin, std::hypot(w[0], w[1], w[2] - 1.0));
      }
    }
    const std::vector<float> poses = system.poses();
    double worstPose = 0.0;
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
      worstPose = std::max(
        worstPose, rotationDistance(&poses[4 * e], turnedAboutZ(&start[4 * e], steps * dt)));
    std::printf("%s %s anchored: centres within %.2e of their release, spins within %.2e of "
                "(0, 0, 1), poses within %.2e\n",
      GetParam() ? "GPU" : "CPU", element.name.c_str(), worstShift, worstSpin, worstPose);
    EXPECT_LT(worstShift, 1e-5);
    EXPECT_LE(worstSpin, 0.02);
    EXPECT_LT(worstPose, 1e-4);
  }
}

// Anchor = Centre in the shear layer: anchored paddlewheels turn in place at
// half the local vorticity, as free ones released with them do while they
// drift downstream: the two differ in where they are, not in how they turn.
TEST_P(Physics, AnchoredPaddlewheelsTurnInPlaceAtHalfTheVorticity)
{
  const bp::VectorField field = shearLayer();
  for (float level : { 0.5f, -0.5f })
  {
    bp::Parameters p = wheelsAcrossTheShearLayer(level);
    bp::Parameters anchoredParameters = p;
    anchoredParameters.anchor = bp::Anchor::Centre;
    const bp::ElementTemplate wheel = bp::builtinTemplate(bp::BuiltinShape::Paddlewheel);
    System free(GetParam(), wheel, p, field);
    System anchored(GetParam(), wheel, anchoredParameters, field);
    const std::vector<float> x0 = anchored.positions();
    const int steps = 400;
    const double dt = 0.01;
    auto angles = [&](const std::vector<float>& x)
    {
      std::vector<double> a(p.numberOfElements);
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
        a[e] = angleOf(x, e * 8, 0, 3, 0, 2); // a diagonal in the x-z plane
      return a;
    };
    std::vector<double> lastFree = angles(free.positions()), lastAnchored = angles(x0);
    double turnedFree = 0.0, turnedAnchored = 0.0;
    for (int s = 0; s < steps; ++s)
    {
      free.step(s * dt, dt);
      anchored.step(s * dt, dt);
      const std::vector<double> nowFree = angles(free.positions());
      const std::vector<double> nowAnchored = angles(anchored.positions());
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
      {
        turnedFree += unwrap(nowFree[e] - lastFree[e]) / (steps * dt * p.numberOfElements);
        turnedAnchored +=
          unwrap(nowAnchored[e] - lastAnchored[e]) / (steps * dt * p.numberOfElements);
      }
      lastFree = nowFree;
      lastAnchored = nowAnchored;
    }
    const std::vector<float> xFree = free.positions(), xAnchored = anchored.positions();
    double worstShift = 0.0, leastDrift = 1e9, worstSpin = 0.0;
    const std::vector<float> spins = anchored.spins();
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      const std::array<float, 3> c = centerOf(xAnchored, e, 8), c0 = centerOf(x0, e, 8);
      const std::array<float, 3> f = centerOf(xFree, e, 8);
      worstShift =
        std::max(worstShift, double(std::hypot(c[0] - c0[0], c[1] - c0[1], c[2] - c0[2])));
      leastDrift = std::min(leastDrift, double(f[0] - c0[0]));
      // The spin over the last step: half the curl at the anchor.
      float v[3], curl[3];
      field.sampleWithCurl(c0.data(), 0.0f, v, curl);
      const float* w = &spins[4 * e];
      worstSpin = std::max(worstSpin,
        std::hypot(w[0] - 0.5 * curl[0], w[1] - 0.5 * curl[1], w[2] - 0.5 * curl[2]) /
          (0.5 * std::hypot(curl[0], curl[1], curl[2])));
    }
    const double halfVorticity = -level; // (du/dz) / 2 = -z
    std::printf("%s: at z = %+.1f anchored paddlewheels turn at %+.4f rad/time, free ones at "
                "%+.4f (half the vorticity %+.4f); anchored centres within %.2e, free ones "
                "drifted at least %.3f; anchored spins within %.2f%% of half the curl\n",
      GetParam() ? "GPU" : "CPU", level, turnedAnchored, turnedFree, halfVorticity, worstShift,
      leastDrift, 100 * worstSpin);
    EXPECT_NEAR(turnedAnchored, halfVorticity, 0.1 * std::abs(halfVorticity)) << "z = " << level;
    EXPECT_NEAR(turnedFree, halfVorticity, 0.1 * std::abs(halfVorticity)) << "z = " << level;
    EXPECT_NEAR(turnedAnchored, turnedFree, 0.02 * std::abs(halfVorticity)) << "z = " << level;
    EXPECT_LT(worstShift, 1e-5) << "z = " << level;
    EXPECT_GT(leastDrift, 0.9 * steps * dt * (1.25 - level * level)) << "z = " << level;
    EXPECT_LT(worstSpin, 0.1) << "z = " << level;
  }
}

// An element of one particle has no orientation: its pose stays the identity
// and its spin 0, however it was placed (random orientations) and replaced.
TEST_P(Physics, OneParticleElementsHaveNoPoseOrSpin)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::ABC, { 17, 17, 17 }, { -1, 1, -1, 1, -1, 1 });
  bp::Parameters p = placed(50, 0.2f, { -0.5f, -0.5f, -0.5f }, { 0.5f, 0.5f, 0.5f });
  p.lifetimeMin = 0.05f; // placed again every few steps
  p.lifetimeMax = 0.2f;
  p.trackPoses = true;
  System system(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Point), p, field);
  int others = 0;
  for (int s = 0; s <= 40; ++s)
  {
    if (s > 0)
      system.step((s - 1) * 0.02, 0.02);
    const std::vector<float> poses = system.poses(), spins = system.spins();
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      const float* q = &poses[4 * e];
      const float* w = &spins[4 * e];
      others += !(q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 1);
      others += !(w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 0);
    }
  }
  EXPECT_EQ(others, 0) << "poses other than the identity or spins other than 0";
}

// Vertical shear (thesis Fig. 4.4): strips lying in horizontal planes ride the
// wind of their height. With reset on any particle leaving, no particle is ever
// advected from outside the field, and the strips stay straight instead of
// dragging at the boundary.
TEST_P(Physics, VerticalShearStripsStayInsideAndStraight)
{
  const std::array<double, 6> box = { -1, 1, -1, 1, 0, 0.5 };
  const bp::VectorField field = steady(bp::AnalyticFlow::VerticalShear, { 33, 33, 17 }, box);
  const float size = 0.3f, r = 0.5f * size; // emitter shrunk by the element's radius
  bp::Parameters p = placed(200, size, { -1 + r, -1 + r, r }, { 1 - r, 1 - r, 0.5f - r });
  p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
  p.orientation = bp::Orientation::Fixed; // lying in horizontal planes, where the wind is uniform
  const bp::ElementTemplate strip = bp::builtinTemplate(bp::BuiltinShape::Strip16);
  System system(GetParam(), strip, p, field);
  const double rest =
    std::hypot(strip.rest[14][0] - strip.rest[0][0], strip.rest[14][1] - strip.rest[0][1],
      strip.rest[14][2] - strip.rest[0][2]) *
    size;
  const bp::VectorField::SamplingConstants c = field.samplingConstants();
  int outsideUnflagged = 0, resets = 0;
  double worstBend = 0.0;
  for (int s = 0; s < 300; ++s)
  {
    system.step(s * 0.01, 0.01);
    const std::vector<float> x = system.positions();
    const std::vector<float> flags = system.flags();
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      if (flags[e] > 0.5f)
      {
        ++resets; // reset before its particles are advected again
        continue;
      }
      for (std::size_t i = 0; i < 16; ++i)
      {
        const float* q = &x[3 * (e * 16 + i)];
        for (int a = 0; a < 3; ++a)
          outsideUnflagged += !(q[a] >= c.lower[a] && q[a] <= c.upper[a]);
      }
      // A strip dragging at the boundary bends: its end-to-end length shrinks.
      const float* a = &x[3 * (e * 16)];
      const float* b = &x[3 * (e * 16 + 14)];
      worstBend =
        std::max(worstBend, std::abs(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) / rest - 1));
    }
  }
  EXPECT_EQ(outsideUnflagged, 0);
  EXPECT_GT(resets, 0); // the check saw elements leave
  EXPECT_LT(worstBend, 0.02);
}

// A pinned particle stays put to machine precision while its element swings.
TEST_P(Physics, PinnedParticleStaysPut)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::ABC, { 17, 17, 17 }, { -1, 1, -1, 1, -1, 1 });
  bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip8);
  shape.pinned.assign(shape.particleCount(), 0);
  shape.pinned[0] = 1;
  bp::Parameters p = placed(10, 0.3f, { -0.5f, -0.5f, -0.5f }, { 0.5f, 0.5f, 0.5f });
  System system(GetParam(), shape, p, field);
  const std::vector<float> start = system.positions();
  for (int s = 0; s < 100; ++s)
    system.step(s * 0.01, 0.01);
  const std::vector<float> end = system.positions();
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
  {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(end[3 * e * 8 + k], start[3 * e * 8 + k]);
    EXPECT_GT(std::abs(end[3 * e * 8 + 21] - start[3 * e * 8 + 21]), 1e-3); // the far end swings
  }
}

// Super sets: a sheet of points in solid-body rotation turns as one rigid
// sheet, every link within 1% of its rest length, at the field's angular
// velocity within 2%; a ring of crosses does too.
TEST_P(Physics, SuperSetTurnsAsOneInSolidBodyRotation)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::SolidBodyRotation, { 33, 33, 9 }, { -1, 1, -1, 1, -1, 1 });
  for (auto linking : { bp::Linking::Sheet, bp::Linking::Ring })
  {
    SCOPED_TRACE(bp::enumName(linking));
    const bool sheet = linking == bp::Linking::Sheet;
    bp::Parameters p = placed(sheet ? 64 : 24, 0.1f, { -0.6f, -0.4f, 0 }, { 0.6f, 0.4f, 0 });
    p.orientation = bp::Orientation::Fixed;
    p.integrator = bp::Integrator::RK4;
    p.linking = linking;
    const bp::ElementTemplate shape =
      bp::builtinTemplate(sheet ? bp::BuiltinShape::Point : bp::BuiltinShape::Cross);
    const std::size_t n = shape.particleCount();
    bp::Engine reference; // the link table the engines build
    ASSERT_EQ(reference.configure(shape, p), "");
    const bp::LinkTable& links = reference.links();
    System system(GetParam(), shape, p, field);
    const int steps = 400;
    const double dt = 2 * Pi / steps;
    // The turn of the line from element 0 to the element half a row (or half
    // the ring) away.
    const std::size_t far = sheet ? 7 : 12;
    std::vector<float> x = system.positions();
    double last = angleOf(x, 0, 0, int(far * n), 1, 0), turned = 0.0, worstStrain = 0.0;
    for (int s = 0; s < steps; ++s)
    {
      system.step(s * dt, dt);
      x = system.positions();
      const double now = angleOf(x, 0, 0, int(far * n), 1, 0);
      turned += unwrap(now - last);
      last = now;
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
        for (int d = 0; d < bp::LinkDirections; ++d)
        {
          const std::int32_t f = links.neighbours[bp::LinkDirections * e + d];
          if (f < 0)
            continue;
          for (std::size_t i = 0; i < n; ++i)
          {
            const float* a = &x[3 * (e * n + i)];
            const float* b = &x[3 * (std::size_t(f) * n + i)];
            const double length = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
            worstStrain =
              std::max(worstStrain, std::abs(length / links.rest[bp::LinkDirections * e + d] - 1));
          }
        }
    }
    std::printf("%s %s: turned %.4f rad (2 pi = %.4f), worst link strain %.2e\n",
      GetParam() ? "GPU" : "CPU", bp::enumName(linking), turned, 2 * Pi, worstStrain);
    EXPECT_LT(worstStrain, 0.01);
    EXPECT_NEAR(turned, 2 * Pi, 0.02 * 2 * Pi);
  }
}

// Super sets hold together: in the shear layer a chain of points across the
// layer stretches far when its links have no stiffness. With stiff links it
// stretches less, and less again with more restoration iterations (Jacobi
// passes propagate a correction one link per pass).
TEST_P(Physics, SuperSetChainHoldsTogetherInShear)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::ShearLayer, { 65, 9, 41 }, { 0, 8, 0, 1, -1, 1 });
  const auto stretchOf = [&](float stiffness, int iterations)
  {
    // A vertical chain from z = -0.8 to 0.8: the shear turns and stretches it.
    bp::Parameters p = placed(33, 0.05f, { 1, 0.5f, -0.8f }, { 1, 0.5f, 0.8f });
    p.orientation = bp::Orientation::Fixed;
    p.linking = bp::Linking::Chain;
    p.linkStiffness = stiffness;
    p.iterations = iterations;
    System system(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Point), p, field);
    for (int s = 0; s < 100; ++s)
      system.step(s * 0.01, 0.01);
    const std::vector<float> x = system.positions();
    double length = 0.0;
    for (std::size_t e = 0; e + 1 < p.numberOfElements; ++e)
      length += std::hypot(
        x[3 * e + 3] - x[3 * e], x[3 * e + 4] - x[3 * e + 1], x[3 * e + 5] - x[3 * e + 2]);
    return length / 1.6 - 1;
  };
  const double free = stretchOf(0.0f, 4), four = stretchOf(1.0f, 4), many = stretchOf(1.0f, 32);
  std::printf("%s: chain stretched by %.1f%% with free links, %.1f%% with stiff ones and 4 "
              "iterations, %.2f%% with 32\n",
    GetParam() ? "GPU" : "CPU", 100 * free, 100 * four, 100 * many);
  EXPECT_GT(free, 0.2);
  EXPECT_LT(four, 0.5 * free);
  EXPECT_LT(many, 0.02);
}

// Linear shape matching (Müller et al. 2005, §4.3): with beta = 0 it is the
// rigid fit, bit for bit; with beta > 0 a sheared element deforms, by more as
// beta grows, and still turns with the flow.
TEST_P(Physics, LinearShapeMatchingLetsElementsShear)
{
  const bp::VectorField field =
    steady(bp::AnalyticFlow::ShearLayer, { 65, 9, 41 }, { 0, 8, 0, 1, -1, 1 });
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Paddlewheel);
  const auto run = [&](bool linear, float beta)
  {
    bp::Parameters p = placed(20, 0.2f, { 0.5f, 0.4f, 0.5f }, { 1.5f, 0.6f, 0.5f });
    p.orientation = bp::Orientation::Fixed;
    p.frame = bp::rotationFromDegrees(90, 0, 0);
    p.restoration = bp::Restoration::ShapeMatching;
    p.linearShapeMatching = linear;
    p.linearBlend = beta;
    System system(GetParam(), shape, p, field);
    for (int s = 0; s < 100; ++s)
      system.step(s * 0.01, 0.01);
    const std::vector<float> x = system.positions();
    double strain = 0.0;
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
      for (const bp::Spring& sp : shape.springs)
      {
        const float* a = &x[3 * (e * 8 + sp.a)];
        const float* b = &x[3 * (e * 8 + sp.b)];
        strain = std::max(strain,
          std::abs(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) /
              double(sp.restLength * p.elementSize) -
            1));
      }
    return std::make_pair(x, strain);
  };
  const auto rigid = run(false, 0.0f);
  const auto zero = run(true, 0.0f);
  const auto half = run(true, 0.5f);
  const auto most = run(true, 0.9f);
  std::printf("%s: worst spring strain rigid %.2e, linear beta 0.5 %.2e, beta 0.9 %.2e\n",
    GetParam() ? "GPU" : "CPU", rigid.second, half.second, most.second);
  double differ = 0.0;
  for (std::size_t k = 0; k < rigid.first.size(); ++k)
    differ = std::max(differ, double(std::abs(rigid.first[k] - zero.first[k])));
  EXPECT_LT(differ, 1e-5);
  EXPECT_LT(rigid.second, 0.01);
  EXPECT_GT(half.second, 2 * rigid.second);
  EXPECT_GT(most.second, half.second);
}

INSTANTIATE_TEST_SUITE_P(Engines, Physics, ::testing::Values(false, true), bptest::engineName);
