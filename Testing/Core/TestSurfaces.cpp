// SPDX-License-Identifier: BSD-3-Clause
// Gates and outlets of the Surfaces input in the CPU engine (Surfaces.h,
// engine specification 2.10): a gate on a half-plane in solid-body rotation
// records each element once per turn at the analytic time; an outlet ends
// an element where its centre crosses it and records that once; the
// refusals; and without surfaces nothing changes. The Outlet triangles the
// GPU engine takes (SurfaceSet::outletCorners, gpuOutletError).
#include "Engine.h"
#include "ParticleLayout.h"
#include "Surfaces.h"
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// The rectangle [x0, x1] x [y0, y1] in the plane z = `z` (normal +z), or
/// with `xz` the rectangle [x0, x1] x [z0 = y0, z1 = y1] in the plane y = `z`
/// (normal -y, so +y by `flip`), as two triangles.
std::vector<float> rectangle(float x0, float x1, float y0, float y1, float z, bool xz = false)
{
  std::vector<float> c = { x0, y0, z, x1, y0, z, x1, y1, z, x0, y0, z, x1, y1, z, x0, y1, z };
  if (xz)
  {
    for (std::size_t k = 0; k < c.size(); k += 3)
    {
      std::swap(c[k + 1], c[k + 2]); // (x, a, b) -> (x, b, a): the plane y = z
    }
  }
  return c;
}

/// The plane x = `x` over y, z in [-1, 1] as two triangles.
std::vector<float> planeX(float x)
{
  std::vector<float> c = rectangle(-1, 1, -1, 1, x, false);
  for (std::size_t k = 0; k < c.size(); k += 3)
    std::swap(c[k], c[k + 2]); // (x, y, z) -> (z, y, x): the plane z = x made x = x
  return c;
}

std::shared_ptr<const bp::SurfaceSet> surfaceOf(
  const std::vector<float>& corners, bp::SurfaceInteraction kind)
{
  bp::SurfaceTriangles t;
  t.corners = corners;
  const std::size_t n = corners.size() / 9;
  t.surfaces.assign(n, 0);
  t.interaction.assign(n, kind);
  for (std::size_t k = 0; k < n; ++k)
    t.cells.push_back(std::int32_t(100 + k));
  return std::make_shared<const bp::SurfaceSet>(t);
}

bp::Parameters squares(std::vector<float> seeds, float lifetime)
{
  bp::Parameters p;
  p.numberOfElements = seeds.size() / 3;
  p.seedPoints = std::move(seeds);
  p.elementSize = 0.2f;
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = lifetime;
  p.iterations = 8;
  p.integrator = bp::Integrator::RK4;
  return p;
}

void run(bp::Engine& engine, const bp::VectorField& field, int steps, double h)
{
  for (int s = 0; s < steps; ++s)
    engine.step(field, s * h, h, bp::serialRunner());
}
} // namespace

TEST(Surfaces, AGateOnAHalfPlaneRecordsEachElementOncePerTurnAtTheAnalyticTime)
{
  // Solid-body rotation about z (unit angular velocity, period 2 pi) and a
  // gate on the half-plane y = 0, x > 0: an element released at angle a
  // crosses it at 2 pi k - a, going +y.
  const bp::VectorField field =
    bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, bptest::grid(9));
  const int count = 8;
  std::vector<float> seeds;
  std::vector<double> angle;
  for (int j = 0; j < count; ++j)
  {
    angle.push_back(2 * Pi * (j + 0.5) / count);
    seeds.insert(seeds.end(),
      { float(0.5 * std::cos(angle.back())), float(0.5 * std::sin(angle.back())), 0.0f });
  }
  bp::Parameters p = squares(seeds, 100.0f);
  p.surfaces =
    surfaceOf(rectangle(0.0f, 1.0f, -1.0f, 1.0f, 0.0f, true), bp::SurfaceInteraction::Gate);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
  engine.initialize(bp::serialRunner());
  const double h = 0.01;
  run(engine, field, int(std::round(4 * Pi / h)), h); // two turns
  std::map<std::uint32_t, std::vector<bp::InteractionEvent>> passes;
  for (const bp::InteractionEvent& x : engine.interactions().events())
    passes[x.element].push_back(x);
  ASSERT_EQ(passes.size(), std::size_t(count));
  double worst = 0.0;
  for (const auto& [element, events] : passes)
  {
    ASSERT_EQ(events.size(), 2u) << "element " << element;
    for (std::size_t k = 0; k < 2; ++k)
    {
      const bp::InteractionEvent& x = events[k];
      EXPECT_EQ(x.kind, bp::Interaction::Passed);
      EXPECT_EQ(x.particle, -1);
      EXPECT_EQ(x.side, bp::FirstSurfaceId);
      EXPECT_TRUE(x.cell == 100 || x.cell == 101);
      const double expected = 2 * Pi * double(k + 1) - angle[element];
      worst = std::max(worst, std::abs(x.time - expected));
      EXPECT_NEAR(x.position[1], 0.0, 1e-6);
      EXPECT_NEAR(x.position[0], 0.5, 2e-3);
      // The normal is the surface's (-y, by its corners' order), and the
      // element went through it +y, against it.
      EXPECT_NEAR(x.normal[1], -1.0f, 1e-6f);
      EXPECT_NEAR(x.velocity[1], 0.5f, 1e-3f);
    }
  }
  // Within a step, and much closer: the time is interpolated along it.
  EXPECT_LT(worst, 0.1 * h);
  std::printf("worst gate time error %.3g (step %.3g)\n", worst, h);
}

TEST(Surfaces, AnOutletEndsAnElementWhereItsCentreCrossesAndRecordsItOnce)
{
  // A uniform flow along x; an outlet across the box at x = 0; squares
  // released at x = -0.5 reach it at t = 0.5, and again in their next
  // generation (lifetime 2) at t = 2.5.
  const bp::VectorField field = bptest::uniformFlow({ 1, 0, 0 });
  bp::Parameters p = squares({ -0.5f, 0.0f, 0.0f, -0.5f, 0.4f, -0.3f }, 2.0f);
  bp::SurfaceTriangles t;
  t.corners = planeX(0.0f);
  t.surfaces = { 2, 2 };
  t.interaction.assign(2, bp::SurfaceInteraction::Outlet);
  t.cells = { 7, 7 };
  p.surfaces = std::make_shared<const bp::SurfaceSet>(t);
  EXPECT_TRUE(p.surfaces->hasOutlets());
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
  engine.initialize(bp::serialRunner());
  const double h = 0.02;
  run(engine, field, 50, h); // to t = 1
  const std::vector<bp::InteractionEvent> first = engine.interactions().events();
  ASSERT_EQ(first.size(), 2u);
  for (const bp::InteractionEvent& x : first)
  {
    EXPECT_EQ(x.kind, bp::Interaction::Terminated);
    EXPECT_EQ(x.side, bp::FirstSurfaceId + 2);
    EXPECT_EQ(x.cell, 7);
    EXPECT_NEAR(x.time, 0.5, 1e-5);
    EXPECT_NEAR(x.position[0], 0.0f, 1e-6f);
    EXPECT_NEAR(x.velocity[0], 1.0f, 1e-4f);
  }
  for (std::uint8_t flag : engine.resetFlags())
    EXPECT_TRUE(flag & bp::Terminated) << "hidden until its lifetime ends";
  // Past the box's side at x = 1 a terminated element records nothing
  // more; its next generation crosses again.
  run(engine, field, 150, h); // to t = 3 (the steps' times restart: a steady field)
  std::size_t terminated = 0;
  for (const bp::InteractionEvent& x : engine.interactions().events())
    terminated += x.kind == bp::Interaction::Terminated && x.side == bp::FirstSurfaceId + 2;
  EXPECT_EQ(terminated, 4u);
  EXPECT_EQ(engine.interactions().size(), 4u);
}

TEST(Surfaces, AGateChangesNothingInTheTrace)
{
  // Positions with a gate are those without, bit for bit.
  const bp::VectorField field =
    bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, bptest::grid(9));
  bp::Parameters p = squares({ 0.5f, 0.0f, 0.0f, 0.0f, 0.5f, 0.2f }, 10.0f);
  bp::Engine plain, gated;
  ASSERT_EQ(plain.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
  p.surfaces =
    surfaceOf(rectangle(0.0f, 1.0f, -1.0f, 1.0f, 0.0f, true), bp::SurfaceInteraction::Gate);
  ASSERT_EQ(gated.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
  plain.initialize(bp::serialRunner());
  gated.initialize(bp::serialRunner());
  run(plain, field, 700, 0.01);
  run(gated, field, 700, 0.01);
  EXPECT_EQ(plain.positions(), gated.positions());
  EXPECT_EQ(plain.generations(), gated.generations());
  EXPECT_EQ(plain.interactions().size(), 0u);
  EXPECT_GT(gated.interactions().size(), 0u);
}

TEST(Surfaces, AreRefusedWithLinkingAndAnchors)
{
  bp::Parameters p = squares({ 0, 0, 0 }, 1.0f);
  p.surfaces = surfaceOf(rectangle(0, 1, 0, 1, 0), bp::SurfaceInteraction::Gate);
  const bp::ElementTemplate square = bp::builtinTemplate(bp::BuiltinShape::Square);
  EXPECT_EQ(bp::Engine::validate(square, p), "");
  bp::Parameters linked = p;
  linked.linking = bp::Linking::Chain;
  linked.seedPoints.clear();
  linked.numberOfElements = 4;
  EXPECT_NE(bp::Engine::validate(square, linked).find("Surfaces"), std::string::npos);
  bp::Parameters anchored = p;
  anchored.anchor = bp::Anchor::Centre;
  EXPECT_NE(bp::Engine::validate(square, anchored).find("Anchor = Centre"), std::string::npos);
}

namespace
{
/// The plane y = `y` over x, z in [-1, 1] as a Wall (two triangles, cell 3).
std::shared_ptr<const bp::SurfaceSet> floorAt(float y)
{
  bp::SurfaceTriangles t;
  t.corners = rectangle(-1, 1, -1, 1, y, true);
  t.surfaces = { 1, 1 };
  t.interaction.assign(2, bp::SurfaceInteraction::Wall);
  t.cells = { 3, 3 };
  return std::make_shared<const bp::SurfaceSet>(t);
}

/// As Walls' strip at the box's side: a Strip4 (size 0.5) at 45 degrees to
/// the Wall x = 0.6 (block 1, cell 3), in a flow into it and along it (+y).
bp::Parameters stripTowardWall(bp::Boundary boundary)
{
  bp::Parameters p = squares({ 0.1f, -0.5f, 0.0f }, 100.0f);
  p.elementSize = 0.5f;
  p.integrator = bp::Integrator::Euler;
  const float c = std::sqrt(0.5f);
  p.frame = { c, 0, c, 0, 1, 0, -c, 0, c };
  p.boundary = boundary;
  bp::SurfaceTriangles wall;
  wall.corners = planeX(0.6f);
  wall.surfaces = { 1, 1 };
  wall.interaction.assign(2, bp::SurfaceInteraction::Wall);
  wall.cells = { 3, 3 };
  p.surfaces = std::make_shared<const bp::SurfaceSet>(wall);
  return p;
}
} // namespace

TEST(Surfaces, AStripCarriedOntoASlipWallLiesAlongItAndSlides)
{
  // As Walls.AStripLiesDownOnASlipWallAndSlidesAlongIt at the box's side,
  // on the plane x = 0.6 of the Surfaces: flow into the wall and along it
  // (+y), the strip at 45 degrees to it. It lies down on the wall's side,
  // keeps its length and slides at the flow's tangential speed.
  const bp::VectorField field = bptest::uniformFlow({ 1.0f, 0.25f, 0.0f });
  const bp::Parameters p = stripTowardWall(bp::Boundary::Slip);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.initialize(bp::serialRunner());
  run(engine, field, 150, 0.01);
  EXPECT_EQ(engine.generations()[0], 0u);
  EXPECT_EQ(engine.resetFlags()[0], 0u);
  const float* q = engine.positions().data();
  float lowest = 1, highest = -1, meanY = 0;
  for (int i = 0; i < 4; ++i)
  {
    lowest = std::min(lowest, q[3 * i]);
    highest = std::max(highest, q[3 * i]);
    meanY += q[3 * i + 1] / 4;
    std::printf("particle %d at %.5f %.5f %.5f\n", i, q[3 * i], q[3 * i + 1], q[3 * i + 2]);
  }
  EXPECT_LE(highest, 0.6f) << "every particle on the wall's side";
  EXPECT_GT(lowest, 0.59f) << "lying on the wall";
  EXPECT_LT(bptest::worstSpringStrain(engine), 0.05);
  EXPECT_NEAR(meanY, -0.5f + 0.25f * 1.5f, 0.05f) << "it slid along the wall";
  // One Slid event per particle, on the wall's surface and cell, when it
  // first reached it: not again while it slides.
  std::map<int, int> perParticle;
  for (const bp::InteractionEvent& x : engine.interactions().events())
  {
    EXPECT_EQ(x.kind, bp::Interaction::Slid);
    EXPECT_EQ(x.side, bp::FirstSurfaceId + 1);
    EXPECT_EQ(x.cell, 3);
    EXPECT_NEAR(x.position[0], 0.6f, 1e-6f);
    ++perParticle[x.particle];
  }
  EXPECT_EQ(perParticle.size(), 4u);
  for (const auto& [particle, count] : perParticle)
    EXPECT_EQ(count, 1) << "particle " << particle;
}

TEST(Surfaces, APointBouncesOffAWallWithTheRestitution)
{
  // Down at speed 1 from y = 0.5 onto y = 0, steps of 0.3: the second step
  // goes 0.1 beyond and comes back e = 0.5 times that.
  const bp::VectorField field = bptest::uniformFlow({ 0.0f, -1.0f, 0.0f });
  bp::Parameters p = squares({ 0.0f, 0.5f, 0.0f }, 100.0f);
  p.integrator = bp::Integrator::Euler;
  p.boundary = bp::Boundary::Bounce;
  p.restitution = 0.5f;
  p.surfaces = floorAt(0.0f);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Point), p), "");
  engine.initialize(bp::serialRunner());
  run(engine, field, 2, 0.3);
  const float offset = bp::surfaceWallOffset(field.domain());
  EXPECT_NEAR(engine.positions()[1], 0.05f + offset, 1e-6f);
  ASSERT_EQ(engine.interactions().size(), 1u);
  const bp::InteractionEvent x = engine.interactions().events()[0];
  EXPECT_EQ(x.kind, bp::Interaction::Bounced);
  EXPECT_NEAR(x.position[1], 0.0f, 1e-6f);
  EXPECT_DOUBLE_EQ(x.time, 0.6) << "a particle's wall event at the step's end, as at the sides";
}

TEST(Surfaces, AWallReleasesAgainOrEndsAnElementWhoseCentreCrossesIt)
{
  const bp::VectorField field = bptest::uniformFlow({ 0.0f, -1.0f, 0.0f });
  for (bp::Boundary boundary : { bp::Boundary::ReleaseAgain, bp::Boundary::Terminate })
  {
    bp::Parameters p = squares({ 0.0f, 0.5f, 0.0f }, 100.0f);
    p.boundary = boundary;
    p.surfaces = floorAt(0.0f);
    bp::Engine engine;
    ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
    engine.initialize(bp::serialRunner());
    run(engine, field, 30, 0.02); // the centre crosses at t = 0.5
    const std::vector<bp::InteractionEvent> events = engine.interactions().events();
    ASSERT_GE(events.size(), 1u);
    const bool released = boundary == bp::Boundary::ReleaseAgain;
    EXPECT_EQ(events[0].kind, released ? bp::Interaction::Released : bp::Interaction::Terminated);
    EXPECT_EQ(events[0].side, bp::FirstSurfaceId + 1);
    EXPECT_NEAR(events[0].time, 0.5, 1e-5);
    if (released)
    {
      EXPECT_GE(engine.generations()[0], 1u) << "placed again";
    }
    else
    {
      EXPECT_TRUE(engine.resetFlags()[0] & bp::Terminated);
    }
  }
}

TEST(Surfaces, StickHoldsTheParticlesThatReachAWall)
{
  // As Walls.StickHoldsTheParticlesThatReachTheWall at the box's side, on
  // the plane x = 0.6: the particles that reach it are held exactly where
  // they met it, one Stuck event each, and the strip stops climbing.
  const bp::VectorField field = bptest::uniformFlow({ 1.0f, 0.25f, 0.0f });
  const bp::Parameters p = stripTowardWall(bp::Boundary::Stick);
  EXPECT_EQ(bp::Engine::validate(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.initialize(bp::serialRunner());
  run(engine, field, 150, 0.01);
  const std::vector<float> held = engine.positions();
  const float offset = bp::surfaceWallOffset(field.domain());
  std::vector<bool> onWall(4);
  int count = 0;
  for (int i = 0; i < 4; ++i)
  {
    onWall[std::size_t(i)] = p.surfaces->onWall(held.data() + 3 * i, 2 * offset);
    count += onWall[std::size_t(i)] ? 1 : 0;
    EXPECT_LE(held[3 * i], 0.6f) << "on the wall's side";
  }
  EXPECT_GE(count, 1);
  for (int s = 150; s < 200; ++s)
    engine.step(field, s * 0.01, 0.01, bp::serialRunner());
  float meanY = 0;
  for (int i = 0; i < 4; ++i)
  {
    if (onWall[std::size_t(i)])
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(engine.positions()[3 * i + k], held[3 * i + k]) << i; // held exactly
    meanY += engine.positions()[3 * i + 1] / 4;
  }
  // Slip's strip climbs to about -0.125 by t = 1.5; this one stopped below.
  EXPECT_LT(meanY, -0.5f + 0.25f * 0.5f + 0.1f);
  std::map<int, int> stuck;
  for (const bp::InteractionEvent& x : engine.interactions().events())
  {
    EXPECT_EQ(x.kind, bp::Interaction::Stuck);
    ++stuck[x.particle];
  }
  EXPECT_EQ(int(stuck.size()), count);
  for (const auto& [particle, events] : stuck)
    EXPECT_EQ(events, 1) << "particle " << particle << " once, when it is first held";
}

TEST(Surfaces, OutletCornersAreTheOutletTrianglesKept)
{
  // What the GPU engine uploads (engine specification 2.10): the Outlet
  // triangles in the order given, without gates, triangles without area
  // or with a corner that is not finite.
  bp::SurfaceTriangles t;
  t.corners = rectangle(0, 1, 0, 1, 0.0f); // two triangles
  const std::vector<float> flat = { 0, 0, 0, 1, 0, 0, 2, 0, 0 };
  const std::vector<float> nan = { 0, 0, 0, 1, 0, 0, NAN, 1, 0 };
  const std::vector<float> gate = { 0, 0, 1, 1, 0, 1, 0, 1, 1 };
  for (const std::vector<float>* v : { &flat, &nan, &gate })
    t.corners.insert(t.corners.end(), v->begin(), v->end());
  t.interaction.assign(4, bp::SurfaceInteraction::Outlet);
  t.interaction.push_back(bp::SurfaceInteraction::Gate);
  const bp::SurfaceSet set(t);
  EXPECT_TRUE(set.hasOutlets());
  EXPECT_EQ(set.triangleCount(), 3u);
  EXPECT_EQ(set.outletCorners(), rectangle(0, 1, 0, 1, 0.0f));
  EXPECT_FALSE(surfaceOf(gate, bp::SurfaceInteraction::Gate)->hasOutlets());
  EXPECT_TRUE(surfaceOf(gate, bp::SurfaceInteraction::Gate)->outletCorners().empty());
  EXPECT_EQ(bp::gpuOutletError(bp::GpuMaxOutletTriangles), "");
  EXPECT_NE(bp::gpuOutletError(bp::GpuMaxOutletTriangles + 1).find("4097 Outlet triangles"),
    std::string::npos);
}

namespace
{
/// The plane x = `x` over y, z in [-1, 1] as Wall triangles (appended).
void wallAtX(bp::SurfaceTriangles& t, float x)
{
  const std::vector<float> c = planeX(x);
  t.corners.insert(t.corners.end(), c.begin(), c.end());
  t.interaction.insert(t.interaction.end(), 2, bp::SurfaceInteraction::Wall);
}

/// The side of a pipe of radius r along z with `facets` flat facets, as Walls.
bp::SurfaceTriangles pipe(float r, int facets)
{
  bp::SurfaceTriangles t;
  for (int k = 0; k < facets; ++k)
  {
    const double a0 = 2 * Pi * k / facets, a1 = 2 * Pi * (k + 1) / facets;
    const float x0 = float(r * std::cos(a0)), y0 = float(r * std::sin(a0));
    const float x1 = float(r * std::cos(a1)), y1 = float(r * std::sin(a1));
    t.corners.insert(
      t.corners.end(), { x0, y0, -1, x1, y1, -1, x1, y1, 1, x0, y0, -1, x1, y1, 1, x0, y0, 1 });
  }
  t.interaction.assign(t.corners.size() / 9, bp::SurfaceInteraction::Wall);
  return t;
}

/// Points released at `seeds` in `flow` under `boundary`, traced `steps` steps of h.
bp::Engine tracedPoints(const bp::VectorField& flow, const std::vector<float>& seeds,
  const bp::SurfaceTriangles& walls, bp::Boundary boundary, int steps, double h)
{
  bp::Parameters p = squares(seeds, 1000.0f);
  p.integrator = bp::Integrator::Euler;
  p.boundary = boundary;
  p.restitution = 0.5f;
  p.surfaces = std::make_shared<const bp::SurfaceSet>(walls);
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Point), p), "");
  engine.initialize(bp::serialRunner());
  run(engine, flow, steps, h);
  return engine;
}
} // namespace

TEST(Surfaces, NoParticlePassesWhereWallsBendInward)
{
  // A corner (walls x = 0.5 and y = 0.6) and a pipe of 24 flat facets:
  // Slip puts a particle on one wall's plane, which at an inward bend lies
  // behind the other; the rule is taken again there. Bounce alike.
  bp::SurfaceTriangles corner;
  wallAtX(corner, 0.5f);
  const std::vector<float> y = rectangle(-1, 1, -1, 1, 0.6f, true); // the plane y = 0.6
  corner.corners.insert(corner.corners.end(), y.begin(), y.end());
  corner.interaction.insert(corner.interaction.end(), 2, bp::SurfaceInteraction::Wall);
  std::vector<float> seeds;
  for (int k = 0; k < 20; ++k)
    seeds.insert(seeds.end(), { -0.9f + 0.05f * k, -0.8f + 0.03f * k, 0.1f * (k % 5) - 0.2f });
  const bp::VectorField along = bptest::uniformFlow({ 1.0f, 0.5f, 0.0f });
  for (bp::Boundary b : { bp::Boundary::Slip, bp::Boundary::Bounce, bp::Boundary::Stick })
  {
    const bp::Engine engine = tracedPoints(along, seeds, corner, b, 400, 0.01);
    float x = -1, yMost = -1;
    for (std::size_t i = 0; i < 20; ++i)
    {
      x = std::max(x, engine.positions()[3 * i]);
      yMost = std::max(yMost, engine.positions()[3 * i + 1]);
    }
    EXPECT_LE(x, 0.5f) << bp::enumName(b);
    EXPECT_LE(yMost, 0.6f) << bp::enumName(b);
  }
  // Inside a pipe of radius 0.8, a flow across it and along it.
  std::vector<float> inside;
  for (int k = 0; k < 40; ++k)
  {
    const double a = 2 * Pi * k / 40, r = 0.6 * (k % 4 + 1) / 4;
    inside.insert(inside.end(), { float(r * std::cos(a)), float(r * std::sin(a)), 0.0f });
  }
  const bp::VectorField across = bptest::uniformFlow({ 0.6f, 0.05f, 0.35f });
  for (bp::Boundary b : { bp::Boundary::Slip, bp::Boundary::Bounce })
  {
    const bp::Engine engine = tracedPoints(across, inside, pipe(0.8f, 24), b, 300, 0.01);
    float widest = 0;
    for (std::size_t i = 0; i < 40; ++i)
    {
      const float* q = engine.positions().data() + 3 * i;
      widest = std::max(widest, std::sqrt(q[0] * q[0] + q[1] * q[1]));
    }
    EXPECT_LE(widest, 0.8f) << bp::enumName(b) << ": every particle inside the pipe";
  }
}

namespace
{
/// The closed box [-a, a]^3 as 12 Wall triangles (two a face, normals outward).
bp::SurfaceTriangles closedBox(float a)
{
  bp::SurfaceTriangles t;
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : { -a, a })
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const float q[4][2] = { { -a, -a }, { a, -a }, { a, a }, { -a, a } };
      for (const int k : { 0, 1, 2, 0, 2, 3 })
      {
        float x[3];
        x[axis] = side;
        x[u] = q[k][0];
        x[v] = side > 0 ? q[k][1] : -q[k][1]; // the corners' right hand outward
        t.corners.insert(t.corners.end(), x, x + 3);
      }
    }
  t.interaction.assign(12, bp::SurfaceInteraction::Wall);
  return t;
}

/// How far the farthest of the engine's particles lies outside [-a, a]^3 (0 inside).
float farthestOutside(const bp::Engine& engine, float a)
{
  float most = 0;
  for (const float x : engine.positions())
    most = std::max(most, std::abs(x) - a);
  return most;
}
} // namespace

TEST(Surfaces, NoParticleLeavesAClosedBoxThroughItsEdgesOrCorners)
{
  // A step through the edge two faces share meets both at one point: the
  // rule on the first leaves its move's start on the second's plane, where
  // the move meets it at t = 0. Points inside a box of side 0.6 (12 Wall
  // triangles), uniform flows aimed at its 12 edges and 8 corners (each
  // turned a little at random) and the ABC flow: none may end outside.
  const float a = 0.3f;
  const bp::SurfaceTriangles box = closedBox(a);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> inside(-0.28f, 0.28f), turn(-0.02f, 0.02f);
  std::vector<float> seeds(3 * 64);
  for (float& x : seeds)
    x = inside(random);
  std::vector<std::array<float, 3>> aims;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (std::abs(x) + std::abs(y) + std::abs(z) >= 2)
          aims.push_back({ float(x), float(y), float(z) }); // 12 edges, 8 corners
  for (bp::Boundary b : { bp::Boundary::Slip, bp::Boundary::Bounce, bp::Boundary::Stick })
  {
    for (std::size_t k = 0; k < aims.size(); ++k)
    {
      std::array<float, 3> u = aims[k];
      for (float& c : u)
        c += k % 2 ? turn(random) : 0.0f; // every other aim exactly at the edge or corner
      const bp::Engine engine = tracedPoints(bptest::uniformFlow(u), seeds, box, b, 60, 0.013);
      EXPECT_LE(farthestOutside(engine, a), 0.0f)
        << bp::enumName(b) << " aimed at " << u[0] << " " << u[1] << " " << u[2];
    }
    const bp::VectorField abc = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(33));
    for (const double h : { 0.05, 0.1 })
    {
      const bp::Engine engine = tracedPoints(abc, seeds, box, b, 200, h);
      EXPECT_LE(farthestOutside(engine, a), 0.0f) << bp::enumName(b) << " in ABC, h " << h;
    }
  }
}

TEST(Surfaces, NoParticleLeavesAClosedPrismThroughItsSharpEdges)
{
  // A prism of equilateral cross-section (circumradius 0.5, z in [-0.5,
  // 0.5]; 8 Wall triangles): at its 60-degree edges a rule's start c + offset
  // m lies behind the other wall, where no move from it meets that wall;
  // the segment from before the step to p is tested last. Flows aimed at its
  // three long edges and their ends (exactly and turned a little) and the
  // ABC flow: none may end outside.
  bp::SurfaceTriangles prism;
  float vx[3], vy[3];
  for (int k = 0; k < 3; ++k)
  {
    vx[k] = float(0.5 * std::cos(Pi / 2 + 2 * Pi * k / 3));
    vy[k] = float(0.5 * std::sin(Pi / 2 + 2 * Pi * k / 3));
  }
  for (int k = 0, j = 1; k < 3; ++k, j = (k + 1) % 3)
    prism.corners.insert(prism.corners.end(),
      { vx[k], vy[k], -0.5f, vx[j], vy[j], -0.5f, vx[j], vy[j], 0.5f, vx[k], vy[k], -0.5f, vx[j],
        vy[j], 0.5f, vx[k], vy[k], 0.5f });
  for (const float z : { -0.5f, 0.5f })
    prism.corners.insert(
      prism.corners.end(), { vx[0], vy[0], z, vx[1], vy[1], z, vx[2], vy[2], z });
  prism.interaction.assign(8, bp::SurfaceInteraction::Wall);
  auto outside = [](const bp::Engine& engine)
  {
    float most = 0;
    for (std::size_t q = 0; q < engine.positions().size(); q += 3)
    {
      const float* p = &engine.positions()[q];
      most = std::max(most, std::abs(p[2]) - 0.5f);
      for (int k = 0; k < 3; ++k) // side k, k + 1: outward normal at 150 + 120 k degrees, 0.25 off
        most = std::max(most,
          float(std::cos(5 * Pi / 6 + 2 * Pi * k / 3) * p[0] +
            std::sin(5 * Pi / 6 + 2 * Pi * k / 3) * p[1] - 0.25));
    }
    return most;
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<float> inside(-0.2f, 0.2f), turn(-0.02f, 0.02f);
  std::vector<float> seeds(3 * 64);
  for (float& x : seeds)
    x = inside(random);
  const bp::VectorField abc = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(33));
  for (bp::Boundary b : { bp::Boundary::Slip, bp::Boundary::Bounce, bp::Boundary::Stick })
  {
    for (int k = 0; k < 3; ++k)
      for (const float z : { -0.5f, 0.0f, 0.5f })
        for (const bool turned : { false, true })
        {
          std::array<float, 3> u = { vx[k], vy[k], z };
          for (float& c : u)
            c += turned ? turn(random) : 0.0f;
          const bp::Engine engine =
            tracedPoints(bptest::uniformFlow(u), seeds, prism, b, 80, 0.013);
          EXPECT_LE(outside(engine), 0.0f)
            << bp::enumName(b) << " aimed at " << u[0] << " " << u[1] << " " << u[2];
        }
    EXPECT_LE(outside(tracedPoints(abc, seeds, prism, b, 200, 0.05)), 0.0f)
      << bp::enumName(b) << " in ABC";
  }
}

TEST(Surfaces, AParticleStartingOnAWallStaysOnTheSideItCameFrom)
{
  // Seeds on the plane x = 0.5 itself, the flow through it (+x): they are
  // kept on the side behind their first step, as one the step met.
  bp::SurfaceTriangles wall;
  wallAtX(wall, 0.5f);
  const bp::VectorField through = bptest::uniformFlow({ 0.7f, 0.3f, 0.0f });
  for (bp::Boundary b : { bp::Boundary::Slip, bp::Boundary::Bounce, bp::Boundary::Stick })
  {
    const bp::Engine engine =
      tracedPoints(through, { 0.5f, 0.0f, 0.0f, 0.5f, -0.4f, 0.3f }, wall, b, 100, 0.01);
    EXPECT_LE(engine.positions()[0], 0.5f) << bp::enumName(b);
    EXPECT_LE(engine.positions()[3], 0.5f) << bp::enumName(b);
  }
}

TEST(Surfaces, WallCornersAreTheWallTrianglesKept)
{
  // What the GPU engine uploads for the Walls (engine specification 2.10):
  // the Wall triangles in the order given (wallCrossing's tie-break), without
  // the other kinds, triangles without area or with a corner not finite.
  bp::SurfaceTriangles t;
  const std::vector<float> outlet = { 0, 0, 1, 1, 0, 1, 0, 1, 1 };
  t.corners = outlet;
  const std::vector<float> walls = rectangle(0, 1, 0, 1, 0.0f); // two triangles
  t.corners.insert(t.corners.end(), walls.begin(), walls.end());
  const std::vector<float> flat = { 0, 0, 0, 1, 0, 0, 2, 0, 0 };
  const std::vector<float> nan = { 0, 0, 0, 1, 0, 0, NAN, 1, 0 };
  for (const std::vector<float>* v : { &flat, &nan })
    t.corners.insert(t.corners.end(), v->begin(), v->end());
  t.interaction.assign(5, bp::SurfaceInteraction::Wall);
  t.interaction[0] = bp::SurfaceInteraction::Outlet;
  const bp::SurfaceSet set(t);
  EXPECT_TRUE(set.hasWalls());
  EXPECT_EQ(set.wallCorners(), walls);
  EXPECT_EQ(set.outletCorners(), outlet);
  EXPECT_TRUE(surfaceOf(outlet, bp::SurfaceInteraction::Outlet)->wallCorners().empty());
  EXPECT_EQ(bp::gpuWallError(bp::GpuMaxWallTriangles), "");
  EXPECT_NE(
    bp::gpuWallError(bp::GpuMaxWallTriangles + 1).find("4097 Wall triangles"), std::string::npos);
}

namespace
{
/// A uniform flow along +x on [-1, 1]^3 with x periodic (period 2).
bp::VectorField periodicAlongX()
{
  bp::GridGeometry g = bptest::grid(9);
  g.periodic = { true, false, false };
  return bptest::uniformFlow({ 1, 0, 0 }, g);
}

/// Squares released at x0 = 0.505 and 0.305 (their centres cross the seam
/// x = 1 in a step of 0.02 from 0.985 to 1.005, and every 2 after), traced
/// to t = 5 past `surfaces` under `boundary`.
bp::Engine acrossTheSeam(std::shared_ptr<const bp::SurfaceSet> surfaces, bp::Boundary boundary)
{
  bp::Parameters p = squares({ 0.505f, 0.0f, 0.0f, 0.305f, 0.3f, -0.2f }, 100.0f);
  p.boundary = boundary;
  p.surfaces = std::move(surfaces);
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
  engine.initialize(bp::serialRunner());
  run(engine, periodicAlongX(), 250, 0.02);
  return engine;
}
} // namespace

TEST(Surfaces, ACentreCrossingAPeriodicSeamPassesAGateJustPastIt)
{
  // A gate at x = -0.9975, 0.0025 past the seam: the step that crosses the
  // seam reaches it after the period's move, the next starts beyond it.
  // Each element passes it at (1.0025 - x0) + 2 k, k = 0, 1, 2 to t = 5;
  // a gate just before the seam (x = 0.9975) as often, at (0.9975 - x0) + 2 k.
  for (const float at : { -0.9975f, 0.9975f })
  {
    const bp::Engine engine = acrossTheSeam(
      surfaceOf(planeX(at), bp::SurfaceInteraction::Gate), bp::Boundary::ReleaseAgain);
    std::map<std::uint32_t, std::vector<bp::InteractionEvent>> passes;
    for (const bp::InteractionEvent& x : engine.interactions().events())
      passes[x.element].push_back(x);
    ASSERT_EQ(passes.size(), 2u) << "gate at " << at;
    const double x0[2] = { 0.505, 0.305 };
    for (const auto& [element, events] : passes)
    {
      ASSERT_EQ(events.size(), 3u) << "gate at " << at << ", element " << element;
      for (std::size_t k = 0; k < 3; ++k)
      {
        EXPECT_EQ(events[k].kind, bp::Interaction::Passed);
        EXPECT_NEAR(events[k].position[0], at, 1e-5f);
        const double unwrapped = at < 0.0f ? at + 2.0 : at;
        EXPECT_NEAR(events[k].time, unwrapped - x0[element] + 2.0 * double(k), 1e-4);
      }
    }
  }
}

TEST(Surfaces, ACentreCrossingAPeriodicSeamEndsAtAnOutletOrWallJustPastIt)
{
  // An Outlet, or a Wall with Terminate, at x = -0.9975: each element ends
  // there at 1.0025 - x0, once; a Wall with Release Again places it again.
  for (const bp::SurfaceInteraction kind :
    { bp::SurfaceInteraction::Outlet, bp::SurfaceInteraction::Wall })
  {
    for (const bp::Boundary boundary : { bp::Boundary::Terminate, bp::Boundary::ReleaseAgain })
    {
      if (kind == bp::SurfaceInteraction::Outlet && boundary == bp::Boundary::ReleaseAgain)
        continue;
      bp::SurfaceTriangles t;
      t.corners = planeX(-0.9975f);
      t.surfaces = { 3, 3 };
      t.interaction.assign(2, kind);
      t.cells = { 9, 9 };
      const bp::Engine engine = acrossTheSeam(std::make_shared<bp::SurfaceSet>(t), boundary);
      const std::vector<bp::InteractionEvent> events = engine.interactions().events();
      const bool released = boundary == bp::Boundary::ReleaseAgain;
      const double x0[2] = { 0.505, 0.305 };
      std::size_t ended[2] = { 0, 0 };
      for (const bp::InteractionEvent& x : events)
      {
        ASSERT_LT(x.element, 2u);
        EXPECT_EQ(x.side, bp::FirstSurfaceId + 3);
        EXPECT_EQ(x.kind, released ? bp::Interaction::Released : bp::Interaction::Terminated);
        EXPECT_NEAR(x.position[0], -0.9975f, 1e-5f);
        if (ended[x.element]++ == 0)
          EXPECT_NEAR(x.time, 1.0025 - x0[x.element], 1e-4);
      }
      for (std::size_t e = 0; e < 2; ++e)
      {
        // Released, it is placed again at its seed and meets the wall again.
        EXPECT_TRUE(released ? ended[e] >= 2u : ended[e] == 1u)
          << int(kind) << " " << int(boundary) << ": " << ended[e];
      }
      for (std::uint8_t flag : engine.resetFlags())
        EXPECT_EQ(bool(flag & bp::Terminated), !released);
    }
  }
}

TEST(Surfaces, ASurfaceSpanningAPeriodicSeamIsPassedOnce)
{
  // One gate given twice, on either side of the seam: at x = 1.0025 (past
  // the upper side, outside the box) and at its copy x = -0.9975. The
  // crossing outside the box is not kept: each element passes it once a lap.
  std::vector<float> corners = planeX(1.0025f);
  const std::vector<float> copy = planeX(-0.9975f);
  corners.insert(corners.end(), copy.begin(), copy.end());
  const bp::Engine engine =
    acrossTheSeam(surfaceOf(corners, bp::SurfaceInteraction::Gate), bp::Boundary::ReleaseAgain);
  std::size_t passes[2] = { 0, 0 };
  for (const bp::InteractionEvent& x : engine.interactions().events())
  {
    ASSERT_LT(x.element, 2u);
    ++passes[x.element];
    EXPECT_NEAR(x.position[0], -0.9975f, 1e-5f);
  }
  EXPECT_EQ(passes[0], 3u);
  EXPECT_EQ(passes[1], 3u);
}

TEST(Surfaces, ACentreThroughAPeriodicCornerPassesAGateBetweenItsTwoSeams)
{
  // x and y periodic, the flow (1, 1, 0): a square released at (0.505,
  // 0.515) goes through the corner in the step from (0.985, 0.995) to
  // (1.005, 1.015), across the y seam at a quarter of it and the x seam at
  // three quarters. A gate at x = 0.995 over y in [-1, -0.98] lies in the
  // piece between the two (past the y seam only): passed at t = 0.49 + 2 k.
  bp::GridGeometry g = bptest::grid(9);
  g.periodic = { true, true, false };
  const bp::VectorField field = bptest::uniformFlow({ 1, 1, 0 }, g);
  std::vector<float> corners = rectangle(-1.0f, 1.0f, -1.0f, -0.98f, 0.995f);
  for (std::size_t k = 0; k < corners.size(); k += 3)
    std::swap(corners[k], corners[k + 2]); // the plane x = 0.995
  bp::Parameters p = squares({ 0.505f, 0.515f, 0.0f }, 100.0f);
  p.surfaces = surfaceOf(corners, bp::SurfaceInteraction::Gate);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Square), p), "");
  engine.initialize(bp::serialRunner());
  run(engine, field, 250, 0.02);
  const std::vector<bp::InteractionEvent> events = engine.interactions().events();
  ASSERT_EQ(events.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(events[k].time, 0.49 + 2.0 * double(k), 1e-4);
    EXPECT_NEAR(events[k].position[0], 0.995f, 1e-5f);
    EXPECT_NEAR(events[k].position[1], -0.995f, 1e-4f);
  }
}
