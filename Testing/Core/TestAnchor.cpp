// SPDX-License-Identifier: BSD-3-Clause
// Anchor = Centre on the CPU engine: the step of an anchored element is a
// free element's step moved back whole to its release centre; what the
// engine refuses to anchor; the release-speed test and lifetimes with anchors.
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
bp::Parameters anchorParameters(std::size_t elements, float size)
{
  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = size;
  p.emitterMin = { -0.6f, -0.6f, -0.4f };
  p.emitterMax = { 0.6f, 0.6f, 0.4f };
  p.lifetimeMin = p.lifetimeMax = 1000.0f;
  p.seed = 11;
  return p;
}

bp::Engine started(bp::BuiltinShape shape, const bp::Parameters& p)
{
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(shape), p), "");
  engine.initialize(bp::serialRunner());
  return engine;
}

/// The mean of element e's particles.
std::array<double, 3> meanOf(const bp::Engine& engine, std::size_t e)
{
  const std::size_t n = engine.particlesPerElement();
  std::array<double, 3> c = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      c[std::size_t(k)] += engine.positions()[3 * (e * n + i) + std::size_t(k)] / double(n);
  return c;
}
} // namespace

TEST(Anchor, IsRefusedForSuperSetsPinnedParticlesAndOffCentreTemplates)
{
  bp::Parameters p = anchorParameters(16, 0.1f);
  p.anchor = bp::Anchor::Centre;
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  bp::Engine engine;
  EXPECT_EQ(engine.configure(cross, p), "");
  p.linking = bp::Linking::Sheet;
  EXPECT_NE(
    engine.configure(cross, p).find("super set (Linking) cannot be anchored"), std::string::npos);
  p.linking = bp::Linking::None;
  bp::ElementTemplate pinned = cross;
  pinned.pinned.assign(cross.particleCount(), 0);
  EXPECT_EQ(engine.configure(pinned, p), ""); // flags, none set
  pinned.pinned[2] = 1;
  EXPECT_NE(engine.configure(pinned, p).find("pinned"), std::string::npos);
  bp::ElementTemplate offCentre = cross;
  for (auto& r : offCentre.rest)
    r[0] += 0.1f;
  EXPECT_NE(engine.configure(offCentre, p).find("centred on its centroid"), std::string::npos);
  p.anchor = bp::Anchor(7);
  EXPECT_NE(engine.configure(cross, p).find("None or Centre"), std::string::npos);
  // Without an anchor every one of them runs as before.
  p.anchor = bp::Anchor::None;
  EXPECT_EQ(engine.configure(offCentre, p), "");
  EXPECT_EQ(engine.configure(pinned, p), "");
}

TEST(Anchor, AStepIsTheFreeStepMovedBackWhole)
{
  // In the first step both start from the same placement: the anchored
  // element's particles are the free one's moved by (release centre - free
  // mean), and its forces (the restoration's) are the free one's.
  const bp::VectorField field = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(17));
  for (auto restoration : { bp::Restoration::AveragedJacobi, bp::Restoration::ShapeMatching })
  {
    bp::Parameters p = anchorParameters(50, 0.2f);
    p.restoration = restoration;
    p.integrator = bp::Integrator::RK4;
    bp::Engine free = started(bp::BuiltinShape::Paddlewheel, p);
    p.anchor = bp::Anchor::Centre;
    bp::Engine anchored = started(bp::BuiltinShape::Paddlewheel, p);
    ASSERT_EQ(free.positions(), anchored.positions());
    free.step(field, 0.0, 0.02, bp::serialRunner());
    anchored.step(field, 0.0, 0.02, bp::serialRunner());
    const std::size_t n = free.particlesPerElement();
    double worst = 0.0, moved = 0.0;
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      const std::array<double, 3> c = meanOf(free, e);
      const float* c0 = &anchored.initialCenters()[3 * e];
      moved = std::max(moved, std::hypot(c[0] - c0[0], c[1] - c0[1], c[2] - c0[2]));
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
        {
          const std::size_t j = 3 * (e * n + i) + std::size_t(k);
          const double expected = free.positions()[j] + (c0[k] - c[std::size_t(k)]);
          worst = std::max(worst, std::abs(anchored.positions()[j] - expected));
        }
    }
    EXPECT_GT(moved, 0.01); // the free elements did move
    EXPECT_LT(worst, 1e-6);
    EXPECT_EQ(free.forces(), anchored.forces());
  }
}

TEST(Anchor, CentresStayThroughManyStepsAndLifetimesStillEnd)
{
  // A uniform flow along +x would carry a free element out in half a time unit.
  bp::GridGeometry g = bptest::grid(9);
  bp::FieldSlice s;
  auto v = std::make_shared<std::vector<float>>(3 * g.pointCount(), 0.0f);
  for (std::size_t i = 0; i < g.pointCount(); ++i)
    (*v)[3 * i] = 2.0f;
  s.velocity = v;
  const bp::VectorField field(g, s);
  bp::Parameters p = anchorParameters(30, 0.2f);
  p.lifetimeMin = 0.5f;
  p.lifetimeMax = 0.7f;
  p.anchor = bp::Anchor::Centre;
  p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
  bp::Engine engine = started(bp::BuiltinShape::Cross, p);
  const std::vector<float> first = engine.initialCenters();
  double worst = 0.0;
  for (int step = 0; step < 45; ++step) // 0.45: within every first lifetime
  {
    engine.step(field, step * 0.01, 0.01, bp::serialRunner());
    for (std::size_t e = 0; e < p.numberOfElements; ++e)
    {
      EXPECT_EQ(engine.generations()[e], 0u) << "element " << e << " released again";
      const std::array<double, 3> c = meanOf(engine, e);
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(c[std::size_t(k)] - first[3 * e + std::size_t(k)]));
    }
  }
  EXPECT_LT(worst, 1e-6);
  for (int step = 45; step < 100; ++step)
    engine.step(field, step * 0.01, 0.01, bp::serialRunner());
  // Every life ended (0.7 at most): each element released again elsewhere,
  // where it is held now.
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
  {
    EXPECT_GE(engine.generations()[e], 1u);
    const std::array<double, 3> c = meanOf(engine, e);
    const float* c1 = &engine.initialCenters()[3 * e];
    EXPECT_GT(std::abs(c1[0] - first[3 * e]) + std::abs(c1[1] - first[3 * e + 1]), 0.0f);
    EXPECT_NEAR(c[0], c1[0], 1e-6);
    EXPECT_NEAR(c[1], c1[1], 1e-6);
  }
}

TEST(Anchor, TheReleaseSpeedTestReadsTheMotionBeforeTheMoveBack)
{
  // In solid-body rotation, releases near the axis move slowly: a free and
  // an anchored system retry the same ones (not every anchored element,
  // whose centre the move back keeps at its release).
  const bp::VectorField field =
    bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, bptest::grid(17));
  bp::Parameters p = anchorParameters(200, 0.1f);
  p.releaseMinSpeed = 0.3f; // releases within 0.3 of the axis
  bp::Engine free = started(bp::BuiltinShape::Cross, p);
  p.anchor = bp::Anchor::Centre;
  bp::Engine anchored = started(bp::BuiltinShape::Cross, p);
  for (int step = 0; step < 3; ++step)
  {
    free.step(field, step * 0.01, 0.01, bp::serialRunner());
    anchored.step(field, step * 0.01, 0.01, bp::serialRunner());
  }
  std::size_t retried = 0;
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
  {
    EXPECT_EQ(anchored.generations()[e], free.generations()[e]) << "element " << e;
    retried += anchored.generations()[e] > 0;
  }
  EXPECT_GT(retried, 5u);
  EXPECT_LT(retried, p.numberOfElements / 2);
}
