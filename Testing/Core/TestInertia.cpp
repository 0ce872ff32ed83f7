// SPDX-License-Identifier: BSD-3-Clause
// Heavy particles on the CPU engine (Core/Engine/Inertia.h), against the physics:
// settling in still fluid, drag relaxation in a uniform flow, the radial
// drift out of (and a bubble's into) a vortex, the massless limit, a
// response time far below the step, rigid elements, preferential
// concentration in the double gyre, migration, and the refused settings.
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace
{
using bptest::uniformFlow;

/// One Point element released at `at`, Maxey-Riley with tau and density ratio.
bp::Parameters heavy(std::array<float, 3> at, float tau, float densityRatio)
{
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.01f;
  p.emitterMin = p.emitterMax = at;
  p.lifetimeMin = p.lifetimeMax = 1e6f;
  p.integrator = bp::Integrator::RK4;
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = tau;
  p.densityRatio = densityRatio;
  return p;
}

bp::Engine started(const bp::Parameters& p, bp::BuiltinShape shape = bp::BuiltinShape::Point)
{
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(shape), p), "");
  engine.initialize(bp::serialRunner());
  return engine;
}

double radiusOf(const bp::Engine& engine)
{
  const float* x = engine.positions().data();
  return std::hypot(double(x[0]), double(x[1]));
}
} // namespace

TEST(Inertia, AddedMassFactorSpansHeavyNeutralAndBubbles)
{
  EXPECT_FLOAT_EQ(bp::addedMassFactor(1.0f), 1.0f);
  EXPECT_NEAR(bp::addedMassFactor(1e6f), 0.0f, 2e-6f);
  EXPECT_NEAR(bp::addedMassFactor(0.001f), 3.0f / 1.002f, 1e-6f);
  EXPECT_NEAR(bp::addedMassFactor(2.65f), 3.0f / 6.3f, 1e-6f);
}

TEST(Inertia, SettlesInStillFluidAtItsTerminalVelocity)
{
  // Still fluid: dv/dt = -v / tau + (1 - beta) g, so v = T (1 - exp(-t/tau))
  // with T = tau (1 - beta) g, and z = T (t - tau (1 - exp(-t/tau))).
  const bp::VectorField still = uniformFlow({ 0, 0, 0 });
  for (float ratio : { 2.65f, 1000.0f })
  {
    bp::Parameters p = heavy({ 0, 0, 0.5f }, 0.05f, ratio);
    p.gravity = { 0, 0, -9.81f };
    bp::Engine engine = started(p);
    const double tau = p.responseTime, beta = bp::addedMassFactor(ratio), h = 0.004;
    const double terminal = tau * (1.0 - beta) * -9.81;
    double worstVelocity = 0.0, worstPosition = 0.0;
    for (int s = 1; s <= 100; ++s)
    {
      engine.step(still, (s - 1) * h, h, bp::serialRunner());
      const double t = s * h, approach = 1.0 - std::exp(-t / tau);
      const double v = engine.slips()[2]; // the flow is still: the slip is the velocity
      worstVelocity = std::max(worstVelocity, std::abs(v - terminal * approach));
      const double z = 0.5 + terminal * (t - tau * approach);
      worstPosition = std::max(worstPosition, std::abs(engine.positions()[2] - z));
      EXPECT_FLOAT_EQ(engine.positions()[0], 0.0f);
    }
    std::printf("density ratio %g: terminal %.5f, velocity within %.2e (%.4f%%), height within "
                "%.2e\n",
      double(ratio), terminal, worstVelocity, 100.0 * worstVelocity / std::abs(terminal),
      worstPosition);
    EXPECT_LT(worstVelocity, 0.01 * std::abs(terminal)); // within 1% at every step
    EXPECT_NEAR(engine.slips()[2], terminal, 0.01 * std::abs(terminal));
    EXPECT_LT(worstPosition, 0.01 * std::abs(terminal) * 100 * h);
  }
}

TEST(Inertia, ResponseTimeFarBelowTheStepNeitherBlowsUpNorStalls)
{
  const bp::VectorField still = uniformFlow({ 0, 0, 0 });
  bp::Parameters p = heavy({ 0, 0, 0.5f }, 1e-5f, 1000.0f);
  p.gravity = { 0, 0, -9.81f };
  EXPECT_TRUE(bp::nearlyMassless(p, 0.05));
  EXPECT_FALSE(bp::nearlyMassless(p, 0.005));
  bp::Engine engine = started(p);
  const double terminal = 1e-5 * (1.0 - bp::addedMassFactor(1000.0f)) * -9.81;
  for (int s = 0; s < 50; ++s)
  {
    engine.step(still, s * 0.05, 0.05, bp::serialRunner());
    ASSERT_TRUE(std::isfinite(engine.slips()[2]));
    EXPECT_NEAR(engine.slips()[2], terminal, 1e-3 * std::abs(terminal));
  }
  EXPECT_NEAR(engine.positions()[2], 0.5 + terminal * 2.5, 1e-6);
}

TEST(Inertia, ReachesAUniformFlowByDrag)
{
  // Released at rest in a uniform flow U (slip -U): v = U (1 - exp(-t/tau)).
  const std::array<float, 3> U = { 0.4f, -0.2f, 0.1f };
  const bp::VectorField uniform = uniformFlow(U);
  const bp::Parameters p = heavy({ -0.5f, 0.5f, 0 }, 0.1f, 3.0f);
  bp::Engine engine = started(p);
  for (int k = 0; k < 3; ++k)
    engine.mutableSlips()[std::size_t(k)] = -U[std::size_t(k)];
  const double h = 0.01;
  double worst = 0.0;
  for (int s = 1; s <= 100; ++s)
  {
    engine.step(uniform, (s - 1) * h, h, bp::serialRunner());
    const double approach = 1.0 - std::exp(-s * h / 0.1);
    for (int k = 0; k < 3; ++k)
    {
      const double v = U[std::size_t(k)] + engine.slips()[std::size_t(k)];
      worst = std::max(worst, std::abs(v - U[std::size_t(k)] * approach));
    }
  }
  std::printf("drag relaxation: velocity within %.2e of U (1 - exp(-t/tau))\n", worst);
  EXPECT_LT(worst, 0.01 * 0.1);
}

TEST(Inertia, HeavyParticlesLeaveAVortexAndBubblesGoIn)
{
  // Solid-body rotation at omega = 1: dr/dt = tau (1 - beta) omega^2 r for
  // small tau omega, outwards for heavy particles, inwards for bubbles. An
  // element's centre is measured against the same element without inertia
  // (its restoration's own drift taken out).
  const bp::VectorField vortex =
    bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, bptest::grid(9));
  const double Pi = 3.14159265358979;
  auto turnRate = [&](const bp::Parameters& p, bp::BuiltinShape shape)
  {
    bp::Engine engine = started(p, shape);
    const std::size_t n = engine.particlesPerElement();
    auto radius = [&]
    {
      double c[2] = { 0, 0 };
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 2; ++k)
          c[k] += engine.positions()[3 * i + std::size_t(k)] / double(n);
      return std::hypot(c[0], c[1]);
    };
    const double r0 = radius(), h = 2 * Pi / 2000;
    for (int s = 0; s < 2000; ++s)
      engine.step(vortex, s * h, h, bp::serialRunner());
    return std::log(radius() / r0) / (2 * Pi);
  };
  for (auto shape : { bp::BuiltinShape::Point, bp::BuiltinShape::Square })
  {
    for (float ratio : { 1000.0f, 2.65f, 0.001f })
    {
      bp::Parameters p = heavy({ 0.3f, 0, 0 }, 0.01f, ratio);
      p.elementSize = 0.05f;
      p.orientation = bp::Orientation::Fixed;
      bp::Parameters massless = p;
      massless.inertia = bp::Inertia::None;
      const double own = turnRate(massless, shape);
      const double rate = turnRate(p, shape) - own;
      const double expected = 0.01 * (1.0 - bp::addedMassFactor(ratio));
      std::printf("%s, density ratio %g: dr/dt / r = %.6f over a turn (less %.6f without "
                  "inertia), tau (1 - beta) omega^2 = %.6f (%.2f%% off)\n",
        shape == bp::BuiltinShape::Point ? "point" : "square", double(ratio), rate, own, expected,
        100.0 * (rate / expected - 1.0));
      EXPECT_NEAR(rate, expected, 0.05 * std::abs(expected));
    }
  }
}

TEST(Inertia, ZeroResponseTimeIsTheTracerBitForBitAndTinyOnesAreClose)
{
  const bp::VectorField field =
    bptest::unsteadyFlow(bp::AnalyticFlow::DoubleGyre, bptest::grid(33, 0.0, 1.0, 1), 0.0, 0.5);
  bp::Parameters tracer;
  tracer.numberOfElements = 64;
  tracer.elementSize = 0.03f;
  tracer.emitterMin = { 0.1f, 0.1f, 0 };
  tracer.emitterMax = { 0.9f, 0.9f, 0 };
  tracer.integrator = bp::Integrator::RK2;
  tracer.lifetimeMin = tracer.lifetimeMax = 1e6f;
  tracer.planeAxis = 2;
  bp::Parameters zero = tracer, tiny = tracer;
  zero.inertia = tiny.inertia = bp::Inertia::MaxeyRiley;
  zero.gravity = tiny.gravity = { 0, -9.81f, 0 };
  tiny.responseTime = 1e-6f;
  tiny.densityRatio = zero.densityRatio = 1000.0f;
  bp::Engine a = started(tracer, bp::BuiltinShape::Strip8);
  bp::Engine b = started(zero, bp::BuiltinShape::Strip8);
  bp::Engine c = started(tiny, bp::BuiltinShape::Strip8);
  EXPECT_TRUE(b.slips().empty()); // tau = 0 keeps no slip: nothing more per particle
  EXPECT_EQ(c.slips().size(), c.positions().size());
  for (int s = 0; s < 100; ++s)
  {
    for (bp::Engine* e : { &a, &b, &c })
      e->step(field, s * 0.005, 0.005, bp::serialRunner());
  }
  EXPECT_EQ(a.positions(), b.positions());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.positions().size(); ++i)
    worst = std::max(worst, double(std::abs(a.positions()[i] - c.positions()[i])));
  std::printf("tau = 1e-6: within %.2e of the tracer after 100 steps\n", worst);
  EXPECT_LT(worst, 1e-5);
}

TEST(Inertia, HeavyParticlesLeaveTheDoubleGyresCores)
{
  // Preferential concentration: heavy particles are flung out of the eddies
  // towards the strain between them, so fewer of them stay in the cores
  // (within 0.15 of the gyres' centres, x = 0.5 and 1.5 of [0, 2] x [0, 1],
  // here laid over [0, 1]^2) than massless tracers.
  const bp::GridGeometry g = bptest::grid(65, 0.0, 1.0, 1);
  bp::Parameters p;
  p.numberOfElements = 2000;
  p.elementSize = 0.01f;
  p.emitterMin = { 0.02f, 0.02f, 0 };
  p.emitterMax = { 0.98f, 0.98f, 0 };
  p.lifetimeMin = p.lifetimeMax = 1e6f;
  p.integrator = bp::Integrator::RK2;
  p.planeAxis = 2;
  p.resetWhen = bp::ResetWhen::CenterLeaves;
  bp::Parameters inertial = p;
  inertial.inertia = bp::Inertia::MaxeyRiley;
  inertial.responseTime = 0.5f;
  inertial.densityRatio = 1000.0f;
  bp::Engine tracers = started(p), particles = started(inertial);
  const double h = 0.05;
  for (int s = 0; s < 400; ++s)
  {
    const double t = s * h, t0 = 0.5 * std::floor(t / 0.5);
    const bp::VectorField field =
      bptest::unsteadyFlow(bp::AnalyticFlow::DoubleGyre, g, t0, t0 + 0.5);
    tracers.step(field, t, h, bp::serialRunner());
    particles.step(field, t, h, bp::serialRunner());
  }
  auto coreShare = [](const bp::Engine& e)
  {
    std::size_t in = 0;
    for (std::size_t k = 0; k < e.elementCount(); ++k)
    {
      const float* x = e.positions().data() + 3 * k;
      const double dx = std::min(std::abs(x[0] - 0.25), std::abs(x[0] - 0.75)) * 2.0;
      in += std::hypot(dx, x[1] - 0.5) < 0.15 ? 1 : 0;
    }
    return double(in) / double(e.elementCount());
  };
  const double massless = coreShare(tracers), heavy = coreShare(particles);
  std::printf("double gyre after 20 time units: share in the cores %.3f massless, %.3f heavy "
              "(tau 0.5, density ratio 1000)\n",
    massless, heavy);
  EXPECT_LT(heavy, 0.5 * massless);
}

TEST(Inertia, MigrationCarriesTheSlip)
{
  const bp::VectorField still = uniformFlow({ 0, 0, 0 });
  bp::Parameters p = heavy({ 0, 0, 0 }, 0.1f, 2.0f);
  p.numberOfElements = 3;
  p.gravity = { 0, 0, -1 };
  bp::Parameters massless = p;
  massless.inertia = bp::Inertia::None;
  bp::Engine a = started(p, bp::BuiltinShape::Square);
  bp::Engine none = started(massless, bp::BuiltinShape::Square);
  EXPECT_EQ(a.recordWords(), none.recordWords() + 3 * 4); // 12 bytes a particle
  a.step(still, 0.0, 0.01, bp::serialRunner());
  std::vector<std::uint32_t> record;
  a.packElement(1, record);
  bp::Engine b = started(p, bp::BuiltinShape::Square);
  ASSERT_EQ(b.exchange({ 0, 1, 0 }, {}), ""); // drop element 1, then take it back
  ASSERT_EQ(b.exchange({ 0, 0 }, record), "");
  ASSERT_EQ(b.elementCount(), 3u);
  for (std::size_t i = 0; i < 12; ++i)
    EXPECT_EQ(b.slips()[12 + i], a.slips()[12 + i]);
}

TEST(Inertia, BadSettingsAreRefusedByName)
{
  bp::Parameters p = heavy({ 0, 0, 0 }, 0.1f, 2.0f);
  const bp::ElementTemplate point = bp::builtinTemplate(bp::BuiltinShape::Point);
  auto refusal = [&](const bp::Parameters& q) { return bp::Engine::validate(point, q); };
  EXPECT_EQ(refusal(p), "");
  bp::Parameters q = p;
  q.responseTime = -1.0f;
  EXPECT_NE(refusal(q).find("ResponseTime"), std::string::npos);
  q.responseTime = std::nanf("");
  EXPECT_NE(refusal(q).find("ResponseTime"), std::string::npos);
  q = p;
  q.densityRatio = 0.0f;
  EXPECT_NE(refusal(q).find("DensityRatio"), std::string::npos);
  q.densityRatio = std::nanf("");
  EXPECT_NE(refusal(q).find("DensityRatio"), std::string::npos);
  q = p;
  q.gravity[1] = std::nanf("");
  EXPECT_NE(refusal(q).find("Gravity"), std::string::npos);
  q = p;
  q.anchor = bp::Anchor::Centre;
  EXPECT_NE(refusal(q).find("inertia has no meaning"), std::string::npos);
  // Finite in double, beyond float: infinity (never undefined behaviour),
  // refused with the range rather than as "not finite".
  EXPECT_EQ(bp::settingAsFloat(1e300), std::numeric_limits<float>::infinity());
  EXPECT_EQ(bp::settingAsFloat(-1e39), -std::numeric_limits<float>::infinity());
  EXPECT_EQ(bp::settingAsFloat(3e38), 3e38f);
  EXPECT_TRUE(std::isnan(bp::settingAsFloat(std::nan(""))));
  // Below float's smallest (issue 53): the sign and "not 0" stay, so a tiny
  // negative response time is refused as -1e-40 is, and a tiny positive one
  // is a response time (noted as nearly massless), not none.
  for (const double tiny : { 1e-46, 1e-300, 5e-324 })
  {
    EXPECT_EQ(bp::settingAsFloat(tiny), std::numeric_limits<float>::denorm_min()) << tiny;
    EXPECT_EQ(bp::settingAsFloat(-tiny), -std::numeric_limits<float>::denorm_min()) << tiny;
    q = p;
    q.responseTime = bp::settingAsFloat(-tiny);
    EXPECT_NE(refusal(q).find("ResponseTime"), std::string::npos) << -tiny;
    q.responseTime = bp::settingAsFloat(tiny);
    EXPECT_TRUE(bp::carriesInertia(q)) << tiny;
    EXPECT_TRUE(bp::nearlyMassless(q, 1e-30)) << tiny;
  }
  EXPECT_EQ(bp::settingAsFloat(0.0), 0.0f);
  EXPECT_EQ(bp::settingAsFloat(1e-40), 1e-40f);
  q = p;
  q.responseTime = bp::settingAsFloat(1e39);
  EXPECT_NE(refusal(q).find("ResponseTime"), std::string::npos);
  EXPECT_NE(refusal(q).find("3.4e38"), std::string::npos);
  q = p;
  q.densityRatio = bp::settingAsFloat(1e300);
  EXPECT_NE(refusal(q).find("3.4e38"), std::string::npos);
  q = p;
  q.gravity[2] = bp::settingAsFloat(-1e39);
  EXPECT_NE(refusal(q).find("3.4e38"), std::string::npos);
  // Without inertia the inertial settings are not read.
  q.inertia = bp::Inertia::None;
  q.anchor = bp::Anchor::None;
  q.responseTime = -1.0f;
  EXPECT_EQ(refusal(q), "");
}

TEST(Inertia, SettlingDistanceIsFreeFallEarlyAndTerminalLate)
{
  bp::Parameters p;
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = 0.5f;
  p.densityRatio = 2.0f;     // beta = 0.6
  p.gravity = { 0, -3, -4 }; // |g| = 5
  const double terminal = 0.5 * 0.4 * 5.0;
  // beta is a float (addedMassFactor): within 1e-6 relative.
  EXPECT_NEAR(bp::terminalSettlingSpeed(p), terminal, 1e-6 * terminal);
  // Far below tau it is free fall, (1 - beta) |g| t^2 / 2 (less t / (3 tau) of
  // it, 7e-5); far above, the terminal speed's over t - tau.
  EXPECT_NEAR(bp::settlingDistance(p, 1e-4), 0.5 * 0.4 * 5.0 * 1e-8, 1e-4 * 1e-8);
  EXPECT_NEAR(bp::settlingDistance(p, 1000.0), terminal * (1000.0 - 0.5), 1e-6 * 1000.0);
  // Its exact form in between (the still-fluid solution the engines step).
  EXPECT_NEAR(bp::settlingDistance(p, 1.0), terminal * (1.0 - 0.5 * (1.0 - std::exp(-2.0))), 1e-6);
  // A response time far above t: free fall still, not tau times rounding
  // noise (which would be 1e14 times too far at tau = 1e30).
  p.responseTime = 1e30f;
  EXPECT_NEAR(bp::settlingDistance(p, 2.0), 0.4 * 5.0 * 2.0, 1e-6 * 4.0);
  p.inertia = bp::Inertia::None;
  EXPECT_EQ(bp::settlingDistance(p, 1.0), 0.0);
}

TEST(Inertia, SettlingTimeAndSpeedAcrossALength)
{
  bp::Parameters p;
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = 0.5f;
  p.densityRatio = 2.0f;     // beta = 0.6
  p.gravity = { 0, -3, -4 }; // |g| = 5: terminal 1, a = 2
  for (const double length : { 1e-6, 0.3, 1.0, 1e3 })
  {
    const double t = bp::settlingTime(p, length);
    EXPECT_NEAR(bp::settlingDistance(p, t), length, 1e-9 * length) << length;
    EXPECT_NEAR(
      bp::settlingSpeedAfter(p, t), bp::terminalSettlingSpeed(p) * (1.0 - std::exp(-t / 0.5)), 1e-9)
      << length;
  }
  // Far: at the terminal speed, behind it by tau; near: free fall.
  EXPECT_NEAR(bp::settlingTime(p, 1e3), 1e3 + 0.5, 1e-6 * 1e3); // beta is a float
  EXPECT_NEAR(bp::settlingTime(p, 1e-6), std::sqrt(2.0 * 1e-6 / 2.0), 1e-3 * 1e-3);
  p.responseTime = 1e30f;
  EXPECT_NEAR(bp::settlingSpeedAfter(p, bp::settlingTime(p, 1.0)), 2.0, 1e-6);
  // Nothing settles: no gravity, neutral buoyancy, no inertia, not finite.
  p.responseTime = 0.5f;
  bp::Parameters q = p;
  q.gravity = { 0, 0, 0 };
  EXPECT_EQ(bp::settlingTime(q, 1.0), 0.0);
  q = p;
  q.densityRatio = 1.0f;
  EXPECT_EQ(bp::settlingTime(q, 1.0), 0.0);
  q = p;
  q.inertia = bp::Inertia::None;
  EXPECT_EQ(bp::settlingTime(q, 1.0), 0.0);
  EXPECT_EQ(bp::settlingSpeedAfter(q, 1.0), 0.0);
  q = p;
  q.gravity[1] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(bp::settlingTime(q, 1.0), 0.0);
}
