// SPDX-License-Identifier: BSD-3-Clause
// What happens at the field's boundary (Parameters::boundary, engine
// specification "Boundaries"): Release Again places an element that left the
// field again at once; Terminate hides it until its lifetime runs out.
#include "Engine.h"
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace
{

/// A uniform flow along +x on [-1, 1]^3: elements leave through x = 1.
bp::VectorField uniformFlow()
{
  const bp::GridGeometry g = bptest::grid(5);
  bp::FieldSlice s;
  auto v = std::make_shared<std::vector<float>>(3 * g.pointCount(), 0.0f);
  for (std::size_t i = 0; i < g.pointCount(); ++i)
    (*v)[3 * i] = 1.0f;
  s.velocity = v;
  return bp::VectorField(g, s);
}

bp::Parameters outflowParameters(bp::Boundary boundary)
{
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.25f;
  p.emitterMin = { 0.5f, 0, 0 };
  p.emitterMax = { 0.5f, 0, 0 };
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = 1.0f; // the centre leaves after 0.5
  p.lifetimeMax = 1.0f;
  p.boundary = boundary;
  return p;
}

bp::Engine configured(const bp::Parameters& p)
{
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.initialize(bp::serialRunner());
  return engine;
}

/// 64-bit FNV-1a over positions, flags, generations and lifetimes.
std::uint64_t digest(const bp::Engine& engine)
{
  std::uint64_t h = 1469598103934665603ull;
  const auto bytes = [&h](const void* data, std::size_t size)
  {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
      h = (h ^ b[i]) * 1099511628211ull;
  };
  bytes(engine.positions().data(), engine.positions().size() * sizeof(float));
  bytes(engine.resetFlags().data(), engine.resetFlags().size());
  bytes(engine.generations().data(), engine.generations().size() * sizeof(std::uint32_t));
  bytes(engine.lifetimes().data(), engine.lifetimes().size() * sizeof(float));
  return h;
}

} // namespace

TEST(Boundary, ReleaseAgainPlacesALeavingElementAtOnce)
{
  const bp::VectorField field = uniformFlow();
  bp::Engine engine = configured(outflowParameters(bp::Boundary::ReleaseAgain));
  int step = 0;
  for (; step < 100 && !engine.resetFlags()[0]; ++step)
    engine.step(field, step * 0.01, 0.01, bp::serialRunner());
  ASSERT_EQ(engine.resetFlags()[0], bp::ResetDue);
  engine.step(field, step * 0.01, 0.01, bp::serialRunner());
  EXPECT_EQ(engine.generations()[0], 1u);
  EXPECT_EQ(engine.resetFlags()[0], 0u);
}

TEST(Boundary, TerminatedWaitsForItsLifetime)
{
  const bp::VectorField field = uniformFlow();
  bp::Engine engine = configured(outflowParameters(bp::Boundary::Terminate));
  const double h = 0.01;
  int step = 0;
  for (; step < 100 && !engine.resetFlags()[0]; ++step)
    engine.step(field, step * h, h, bp::serialRunner());
  // The centre left at x = 1 after about 0.5: terminated, not due.
  EXPECT_NEAR(step * h, 0.5, 0.011);
  ASSERT_EQ(engine.resetFlags()[0], bp::Terminated);
  EXPECT_TRUE(engine.resetFlags()[0] & bp::HiddenFlags);
  // Not replaced, and hidden, while its lifetime lasts.
  while (engine.lifetimes()[0] > 0.0f)
  {
    engine.step(field, step * h, h, bp::serialRunner());
    ++step;
    EXPECT_EQ(engine.generations()[0], 0u) << step;
    EXPECT_EQ(engine.resetFlags()[0], bp::Terminated) << step;
  }
  EXPECT_NEAR(step * h, 1.0, 0.011);
  // Then placed again as its next generation, shown, at its release centre.
  engine.step(field, step * h, h, bp::serialRunner());
  EXPECT_EQ(engine.generations()[0], 1u);
  EXPECT_EQ(engine.resetFlags()[0], 0u);
  EXPECT_NEAR(engine.positions()[0], 0.5f - 0.1875f + 0.01f, 0.2f);
}

TEST(Boundary, TerminateFollowsResetWhen)
{
  // Any Particle Leaves terminates the element when its first particle
  // leaves, its reach earlier than the centre.
  const bp::VectorField field = uniformFlow();
  for (const auto when : { bp::ResetWhen::CenterLeaves, bp::ResetWhen::AnyParticleLeaves })
  {
    bp::Parameters p = outflowParameters(bp::Boundary::Terminate);
    p.resetWhen = when;
    bp::Engine engine = configured(p);
    int step = 0;
    for (; step < 100 && !engine.resetFlags()[0]; ++step)
      engine.step(field, step * 0.01, 0.01, bp::serialRunner());
    float reach = 0.0f;
    for (const auto& r : engine.shape().rest)
      reach = std::max(reach, r[0] * p.elementSize);
    EXPECT_EQ(engine.resetFlags()[0], bp::Terminated);
    EXPECT_NEAR(step * 0.01, when == bp::ResetWhen::CenterLeaves ? 0.5 : 0.5 - reach, 0.011);
  }
}

TEST(Boundary, TerminateShowsFewerElementsInAnOutflow)
{
  // Many elements in a uniform outflow: with Terminate those that left wait
  // hidden; with Release Again none is ever hidden for leaving.
  const bp::VectorField field = uniformFlow();
  std::size_t hidden[2] = { 0, 0 };
  for (const auto boundary : { bp::Boundary::ReleaseAgain, bp::Boundary::Terminate })
  {
    bp::Parameters p = outflowParameters(boundary);
    p.numberOfElements = 200;
    p.emitterMin = { -0.8f, -0.8f, -0.8f };
    p.emitterMax = { 0.8f, 0.8f, 0.8f };
    p.lifetimeMin = 2.0f;
    p.lifetimeMax = 3.0f;
    bp::Engine engine = configured(p);
    for (int s = 0; s < 100; ++s)
      engine.step(field, s * 0.01, 0.01, bp::serialRunner());
    for (std::size_t e = 0; e < engine.elementCount(); ++e)
    {
      if (!(engine.resetFlags()[e] & bp::HiddenFlags))
        continue;
      ++hidden[int(boundary)];
      // A terminated element lies outside the field (its centre left).
      const std::size_t n = engine.particlesPerElement();
      float x = 0.0f;
      for (std::size_t i = 0; i < n; ++i)
        x += engine.positions()[3 * (e * n + i)];
      EXPECT_GT(x / float(n), 1.0f) << e;
    }
  }
  EXPECT_EQ(hidden[0], 0u);
  EXPECT_GT(hidden[1], 50u);
}

TEST(Boundary, SuperSetsRefuseTerminate)
{
  bp::Parameters p = outflowParameters(bp::Boundary::Terminate);
  p.numberOfElements = 4;
  p.linking = bp::Linking::Chain;
  bp::Engine engine;
  const std::string error = engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p);
  EXPECT_NE(error.find("Boundary = Terminate"), std::string::npos) << error;
  p.boundary = bp::Boundary(7);
  p.linking = bp::Linking::None;
  EXPECT_NE(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p)
              .find("Boundary must be Release Again, Terminate, Stick, Slip or Bounce"),
    std::string::npos);
}

TEST(Boundary, ReleaseAgainKeepsTheBitsOfBefore)
{
  // Release Again is the rule of before Boundary existed: these digests were
  // taken by the engine before it (a uniform outflow and a hurricane, by
  // centre and by particle, with a release speed and Along Flow).
  const bp::VectorField outflow = uniformFlow();
  const bp::VectorField hurricane =
    bptest::steadyFlow(bp::AnalyticFlow::Hurricane, bptest::grid(9));
  std::vector<std::uint64_t> digests;
  for (const bp::VectorField* field : { &outflow, &hurricane })
    for (const auto when : { bp::ResetWhen::CenterLeaves, bp::ResetWhen::AnyParticleLeaves })
    {
      bp::Parameters p;
      p.numberOfElements = 64;
      p.elementSize = 0.3f;
      p.emitterMin = { -0.9f, -0.9f, -0.9f };
      p.emitterMax = { 0.9f, 0.9f, 0.9f };
      p.lifetimeMin = 0.5f;
      p.lifetimeMax = 1.5f;
      p.resetWhen = when;
      p.releaseMinSpeed = 0.05f;
      p.orientation = bp::Orientation::AlongFlow;
      p.seed = 11;
      bp::Engine engine;
      EXPECT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip8), p), "");
      engine.initialize(bp::serialRunner());
      for (int s = 0; s < 150; ++s)
        engine.step(*field, s * 0.02, 0.02, bp::serialRunner());
      digests.push_back(digest(engine));
    }
  const std::vector<std::uint64_t> before = { 0xee8fa1d758363f89ull, 0xa5468d0fe56bc163ull,
    0x39b07d9d7f55d446ull, 0xeeb30303556d4f16ull };
  for (std::size_t k = 0; k < before.size(); ++k)
    EXPECT_EQ(digests[k], before[k]) << k << ": 0x" << std::hex << digests[k];
}
