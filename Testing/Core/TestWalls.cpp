// SPDX-License-Identifier: BSD-3-Clause
// The field's boundary as a wall (Boundary Stick, Slip, Bounce; Walls.h,
// engine specification 2.8): the rules for one particle, then the CPU
// engine's elements and heavy particles against them, and the settings the
// engine refuses.
#include "DomainMask.h"
#include "TestHelpers.h"
#include "Walls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace
{
using bptest::cube;
using bptest::uniformFlow;

/// One Strip4 element of size 0.5 centred at `at`, fixed orientation (along x).
bp::Parameters strip(bp::Boundary boundary, std::array<float, 3> at)
{
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.5f;
  p.emitterMin = p.emitterMax = at;
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = 100.0f;
  p.iterations = 4;
  p.boundary = boundary;
  return p;
}

bp::Engine started(const bp::Parameters& p, bp::BuiltinShape shape)
{
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(shape), p), "");
  engine.initialize(bp::serialRunner());
  return engine;
}

void run(bp::Engine& engine, const bp::VectorField& field, int steps, double h, double t0 = 0.0)
{
  for (int s = 0; s < steps; ++s)
    engine.step(field, t0 + s * h, h, bp::serialRunner());
}

bool inCube(const bp::Engine& engine)
{
  const bp::Domain box = cube();
  for (std::size_t i = 0; i < engine.positions().size(); i += 3)
    if (!box.contains(engine.positions().data() + i))
      return false;
  return true;
}
} // namespace

TEST(Walls, OnlySidesOfAxesWithExtentAreWalls)
{
  bp::Domain flat = cube();
  flat.lower[2] = flat.upper[2] = 0.0f;
  flat.degenerate[2] = true;
  const float onX[3] = { 1, 0.5f, 0 }, inside[3] = { 0.5f, 0.5f, 0 };
  EXPECT_TRUE(bp::onWall(cube(), onX));
  EXPECT_FALSE(bp::onWall(cube(), inside));
  EXPECT_FALSE(bp::onWall(flat, inside)); // z = 0 is the flat axis' one plane, no wall
  float beyond[3] = { 0.5f, -3, 7 };
  EXPECT_EQ(bp::clampToBox(flat, beyond), 1u << 2); // lower y only
  EXPECT_FLOAT_EQ(beyond[1], -1.0f);
  EXPECT_FLOAT_EQ(beyond[2], 7.0f);
  float notANumber[3] = { NAN, 0, 0 };
  EXPECT_EQ(bp::clampToBox(cube(), notANumber), 0u);
  EXPECT_TRUE(std::isnan(notANumber[0]));
}

TEST(Walls, StickPutsTheParticleWhereItsStepFirstMeetsASide)
{
  const float before[3] = { 0, 0, 0 };
  float p[3] = { 2, 0.5f, -0.5f };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Stick, 1, cube(), before, p), 2u); // upper x
  EXPECT_EQ(p[0], 1.0f); // on the wall exactly: held from now on
  EXPECT_FLOAT_EQ(p[1], 0.25f);
  EXPECT_FLOAT_EQ(p[2], -0.25f);
  EXPECT_TRUE(bp::onWall(cube(), p));
  // Two sides crossed: the nearer along the step wins.
  float q[3] = { 3, -1.5f, 0 };
  const float from[3] = { 0.5f, 0, 0 };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Stick, 1, cube(), from, q), 2u);
  EXPECT_EQ(q[0], 1.0f);
  EXPECT_FLOAT_EQ(q[1], -0.3f);
  // From outside the box (an element released across a side): clamped.
  const float outside[3] = { 1.5f, 0, 0 };
  float r[3] = { 1.75f, 0.5f, 0 };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Stick, 1, cube(), outside, r), 2u);
  EXPECT_EQ(r[0], 1.0f);
  EXPECT_EQ(r[1], 0.5f);
  // A step that stays inside is left alone.
  float s[3] = { 0.5f, 0.5f, 0.5f };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Stick, 1, cube(), before, s), 0u);
  EXPECT_EQ(s[0], 0.5f);
}

TEST(Walls, SlipProjectsAndBounceReflectsWithTheRestitution)
{
  const float before[3] = { 0.9f, 0, 0 };
  float slid[3] = { 1.5f, 0.3f, 0 };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Slip, 1, cube(), before, slid), 2u);
  EXPECT_EQ(slid[0], 1.0f);
  EXPECT_EQ(slid[1], 0.3f); // the tangential part of the step kept whole
  float bounced[3] = { 1.5f, 0.3f, 0 };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Bounce, 0.5f, cube(), before, bounced), 2u);
  EXPECT_FLOAT_EQ(bounced[0], 0.75f);
  EXPECT_EQ(bounced[1], 0.3f);
  float mirrored[3] = { -1.25f, 0, 0 };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Bounce, 1, cube(), before, mirrored), 1u);
  EXPECT_FLOAT_EQ(mirrored[0], -0.75f);
  // A reflection past the opposite side ends on it.
  float far[3] = { 4, 0, 0 };
  EXPECT_EQ(bp::wallAfterAdvection(bp::Boundary::Bounce, 1, cube(), before, far), 3u);
  EXPECT_EQ(far[0], -1.0f);
  // Restitution 0 is Slip.
  float dead[3] = { 1.5f, 0.3f, 0 };
  bp::wallAfterAdvection(bp::Boundary::Bounce, 0, cube(), before, dead);
  EXPECT_EQ(dead[0], 1.0f);
  // Not a wall: nothing changes.
  for (bp::Boundary b : { bp::Boundary::ReleaseAgain, bp::Boundary::Terminate })
  {
    float p[3] = { 1.5f, 0.3f, 0 };
    EXPECT_EQ(bp::wallAfterAdvection(b, 1, cube(), before, p), 0u);
    EXPECT_EQ(p[0], 1.5f);
  }
}

TEST(Walls, TheVelocityRuleActsOnTheOutwardNormalComponentOnly)
{
  const bp::WallHits floor = 1u << 4; // lower z
  float v[3] = { 1, 2, -3 };
  bp::wallVelocity(bp::Boundary::Stick, 0.5f, floor, v);
  EXPECT_EQ(v[0], 0.0f);
  EXPECT_EQ(v[1], 0.0f);
  EXPECT_EQ(v[2], 0.0f);
  float s[3] = { 1, 2, -3 };
  bp::wallVelocity(bp::Boundary::Slip, 0.5f, floor, s);
  EXPECT_EQ(s[0], 1.0f);
  EXPECT_EQ(s[1], 2.0f);
  EXPECT_EQ(s[2], 0.0f);
  float b[3] = { 1, 2, -3 };
  bp::wallVelocity(bp::Boundary::Bounce, 0.5f, floor, b);
  EXPECT_EQ(b[2], 1.5f);
  EXPECT_EQ(b[1], 2.0f);
  // Already leaving the wall: kept.
  float away[3] = { 0, 0, 2 };
  bp::wallVelocity(bp::Boundary::Bounce, 0.5f, floor, away);
  EXPECT_EQ(away[2], 2.0f);
  bp::wallVelocity(bp::Boundary::Slip, 0.5f, floor, away);
  EXPECT_EQ(away[2], 2.0f);
  // No side met: nothing changes, even for Stick.
  float free[3] = { 1, 2, 3 };
  bp::wallVelocity(bp::Boundary::Stick, 1, 0u, free);
  EXPECT_EQ(free[0], 1.0f);
}

TEST(Walls, AStripLiesDownOnASlipWallAndSlidesAlongIt)
{
  // Flow into the wall x = 1 and along it (+y); the strip (a quad in its
  // x-y plane, turned 45 degrees about y) starts at 45 degrees to the wall. Its leading particle
  // reaches the wall first and slides, the others follow until the whole strip lies on the wall; it
  // is never released again and keeps its length.
  const bp::VectorField field = uniformFlow({ 1.0f, 0.25f, 0 });
  bp::Parameters p = strip(bp::Boundary::Slip, { 0.5f, -0.5f, 0 });
  const float c = std::sqrt(0.5f);
  p.frame = { c, 0, c, 0, 1, 0, -c, 0, c };
  p.iterations = 8;
  bp::Engine engine = started(p, bp::BuiltinShape::Strip4);
  run(engine, field, 150, 0.01);
  EXPECT_TRUE(inCube(engine));
  EXPECT_EQ(engine.generations()[0], 0u);
  EXPECT_EQ(engine.resetFlags()[0], 0u);
  const float* q = engine.positions().data();
  float lowest = 1, meanY = 0;
  for (int i = 0; i < 4; ++i)
  {
    lowest = std::min(lowest, q[3 * i]);
    meanY += q[3 * i + 1] / 4;
  }
  EXPECT_GT(lowest, 0.99f); // lying on the wall
  EXPECT_LT(bptest::worstSpringStrain(engine), 0.05);
  for (int i = 0; i < 4; ++i)
    std::printf("particle %d at %.4f %.4f %.4f\n", i, q[3 * i], q[3 * i + 1], q[3 * i + 2]);
  // It slid along the wall at the flow's tangential speed (within its turn).
  EXPECT_NEAR(meanY, -0.5f + 0.25f * 1.5f, 0.05f);
}

TEST(Walls, StickHoldsTheParticlesThatReachTheWall)
{
  const bp::VectorField field = uniformFlow({ 1.0f, 0.25f, 0 });
  bp::Engine engine =
    started(strip(bp::Boundary::Stick, { 0.5f, -0.5f, 0 }), bp::BuiltinShape::Strip4);
  run(engine, field, 150, 0.01);
  EXPECT_TRUE(inCube(engine));
  EXPECT_EQ(engine.generations()[0], 0u);
  const std::vector<float> held = engine.positions();
  int onWall = 0;
  for (int i = 0; i < 4; ++i)
    onWall += bp::onWall(cube(), held.data() + 3 * i) ? 1 : 0;
  EXPECT_GE(onWall, 1);
  run(engine, field, 50, 0.01, 1.5);
  for (int i = 0; i < 4; ++i)
    if (bp::onWall(cube(), held.data() + 3 * i))
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(engine.positions()[3 * i + k], held[3 * i + k]) << i; // held exactly
  // The strip stopped: its particles no longer climb the wall as Slip's do.
  float meanY = 0;
  for (int i = 0; i < 4; ++i)
    meanY += engine.positions()[3 * i + 1] / 4;
  EXPECT_LT(meanY, -0.5f + 0.25f * 0.5f + 0.1f);
}

TEST(Walls, BounceKeepsElementsInAndTheDefaultsTraceAsBefore)
{
  const bp::VectorField field = uniformFlow({ 1.0f, 0.25f, 0 });
  bp::Parameters p = strip(bp::Boundary::Bounce, { 0.5f, -0.5f, 0 });
  p.restitution = 0.5f;
  bp::Engine engine = started(p, bp::BuiltinShape::Strip4);
  run(engine, field, 150, 0.01);
  EXPECT_TRUE(inCube(engine));
  EXPECT_EQ(engine.generations()[0], 0u);
  // Release Again with any restitution is the trace of before.
  bp::Parameters again = strip(bp::Boundary::ReleaseAgain, { 0.5f, -0.5f, 0 });
  bp::Engine a = started(again, bp::BuiltinShape::Strip4);
  again.restitution = 0.25f;
  bp::Engine b = started(again, bp::BuiltinShape::Strip4);
  run(a, field, 150, 0.01);
  run(b, field, 150, 0.01);
  EXPECT_EQ(a.positions(), b.positions());
  EXPECT_GT(a.generations()[0], 0u);
}

TEST(Walls, AnyParticleLeavesNeverResetsAWalledElement)
{
  const bp::VectorField field = uniformFlow({ 1.0f, 0, 0 });
  for (bp::Boundary b : { bp::Boundary::Stick, bp::Boundary::Slip, bp::Boundary::Bounce })
  {
    bp::Parameters p = strip(b, { 0.5f, 0, 0 });
    p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
    bp::Engine engine = started(p, bp::BuiltinShape::Strip4);
    run(engine, field, 100, 0.01);
    EXPECT_EQ(engine.generations()[0], 0u) << bp::enumName(b);
    EXPECT_TRUE(inCube(engine)) << bp::enumName(b);
  }
}

TEST(Walls, ACellOutsideTheFlowIsAWallOnItsFaces)
{
  // The last layer of cells (x from 0.5) is outside the flow: a particle
  // that would enter it stays on the face x = 0.5 (MaskWalls.h).
  bp::GridGeometry g = bptest::grid(5);
  auto v = std::make_shared<std::vector<float>>();
  for (std::size_t i = 0; i < g.pointCount(); ++i)
    v->insert(v->end(), { 1.0f, 0.0f, 0.0f });
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      (*v)[3 * (std::size_t(k) * 25 + std::size_t(j) * 5 + 4)] = NAN;
  const bp::DomainMask mask = bp::maskOutsidePoints(g, *v, nullptr);
  const bp::VectorField field(g, bp::FieldSlice{ 0.0, v, mask.outsideCells });
  for (bp::Boundary b : { bp::Boundary::Stick, bp::Boundary::Slip, bp::Boundary::Bounce })
  {
    bp::Engine engine = started(strip(b, { 0.0f, 0, 0 }), bp::BuiltinShape::Strip4);
    run(engine, field, 100, 0.01);
    EXPECT_EQ(engine.generations()[0], 0u) << bp::enumName(b);
    for (std::size_t i = 0; i < 4; ++i)
    {
      const float* q = engine.positions().data() + 3 * i;
      EXPECT_FALSE(field.outsideCellAt(q, 0.0f)) << bp::enumName(b) << " particle " << i;
      EXPECT_LT(q[0], 0.5f);
    }
  }
}

TEST(Walls, AHeavyParticleSticksWhereAndWhenItReachesTheFloor)
{
  // Still fluid, gravity along -z: released at rest at z = 0.5, it settles
  // 1.5 to the floor z = -1 in settlingTime, and stays there.
  const bp::VectorField still = uniformFlow({ 0, 0, 0 });
  bp::Parameters p = strip(bp::Boundary::Stick, { 0.25f, 0, 0.5f });
  p.elementSize = 0.01f;
  p.integrator = bp::Integrator::RK4;
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = 0.1f;
  p.densityRatio = 1000.0f;
  p.gravity = { 0, 0, -9.81f };
  bp::Engine engine = started(p, bp::BuiltinShape::Point);
  const double h = 0.002, arrival = bp::settlingTime(p, 1.5);
  int s = 0;
  for (; s < 5000 && engine.positions()[2] > -1.0f; ++s)
    engine.step(still, s * h, h, bp::serialRunner());
  EXPECT_NEAR(s * h, arrival, h);
  EXPECT_EQ(engine.positions()[2], -1.0f);
  EXPECT_FLOAT_EQ(engine.positions()[0], 0.25f);
  EXPECT_EQ(engine.slips()[2], 0.0f); // still fluid: the velocity, made 0
  run(engine, still, 100, h, s * h);
  EXPECT_EQ(engine.positions()[2], -1.0f);
  EXPECT_FLOAT_EQ(engine.positions()[0], 0.25f);
}

TEST(Walls, AHeavyParticleBouncesToTheSquareOfTheRestitution)
{
  // Nearly free fall (tau far above the flight): dropped from 1.5 above the
  // floor, it rises to e^2 of that after the bounce, within a step's travel.
  const bp::VectorField still = uniformFlow({ 0, 0, 0 });
  for (float e : { 1.0f, 0.5f })
  {
    bp::Parameters p = strip(bp::Boundary::Bounce, { 0, 0, 0.5f });
    p.elementSize = 0.01f;
    p.integrator = bp::Integrator::RK4;
    p.inertia = bp::Inertia::MaxeyRiley;
    p.responseTime = 1e4f;
    p.densityRatio = 1e6f;
    p.gravity = { 0, 0, -9.81f };
    p.restitution = e;
    bp::Engine engine = started(p, bp::BuiltinShape::Point);
    const double h = 0.001;
    int s = 0;
    bool bounced = false, rising = false;
    float apex = -1;
    for (; s < 3000; ++s)
    {
      const float z = engine.positions()[2];
      engine.step(still, s * h, h, bp::serialRunner());
      const float now = engine.positions()[2];
      bounced = bounced || engine.slips()[2] > 0.0f;
      if (bounced)
      {
        if (rising && now < z)
          break; // past the apex
        rising = rising || now > z;
        apex = std::max(apex, now);
      }
    }
    const double speed = std::sqrt(2 * 9.81 * 1.5);
    EXPECT_TRUE(bounced);
    EXPECT_NEAR(apex + 1.0, e * e * 1.5, 2 * speed * h) << "restitution " << e;
  }
}

TEST(Walls, BadCombinationsAreRefusedByName)
{
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip4);
  bp::Parameters p = strip(bp::Boundary::Bounce, { 0, 0, 0 });
  for (float bad : { -0.1f, 1.5f, NAN })
  {
    p.restitution = bad;
    EXPECT_NE(
      bp::Engine::validate(shape, p).find("Restitution must be between 0 and 1"), std::string::npos)
      << bad;
  }
  p.restitution = 0.5f;
  EXPECT_EQ(bp::Engine::validate(shape, p), "");
  for (bp::Boundary b : { bp::Boundary::Stick, bp::Boundary::Slip, bp::Boundary::Bounce })
  {
    bp::Parameters linked = strip(b, { 0, 0, 0 });
    linked.numberOfElements = 4;
    linked.linking = bp::Linking::Chain;
    const std::string said = bp::Engine::validate(shape, linked);
    EXPECT_NE(said.find(std::string("Boundary = ") + bp::enumName(b)), std::string::npos) << said;
    EXPECT_NE(said.find("Linking"), std::string::npos) << said;
    bp::Parameters anchored = strip(b, { 0, 0, 0 });
    anchored.anchor = bp::Anchor::Centre;
    EXPECT_NE(bp::Engine::validate(shape, anchored).find("Anchor = Centre"), std::string::npos);
  }
  bp::Parameters unknown = strip(bp::Boundary::Bounce, { 0, 0, 0 });
  unknown.boundary = bp::Boundary(7);
  EXPECT_NE(bp::Engine::validate(shape, unknown).find("Boundary must be"), std::string::npos);
}

TEST(Walls, AResumedStickTraceHoldsWhatItHeld)
{
  // Held is a property of the position (on a side, exactly): a state saved
  // with particles held resumes them held, to the bits of a trace that never
  // stopped, with no new state.
  const bp::VectorField field = uniformFlow({ 1.0f, 0.25f, 0 });
  bp::Parameters p = strip(bp::Boundary::Stick, { 0.5f, -0.5f, 0 });
  p.numberOfElements = 8;
  p.emitterMin = { 0.2f, -0.6f, -0.5f };
  p.emitterMax = { 0.6f, 0.6f, 0.5f };
  p.orientation = bp::Orientation::Random;
  p.lifetimeMin = 0.5f;
  p.lifetimeMax = 1.5f;
  bp::Engine a = started(p, bp::BuiltinShape::Strip4);
  run(a, field, 60, 0.01);
  int held = 0;
  for (std::size_t q = 0; q < a.positions().size(); q += 3)
    held += bp::onWall(cube(), a.positions().data() + q) ? 1 : 0;
  EXPECT_GT(held, 4);
  bp::Engine b = started(p, bp::BuiltinShape::Strip4);
  ASSERT_EQ(b.loadState(a.saveState()), "");
  run(a, field, 90, 0.01, 0.6);
  run(b, field, 90, 0.01, 0.6);
  EXPECT_EQ(a.positions(), b.positions());
  EXPECT_EQ(a.generations(), b.generations());
  EXPECT_GT(a.generations()[0] + a.generations()[1], 0u); // released again at their lifetime's end
}
