// SPDX-License-Identifier: BSD-3-Clause
// The walls of the cells outside the flow (MaskWalls.h, engine specification
// 2.8): the face a step meets, the rules on it, and the CPU engine's
// elements sliding along, bouncing off and held by a block and a staircase
// of cells outside the flow, with their events (2.9).
#include "DomainMask.h"
#include "MaskWalls.h"
#include "Surfaces.h"
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace
{
/// grid(9) over [-1, 1]^3 (spacing 0.25) with flow `u`, and NaN (outside the
/// flow) at the points `outside` takes: a cell with one is outside.
bp::VectorField maskedFlow(std::array<float, 3> u,
  const std::function<bool(double, double)>& outside, bool periodicX = false)
{
  bp::GridGeometry g = bptest::grid(9);
  g.periodic = { periodicX, false, false };
  auto v = std::make_shared<std::vector<float>>();
  for (int k = 0; k < 9; ++k)
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i)
      {
        const bool out = outside(g.coordinate(0, i), g.coordinate(1, j));
        v->insert(v->end(), { out ? NAN : u[0], u[1], u[2] });
      }
  const bp::DomainMask mask = bp::maskOutsidePoints(g, *v, nullptr);
  return bp::VectorField(g, bp::FieldSlice{ 0.0, v, mask.outsideCells });
}

/// Cells from x = 0.5 on are outside the flow: a wall at x = 0.5.
bp::VectorField block(std::array<float, 3> u)
{
  return maskedFlow(u, [](double x, double) { return x > 0.6; });
}

/// A staircase: the cells with a corner where x + y > 0.6 are outside.
bp::VectorField staircase(std::array<float, 3> u)
{
  return maskedFlow(u, [](double x, double y) { return x + y > 0.6; });
}

bp::Parameters strip(bp::Boundary boundary, std::array<float, 3> at, std::size_t count = 1)
{
  bp::Parameters p;
  p.numberOfElements = count;
  p.elementSize = 0.5f;
  p.emitterMin = p.emitterMax = at;
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = 100.0f;
  p.iterations = 8;
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

/// Steps the engine; returns how many particles ended a step in a cell
/// outside the flow.
int run(bp::Engine& engine, const bp::VectorField& field, int steps, double h, double t0 = 0.0)
{
  int outside = 0;
  for (int s = 0; s < steps; ++s)
  {
    engine.step(field, t0 + s * h, h, bp::serialRunner());
    for (std::size_t i = 0; i < engine.positions().size(); i += 3)
      outside += field.outsideCellAt(engine.positions().data() + i, 0.0f) ? 1 : 0;
  }
  return outside;
}

float offsetOf(const bp::VectorField& field)
{
  return bp::surfaceWallOffset(field.domain());
}
} // namespace

TEST(MaskWalls, TheFirstFaceIntoACellOutsideAndTheRulesOnIt)
{
  const bp::VectorField field = block({ 1, 0, 0 });
  const float d = offsetOf(field);
  const float before[3] = { 0.4f, 0.0f, 0.0f }, after[3] = { 0.6f, 0.1f, 0.0f };
  bp::MaskFace face;
  ASSERT_TRUE(bp::firstOutsideFace(field, 0.0f, before, after, face));
  EXPECT_EQ(face.axis, 0);
  EXPECT_EQ(face.plane, 0.5f);
  EXPECT_EQ(face.toward, -1.0f);
  EXPECT_NEAR(face.point[1], 0.05f, 1e-6f);
  // From a cell inside that never reaches one outside: none.
  const float short_[3] = { 0.45f, 0.3f, 0.0f };
  EXPECT_FALSE(bp::firstOutsideFace(field, 0.0f, before, short_, face));

  float p[3] = { 0.6f, 0.1f, 0.0f };
  EXPECT_EQ(bp::wallOnOutsideCells(bp::Boundary::Slip, 1, d, field, 0, before, p, face), 2u);
  EXPECT_EQ(p[0], 0.5f - d); // the normal component removed
  EXPECT_EQ(p[1], 0.1f);     // the tangential kept
  EXPECT_TRUE(bp::onOutsideFace(field, 0, d, p));

  std::copy_n(after, 3, p);
  EXPECT_EQ(bp::wallOnOutsideCells(bp::Boundary::Bounce, 0.5f, d, field, 0, before, p, face), 2u);
  EXPECT_NEAR(p[0], 0.5f - 0.5f * 0.1f, 1e-6f); // reflected with e
  EXPECT_EQ(p[1], 0.1f);

  std::copy_n(after, 3, p);
  EXPECT_EQ(bp::wallOnOutsideCells(bp::Boundary::Stick, 1, d, field, 0, before, p, face), 2u);
  EXPECT_EQ(p[0], 0.5f - d); // where the step met the face
  EXPECT_NEAR(p[1], 0.05f, 1e-6f);
  EXPECT_TRUE(bp::onOutsideFace(field, 0, d, p));
  EXPECT_FALSE(bp::onOutsideFace(field, 0, d, before));

  // A heavy particle's velocity: the sides' rule with the face's normal.
  float v[3] = { 2, 1, 0 };
  bp::wallVelocity(bp::Boundary::Bounce, 0.5f, 2u, v);
  EXPECT_EQ(v[0], -1.0f);
  EXPECT_EQ(v[1], 1.0f);

  // A field without cells outside the flow: nothing changes.
  const bp::VectorField open = bptest::uniformFlow({ 1, 0, 0 });
  std::copy_n(after, 3, p);
  EXPECT_EQ(bp::wallOnOutsideCells(bp::Boundary::Slip, 1, d, open, 0, before, p, face), 0u);
  EXPECT_EQ(p[0], 0.6f);
  EXPECT_FALSE(bp::onOutsideFace(open, 0, d, p));

  // Beyond a periodic axis' bounds (cells wrap, faces do not): no face,
  // back to before; within them the faces as without the period.
  const bp::VectorField periodic = maskedFlow(
    { 0, 1, 0 }, [](double, double y) { return y > 0.6; }, true);
  const float across[3] = { 1.05f, 0.4f, 0.0f }, into[3] = { 1.06f, 0.6f, 0.0f };
  std::copy_n(into, 3, p);
  EXPECT_EQ(bp::wallOnOutsideCells(bp::Boundary::Slip, 1, d, periodic, 0, across, p, face),
    bp::WallMaskedCell);
  EXPECT_EQ(p[1], 0.4f);
  const float within[3] = { 0.95f, 0.4f, 0.0f };
  std::copy_n(within, 3, p);
  p[1] = 0.6f;
  EXPECT_EQ(bp::wallOnOutsideCells(bp::Boundary::Slip, 1, d, periodic, 0, within, p, face), 8u);
  EXPECT_EQ(p[1], 0.5f - d);
  EXPECT_EQ(p[0], 0.95f);
}

TEST(MaskWalls, AStripLiesDownOnTheFaceAndSlidesAlongIt)
{
  // As Walls.AStripLiesDownOnASlipWallAndSlidesAlongIt, with the wall at
  // x = 0.5 made of cells outside the flow.
  const bp::VectorField field = block({ 1.0f, 0.25f, 0 });
  bp::Parameters p = strip(bp::Boundary::Slip, { 0.0f, -0.5f, 0 });
  const float c = std::sqrt(0.5f);
  p.frame = { c, 0, c, 0, 1, 0, -c, 0, c };
  bp::Engine engine = started(p, bp::BuiltinShape::Strip4);
  EXPECT_EQ(run(engine, field, 150, 0.01), 0);
  EXPECT_EQ(engine.generations()[0], 0u);
  const float* q = engine.positions().data();
  float lowest = 1, highest = -1, meanY = 0;
  for (int i = 0; i < 4; ++i)
  {
    lowest = std::min(lowest, q[3 * i]);
    highest = std::max(highest, q[3 * i]);
    meanY += q[3 * i + 1] / 4;
    std::printf("particle %d at %.5f %.5f %.5f\n", i, q[3 * i], q[3 * i + 1], q[3 * i + 2]);
  }
  EXPECT_LT(highest, 0.5f);
  EXPECT_GT(lowest, 0.49f); // lying on the face
  EXPECT_LT(bptest::worstSpringStrain(engine), 0.05);
  // It slid along the face at the flow's tangential speed (within its turn).
  EXPECT_NEAR(meanY, -0.5f + 0.25f * 1.5f, 0.05f);
}

TEST(MaskWalls, BounceReflectsWithTheRestitutionAndStickHolds)
{
  const bp::VectorField field = block({ 1.0f, 0.25f, 0 });
  bp::Parameters p = strip(bp::Boundary::Bounce, { 0.0f, -0.5f, 0 });
  p.restitution = 0.5f;
  bp::Engine bounce = started(p, bp::BuiltinShape::Strip4);
  EXPECT_EQ(run(bounce, field, 150, 0.01), 0);
  EXPECT_EQ(bounce.generations()[0], 0u);

  // A point, one step of 0.2 into the face from 0.45: back to 0.5 - 0.5 * 0.15.
  bp::Parameters one = strip(bp::Boundary::Bounce, { 0.45f, 0.0f, 0 });
  one.restitution = 0.5f;
  bp::Engine point = started(one, bp::BuiltinShape::Point);
  const bp::VectorField fast = block({ 1.0f, 0, 0 });
  EXPECT_EQ(run(point, fast, 1, 0.2), 0);
  EXPECT_NEAR(point.positions()[0], 0.5f - 0.5f * 0.15f, 1e-5f);

  const bp::VectorField along = block({ 1.0f, 0.25f, 0 });
  bp::Engine stick =
    started(strip(bp::Boundary::Stick, { 0.0f, -0.5f, 0 }), bp::BuiltinShape::Strip4);
  EXPECT_EQ(run(stick, along, 150, 0.01), 0);
  const float d = offsetOf(along);
  const std::vector<float> held = stick.positions();
  int onFace = 0;
  for (int i = 0; i < 4; ++i)
    onFace += bp::onOutsideFace(along, 0, d, held.data() + 3 * i) ? 1 : 0;
  EXPECT_GE(onFace, 1);
  EXPECT_EQ(run(stick, along, 50, 0.01, 1.5), 0);
  for (int i = 0; i < 4; ++i)
    if (bp::onOutsideFace(along, 0, d, held.data() + 3 * i))
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(stick.positions()[3 * i + k], held[3 * i + k]) << i; // held exactly
}

TEST(MaskWalls, AStaircaseKeepsEveryParticleInside)
{
  // A diagonal boundary of cells outside the flow, flow into it and along
  // it: every particle of every element stays in a cell inside the flow,
  // under each rule, and no element is released again.
  const bp::VectorField field = staircase({ 1.0f, 0.6f, 0.0f });
  for (bp::Boundary b : { bp::Boundary::Stick, bp::Boundary::Slip, bp::Boundary::Bounce })
    for (bp::BuiltinShape shape : { bp::BuiltinShape::Strip8, bp::BuiltinShape::Cross })
    {
      bp::Parameters p = strip(b, { -0.6f, -0.6f, 0 }, 20);
      p.emitterMin = { -0.9f, -0.9f, -0.5f };
      p.emitterMax = { -0.2f, -0.2f, 0.5f };
      p.orientation = bp::Orientation::Random;
      p.elementSize = 0.3f;
      p.restitution = 0.6f;
      bp::Engine engine = started(p, shape);
      EXPECT_EQ(run(engine, field, 200, 0.01), 0) << bp::enumName(b);
      int near = 0;
      for (std::size_t i = 0; i < engine.positions().size(); i += 3)
        near += engine.positions()[i] + engine.positions()[i + 1] > 0.0f ? 1 : 0;
      EXPECT_GT(near, 10) << bp::enumName(b) << ": the staircase is reached";
      for (std::uint32_t g : engine.generations())
        EXPECT_EQ(g, 0u) << bp::enumName(b);
    }
}

TEST(MaskWalls, TheFaceGivesOneEventWithItsOutwardNormal)
{
  // A point carried onto the face and along it: one Slid event, no side,
  // the face's outward normal (+x), where it met the face.
  const bp::VectorField field = block({ 1.0f, 0.25f, 0 });
  // (From x = 0.003, so that no step ends within 2 offsets of the face.)
  bp::Parameters p = strip(bp::Boundary::Slip, { 0.003f, -0.5f, 0 });
  bp::Engine point = started(p, bp::BuiltinShape::Point);
  EXPECT_EQ(run(point, field, 100, 0.01), 0);
  ASSERT_EQ(point.interactions().size(), 1u);
  const bp::InteractionEvent x = point.interactions().events()[0];
  EXPECT_EQ(x.kind, bp::Interaction::Slid);
  EXPECT_EQ(x.side, bp::NoSide);
  EXPECT_EQ(x.normal, (std::array<float, 3>{ 1, 0, 0 }));
  EXPECT_EQ(x.position[0], 0.5f);
  EXPECT_NEAR(x.time, 0.5, 0.011);
  EXPECT_GT(point.positions()[1], x.position[1] + 0.1f); // slid on along the face
}

TEST(MaskWalls, NoStepEndsInACellOutsideTheFlow)
{
  // Random steps on the staircase, half of them from within 10^-4 of its
  // inward corner at (0.25, 0.25) (where a rounding of the contact could
  // fall into a neighbour): under each rule every one ends inside the flow.
  const bp::VectorField field = staircase({ 1.0f, 0.6f, 0.0f });
  const float d = offsetOf(field);
  std::srand(1);
  int walled = 0, bad = 0;
  for (int k = 0; k < 40000; ++k)
  {
    float b[3], p[3];
    for (int a = 0; a < 3; ++a)
    {
      const float r = float(std::rand()) / float(RAND_MAX);
      const float s = float(std::rand()) / float(RAND_MAX) - 0.5f;
      b[a] = k % 2 ? -1 + 2 * r : (a < 2 ? 0.25f : 0.1f) - 1e-4f * r;
      p[a] = std::min(std::max(b[a] + (k % 2 ? 0.3f : 0.03f) * s, -1.0f), 1.0f);
    }
    if (field.outsideCellAt(b, 0))
      continue;
    for (bp::Boundary r : { bp::Boundary::Slip, bp::Boundary::Bounce, bp::Boundary::Stick })
    {
      float q[3] = { p[0], p[1], p[2] };
      bp::MaskFace f;
      walled += bp::wallOnOutsideCells(r, 0.6f, d, field, 0, b, q, f) ? 1 : 0;
      bad += field.outsideCellAt(q, 0) ? 1 : 0;
    }
  }
  EXPECT_GT(walled, 10000);
  EXPECT_EQ(bad, 0);
}
