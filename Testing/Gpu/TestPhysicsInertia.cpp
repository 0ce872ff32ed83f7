// SPDX-License-Identifier: BSD-3-Clause
// Heavy particles (Core/Engine/Inertia.h) on both engines: settling in still fluid,
// the drift out of (and a bubble's into) a vortex, the massless limit; and
// the GPU engine against the CPU engine, positions and slips, for each
// integrator and restoration, steady and unsteady, with gravity, on the
// fragment path, the compute path and its fused step.
#include "AnalyticFlows.h"
#include "Engine.h"
#include "GpuStepper.h"
#include "PhysicsSystem.h"
#include "SharedContext.h"
#include "Stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

namespace
{
constexpr double Pi = 3.14159265358979323846;
using bptest::System;

bp::GridGeometry box(int n, double lo, double hi, int nz)
{
  bp::GridGeometry g;
  g.dims = { n, n, nz };
  g.origin = { lo, lo, nz > 1 ? lo : 0.0 };
  const double h = (hi - lo) / (n - 1);
  g.spacing = { h, h, nz > 1 ? h : 1.0 };
  return g;
}

bp::VectorField flowOn(bp::AnalyticFlow flow, const bp::GridGeometry& g, bool unsteady)
{
  auto slice = [&](double t)
  {
    bp::FieldSlice s;
    s.time = t;
    s.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, t));
    return s;
  };
  return unsteady ? bp::VectorField(g, slice(0.0), slice(1.0)) : bp::VectorField(g, slice(0.0));
}

/// A still field over [-1, 1]^3.
bp::VectorField stillFlow()
{
  const bp::GridGeometry g = box(9, -1, 1, 9);
  bp::FieldSlice s;
  s.velocity = std::make_shared<std::vector<float>>(3 * g.pointCount(), 0.0f);
  return bp::VectorField(g, s);
}

bp::Parameters heavy(std::array<float, 3> lo, std::array<float, 3> hi, float tau, float ratio)
{
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.05f;
  p.emitterMin = lo;
  p.emitterMax = hi;
  p.lifetimeMin = p.lifetimeMax = 1e6f;
  p.integrator = bp::Integrator::RK4;
  p.orientation = bp::Orientation::Fixed;
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = tau;
  p.densityRatio = ratio;
  return p;
}

class InertiaPhysics : public bptest::OnEachEngine
{
};
} // namespace

TEST_P(InertiaPhysics, SettlesAtItsTerminalVelocity)
{
  // v = tau (1 - beta) g (1 - exp(-t/tau)) in still fluid, within 1% at every step.
  const bp::VectorField still = stillFlow();
  bp::Parameters p = heavy({ 0, 0, 0.5f }, { 0, 0, 0.5f }, 0.05f, 2.65f);
  p.gravity = { 0, 0, -9.81f };
  System s(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Square), p, still);
  const double terminal = 0.05 * (1.0 - bp::addedMassFactor(2.65f)) * -9.81, h = 0.004;
  double worst = 0.0;
  for (int k = 1; k <= 100; ++k)
  {
    s.step((k - 1) * h, h);
    const std::vector<float> slips = s.slips();
    ASSERT_EQ(slips.size(), 12u);
    const double expected = terminal * (1.0 - std::exp(-k * h / 0.05));
    for (int i = 0; i < 4; ++i)
      worst = std::max(worst, std::abs(slips[std::size_t(3 * i + 2)] - expected));
  }
  std::printf("%s: settling within %.2e of tau (1 - beta) g (1 - exp(-t/tau)), terminal %.4f\n",
    engine(), worst, terminal);
  EXPECT_LT(worst, 0.01 * std::abs(terminal));
}

TEST_P(InertiaPhysics, AResponseTimeFarAboveTheStepFallsFreely)
{
  // tau >> t: the drag has no time to act, so in still fluid the slip is
  // (1 - beta) g t and the fall (1 - beta) g t^2 / 2 (to within t / tau).
  // The step's terminal-slip form lost every digit here (slip 0 from
  // tau / h = 1e8 on, 56% off at 1e7).
  const bp::VectorField still = stillFlow();
  const double h = 0.004;
  for (float tau : { 0.04f, 4e4f, 4e6f, 4e30f })
  {
    bp::Parameters p = heavy({ 0, 0, 0.5f }, { 0, 0, 0.5f }, tau, 1000.0f);
    p.gravity = { 0, 0, -9.81f };
    System s(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Point), p, still);
    const double a = (1.0 - bp::addedMassFactor(1000.0f)) * -9.81;
    for (int k = 1; k <= 100; ++k)
      s.step((k - 1) * h, h);
    const double t = 100 * h;
    // The exact solution, tau a (1 - E(t)) and tau a (t - tau (1 - E(t))),
    // by its series where t / tau is small.
    const double x = t / tau;
    const double slip = x < 1e-3 ? a * t * (1.0 - x / 2.0) : -tau * a * std::expm1(-x);
    const double fall =
      x < 1e-3 ? a * t * t * (0.5 - x / 6.0) : tau * a * (t + tau * std::expm1(-x));
    const std::vector<float> slips = s.slips(), positions = s.positions();
    std::printf("%s, tau %g: slip %.6f (exact %.6f), fall %.6f (exact %.6f)\n", engine(),
      double(tau), double(slips[2]), slip, double(positions[2]) - 0.5, fall);
    EXPECT_NEAR(slips[2], slip, 1e-4 * std::abs(slip)) << "tau " << tau;
    EXPECT_NEAR(positions[2] - 0.5, fall, 1e-4 * std::abs(fall)) << "tau " << tau;
  }
}

TEST_P(InertiaPhysics, HeavyParticlesLeaveAVortexAndBubblesGoIn)
{
  // Solid-body rotation at omega = 1 over [-1, 1]^3: dr/dt = tau (1 - beta) r.
  const bp::VectorField vortex =
    flowOn(bp::AnalyticFlow::SolidBodyRotation, box(9, -1, 1, 9), false);
  for (float ratio : { 1000.0f, 0.001f })
  {
    const bp::Parameters p = heavy({ 0.3f, 0, 0 }, { 0.3f, 0, 0 }, 0.01f, ratio);
    System s(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Point), p, vortex);
    const double h = 2 * Pi / 1000;
    for (int k = 0; k < 1000; ++k)
      s.step(k * h, h);
    const std::vector<float> x = s.positions();
    const double rate = std::log(std::hypot(x[0], x[1]) / 0.3) / (2 * Pi);
    const double expected = 0.01 * (1.0 - bp::addedMassFactor(ratio));
    std::printf("%s, density ratio %g: radial rate %.6f, tau (1 - beta) omega^2 %.6f\n", engine(),
      double(ratio), rate, expected);
    EXPECT_NEAR(rate, expected, 0.05 * std::abs(expected));
  }
}

TEST_P(InertiaPhysics, ZeroResponseTimeIsTheMasslessTrace)
{
  const bp::VectorField gyre = flowOn(bp::AnalyticFlow::DoubleGyre, box(33, 0, 1, 1), true);
  bp::Parameters massless = heavy({ 0.1f, 0.1f, 0 }, { 0.9f, 0.9f, 0 }, 0.0f, 1000.0f);
  massless.numberOfElements = 50;
  massless.gravity = { 0, -1, 0 };
  massless.planeAxis = 2;
  bp::Parameters off = massless;
  off.inertia = bp::Inertia::None;
  const bp::ElementTemplate strip = bp::builtinTemplate(bp::BuiltinShape::Strip8);
  System a(GetParam(), strip, massless, gyre), b(GetParam(), strip, off, gyre);
  for (int k = 0; k < 50; ++k)
  {
    a.step(k * 0.01, 0.01);
    b.step(k * 0.01, 0.01);
  }
  EXPECT_EQ(a.positions(), b.positions());
  EXPECT_TRUE(a.slips().empty());
}

INSTANTIATE_TEST_SUITE_P(
  Engines, InertiaPhysics, ::testing::Values(false, true), bptest::engineName);

namespace
{
struct ParityCase
{
  bp::BuiltinShape shape;
  bp::Integrator integrator;
  bp::Restoration restoration;
  bool unsteady;
  bp::Linking linking = bp::Linking::None;
};

void compareEngines(const ParityCase& c)
{
  ASSERT_TRUE(bp::haveSharedContext());
  const bp::GridGeometry g = box(24, -1, 1, 24);
  const bp::VectorField field =
    flowOn(c.unsteady ? bp::AnalyticFlow::DoubleGyre : bp::AnalyticFlow::ABC, g, c.unsteady);
  bp::Parameters p = heavy({ -0.6f, -0.6f, -0.6f }, { 0.6f, 0.6f, 0.6f }, 0.05f, 20.0f);
  p.numberOfElements = 200;
  p.elementSize = 0.1f;
  p.lifetimeMin = 0.3f;
  p.lifetimeMax = 1.2f; // elements placed again: their slips start at 0
  p.integrator = c.integrator;
  p.restoration = c.restoration;
  p.iterations = 2;
  p.orientation = bp::Orientation::Random;
  p.linking = c.linking;
  p.gravity = { 0.2f, 0.0f, -1.0f };
  p.seed = 21;
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  System cpu(false, shape, p, field), gpu(true, shape, p, field);
  const double dt = 0.01;
  for (int k = 0; k < 100; ++k)
  {
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
  }
  const std::vector<float> x = cpu.positions(), y = gpu.positions();
  const std::vector<float> s = cpu.slips(), t = gpu.slips();
  ASSERT_EQ(x.size(), y.size());
  ASSERT_EQ(s.size(), t.size());
  ASSERT_EQ(s.size(), x.size());
  double worst = 0.0, worstSlip = 0.0, largestSlip = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
  {
    worst = std::max(worst, double(std::abs(x[k] - y[k])));
    worstSlip = std::max(worstSlip, double(std::abs(s[k] - t[k])));
    largestSlip = std::max(largestSlip, double(std::abs(s[k])));
  }
  std::printf("%s, integrator %d, restoration %d, %s%s: positions within %.3g, slips within "
              "%.3g (largest %.3g)\n",
    shape.name.c_str(), int(c.integrator), int(c.restoration), c.unsteady ? "unsteady" : "steady",
    c.linking != bp::Linking::None ? ", linked" : "", worst, worstSlip, largestSlip);
  EXPECT_LT(worst, 1e-4 * g.diagonal());
  EXPECT_LT(worstSlip, 1e-3 * std::max(largestSlip, 1e-3));
  EXPECT_GT(largestSlip, 1e-3); // the particles did carry inertia
}
} // namespace

TEST(GpuInertia, MatchesTheCpuEngine)
{
  using I = bp::Integrator;
  using R = bp::Restoration;
  const ParityCase cases[] = {
    { bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, false },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, true },
    { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, false },
    { bp::BuiltinShape::Paddlewheel, I::RK2, R::GaussSeidel, true },
    { bp::BuiltinShape::Square, I::Euler, R::Jacobi, false, bp::Linking::Chain },
  };
  for (const ParityCase& c : cases)
    compareEngines(c);
}
