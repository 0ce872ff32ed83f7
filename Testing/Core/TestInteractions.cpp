// SPDX-License-Identifier: BSD-3-Clause
// The events at the field's sides (Interactions.h, engine specification
// 2.9): the contact rule alone, then the CPU engine's record of them under
// each Boundary: a Stick or Slip particle's first contact once, each
// bounce, an element leaving once; a copy of the engine (a short step's
// save, a checkpoint) going back and on gives the straight trace's events,
// and threads change nothing.
#include "Engine.h"
#include "Interactions.h"
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

namespace
{
using bptest::cube;
using bptest::uniformFlow;

/// `count` elements of `shape` (size 0.5, along x) released at `at`.
bp::Engine started(bp::Boundary boundary, bp::BuiltinShape shape, std::array<float, 3> at,
  float restitution = 1.0f, std::size_t count = 1, float lifetime = 100.0f)
{
  bp::Parameters p;
  p.numberOfElements = count;
  p.elementSize = 0.5f;
  p.emitterMin = p.emitterMax = at;
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = lifetime;
  p.iterations = 8;
  p.boundary = boundary;
  p.restitution = restitution;
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(shape), p), "");
  engine.initialize(bp::serialRunner());
  return engine;
}

void run(bp::Engine& engine, const bp::VectorField& field, int from, int to, double h,
  const bp::RangeRunner& runner = bp::serialRunner())
{
  for (int s = from; s < to; ++s)
    engine.step(field, s * h, h, runner);
}

/// Events per (element, particle).
std::map<std::pair<std::uint32_t, int>, int> perParticle(const bp::Engine& engine)
{
  std::map<std::pair<std::uint32_t, int>, int> count;
  for (const bp::InteractionEvent& x : engine.interactions().events())
    ++count[{ x.element, x.particle }];
  return count;
}

void expectSame(
  const std::vector<bp::InteractionEvent>& a, const std::vector<bp::InteractionEvent>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    EXPECT_EQ(a[k].time, b[k].time) << k;
    EXPECT_EQ(a[k].element, b[k].element) << k;
    EXPECT_EQ(a[k].particle, b[k].particle) << k;
    EXPECT_EQ(a[k].kind, b[k].kind) << k;
    EXPECT_EQ(a[k].side, b[k].side) << k;
    EXPECT_EQ(a[k].position, b[k].position) << k;
    EXPECT_EQ(a[k].velocity, b[k].velocity) << k;
  }
}
} // namespace

TEST(Interactions, TheFirstContactIsWhereTheStepMeetsANewSide)
{
  float point[3];
  const float before[3] = { 0, 0, 0 }, beyond[3] = { 2, 0.5f, -0.5f };
  EXPECT_EQ(bp::firstContact(cube(), before, beyond, point), 1); // +x
  EXPECT_EQ(point[0], 1.0f);
  EXPECT_FLOAT_EQ(point[1], 0.25f);
  EXPECT_FLOAT_EQ(point[2], -0.25f);
  // Two sides crossed: the nearer along the step.
  const float from[3] = { 0.5f, 0, 0 }, corner[3] = { 3, -1.5f, 0 };
  EXPECT_EQ(bp::firstContact(cube(), from, corner, point), 1);
  // A side the particle lay on before the step is no contact (Slip's slide).
  const float onFloor[3] = { 0.2f, -1, 0 }, intoFloor[3] = { 0.4f, -1.1f, 0 };
  EXPECT_EQ(bp::firstContact(cube(), onFloor, intoFloor, point), bp::NoSide);
  // ... but another side met from there is.
  const float intoCorner[3] = { 1.2f, -1.1f, 0 };
  EXPECT_EQ(bp::firstContact(cube(), onFloor, intoCorner, point), 1);
  EXPECT_EQ(point[0], 1.0f);
  EXPECT_EQ(point[1], -1.0f);
  // Inside: none. From outside the box: the side it lies beyond, clamped.
  const float inside[3] = { 0.5f, 0.5f, 0.5f };
  EXPECT_EQ(bp::firstContact(cube(), before, inside, point), bp::NoSide);
  const float outside[3] = { 0, -1.5f, 0 }, still[3] = { 0.5f, -1.25f, 0 };
  EXPECT_EQ(bp::firstContact(cube(), outside, still, point), 2); // -y
  EXPECT_EQ(point[1], -1.0f);
  // The sides and their normals; a flat or periodic axis has none.
  EXPECT_EQ(bp::sideNormal(0), (std::array<float, 3>{ -1, 0, 0 }));
  EXPECT_EQ(bp::sideNormal(5), (std::array<float, 3>{ 0, 0, 1 }));
  EXPECT_EQ(bp::sideNormal(bp::NoSide), (std::array<float, 3>{ 0, 0, 0 }));
  EXPECT_EQ(bp::lowestSide(0), bp::NoSide);
  EXPECT_EQ(bp::lowestSide((1u << 3) | (1u << 4)), 3);
  bp::Domain periodic = cube();
  periodic.periodic[0] = true;
  EXPECT_EQ(bp::firstContact(periodic, before, beyond, point), bp::NoSide);
  EXPECT_EQ(bp::InteractionNames[int(bp::Interaction::Slid)], std::string("Slid"));
}

TEST(Interactions, StickRecordsEachParticleOnceWhenItIsFirstHeld)
{
  // Flow into x = 1 and along it: the strip's particles reach the wall one
  // after another and are held there; each is recorded once, where it is held.
  const bp::VectorField field = uniformFlow({ 1.0f, 0.25f, 0 });
  bp::Engine engine = started(bp::Boundary::Stick, bp::BuiltinShape::Strip4, { 0.5f, -0.5f, 0 });
  const double h = 0.01;
  run(engine, field, 0, 150, h);
  const std::vector<bp::InteractionEvent> events = engine.interactions().events();
  ASSERT_FALSE(events.empty());
  int held = 0;
  for (int i = 0; i < 4; ++i)
  {
    const float* q = engine.positions().data() + 3 * i;
    if (bp::onWall(cube(), q))
      ++held;
  }
  EXPECT_GE(held, 1);
  EXPECT_EQ(events.size(), std::size_t(held));
  for (const bp::InteractionEvent& x : events)
  {
    EXPECT_EQ(x.kind, bp::Interaction::Stuck);
    EXPECT_EQ(x.side, 1);
    EXPECT_EQ(x.element, 0u);
    const float* q = engine.positions().data() + 3 * x.particle;
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(x.position[std::size_t(k)], q[k]) << "the event is where the particle is held";
    // A step's end on the schedule.
    const double step = x.time / h;
    EXPECT_NEAR(step, std::round(step), 1e-9);
    EXPECT_GT(x.velocity[0], 0.0f); // the element was still moving into the wall
  }
  // Held on: nothing more.
  run(engine, field, 150, 300, h);
  EXPECT_EQ(engine.interactions().size(), events.size());
}

TEST(Interactions, SlipRecordsTheFirstContactNotTheSlide)
{
  // One particle carried onto the floor y = -1 and along it for many steps:
  // one event, when it reached the floor.
  const bp::VectorField field = uniformFlow({ 0.5f, -1.0f, 0 });
  bp::Engine point = started(bp::Boundary::Slip, bp::BuiltinShape::Point, { -0.9f, -0.5f, 0 });
  run(point, field, 0, 150, 0.01);
  ASSERT_EQ(point.interactions().size(), 1u);
  const bp::InteractionEvent x = point.interactions().events()[0];
  EXPECT_EQ(x.kind, bp::Interaction::Slid);
  EXPECT_EQ(x.side, 2); // -y
  EXPECT_EQ(x.particle, 0);
  EXPECT_EQ(x.position[1], -1.0f);
  EXPECT_NEAR(x.time, 0.5, 0.011); // it travels 0.5 down at speed 1
  EXPECT_EQ(point.positions()[1], -1.0f);
  EXPECT_GT(point.positions()[0], x.position[0] + 0.4f); // slid on along the floor

  // A strip turned 45 degrees to the wall lies down on it and slides
  // (Walls.AStripLiesDownOnASlipWallAndSlidesAlongIt): each particle once.
  const bp::VectorField into = uniformFlow({ 1.0f, 0.25f, 0 });
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.5f;
  p.emitterMin = p.emitterMax = { 0.5f, -0.5f, 0 };
  p.orientation = bp::Orientation::Fixed;
  const float c = std::sqrt(0.5f);
  p.frame = { c, 0, c, 0, 1, 0, -c, 0, c };
  p.lifetimeMin = p.lifetimeMax = 100.0f;
  p.iterations = 8;
  p.boundary = bp::Boundary::Slip;
  bp::Engine strip;
  ASSERT_EQ(strip.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  strip.initialize(bp::serialRunner());
  run(strip, into, 0, 150, 0.01);
  const auto count = perParticle(strip);
  EXPECT_EQ(count.size(), 4u);
  for (const auto& k : count)
    EXPECT_EQ(k.second, 1) << "particle " << k.first.second;
}

TEST(Interactions, BounceRecordsEachBounce)
{
  // One particle in a uniform flow into x = 1 with a mirror: once it is
  // within a step of the wall, every step takes it beyond and back: a bounce.
  const bp::VectorField field = uniformFlow({ 1.0f, 0, 0 });
  bp::Engine engine = started(bp::Boundary::Bounce, bp::BuiltinShape::Point, { 0.55f, 0, 0 });
  const double h = 0.1;
  int bounces = 0;
  for (int s = 0; s < 20; ++s)
  {
    const float x = engine.positions()[0];
    bounces += x + float(h) > 1.0f ? 1 : 0;
    engine.step(field, s * h, h, bp::serialRunner());
  }
  EXPECT_GT(bounces, 10);
  const std::vector<bp::InteractionEvent> events = engine.interactions().events();
  ASSERT_EQ(events.size(), std::size_t(bounces));
  for (std::size_t k = 0; k < events.size(); ++k)
  {
    EXPECT_EQ(events[k].kind, bp::Interaction::Bounced);
    EXPECT_EQ(events[k].side, 1);
    EXPECT_EQ(events[k].position[0], 1.0f); // on the wall, where the step met it
    if (k > 0)
      EXPECT_GT(events[k].time, events[k - 1].time);
  }
}

TEST(Interactions, AnElementThatLeavesIsRecordedOnceAtItsCentre)
{
  // Release Again: each generation leaves through x = 1 once.
  const bp::VectorField field = uniformFlow({ 1.0f, 0, 0 });
  bp::Engine again =
    started(bp::Boundary::ReleaseAgain, bp::BuiltinShape::Strip4, { 0.5f, 0, 0 }, 1.0f, 1, 10.0f);
  run(again, field, 0, 200, 0.01);
  const std::vector<bp::InteractionEvent> released = again.interactions().events();
  ASSERT_GE(released.size(), 3u);
  EXPECT_EQ(released.size(),
    std::size_t(again.generations()[0]) + (again.resetFlags()[0] & bp::ResetDue ? 1u : 0u));
  for (const bp::InteractionEvent& x : released)
  {
    EXPECT_EQ(x.kind, bp::Interaction::Released);
    EXPECT_EQ(x.particle, -1);
    EXPECT_EQ(x.side, 1);
    EXPECT_GT(x.position[0], 1.0f); // the centre beyond the side
    EXPECT_LT(x.position[0], 1.02f);
    EXPECT_NEAR(x.velocity[0], 1.0f, 1e-3f);
  }
  // Terminate: once, then nothing while it waits out its lifetime.
  bp::Engine ended =
    started(bp::Boundary::Terminate, bp::BuiltinShape::Strip4, { 0.5f, 0, 0 }, 1.0f, 1, 1.0f);
  run(ended, field, 0, 90, 0.01);
  const std::vector<bp::InteractionEvent> terminated = ended.interactions().events();
  ASSERT_EQ(terminated.size(), 1u);
  EXPECT_EQ(terminated[0].kind, bp::Interaction::Terminated);
  EXPECT_EQ(terminated[0].particle, -1);
  EXPECT_NEAR(terminated[0].time, 0.5, 0.011);
  // Walls keep the element in: no element events.
  bp::Engine walled = started(bp::Boundary::Slip, bp::BuiltinShape::Strip4, { 0.5f, 0, 0 });
  run(walled, field, 0, 200, 0.01);
  for (const bp::InteractionEvent& x : walled.interactions().events())
    EXPECT_GE(x.particle, 0);
}

TEST(Interactions, GoingBackToACopyAndOnGivesTheStraightTracesEvents)
{
  // Many strips in the hurricane flow with Bounce and Stick, and Release
  // Again: a copy taken midway (a checkpoint, a short step's save), stepped
  // on, holds the straight trace's events; the straight engine taken back to
  // the copy holds the copy's; threads change nothing.
  const bp::VectorField field = bptest::steadyFlow(bp::AnalyticFlow::Hurricane, bptest::grid(9));
  for (const bp::Boundary boundary :
    { bp::Boundary::Bounce, bp::Boundary::Stick, bp::Boundary::ReleaseAgain })
  {
    bp::Parameters p;
    p.numberOfElements = 64;
    p.elementSize = 0.3f;
    p.emitterMin = { -0.9f, -0.9f, -0.9f };
    p.emitterMax = { 0.9f, 0.9f, 0.9f };
    p.lifetimeMin = 1.0f;
    p.lifetimeMax = 3.0f;
    p.boundary = boundary;
    p.restitution = 0.6f;
    bp::Engine straight;
    ASSERT_EQ(straight.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
    straight.initialize(bp::serialRunner());
    const double h = 0.02;
    run(straight, field, 0, 50, h);
    const bp::Engine midway = straight; // a checkpoint
    const std::vector<bp::InteractionEvent> early = midway.interactions().events();
    run(straight, field, 50, 150, h);
    EXPECT_GT(straight.interactions().size(), early.size()) << int(boundary);
    bp::Engine resumed = midway;
    run(resumed, field, 50, 150, h, bp::poolRunner(3));
    expectSame(resumed.interactions().events(), straight.interactions().events());
    // The copy kept its own: the later steps are not in it.
    expectSame(midway.interactions().events(), early);
    straight = midway;
    expectSame(straight.interactions().events(), early);
    // In the output's order, without repeats.
    const std::vector<bp::InteractionEvent> all = resumed.interactions().events();
    for (std::size_t k = 1; k < all.size(); ++k)
      EXPECT_TRUE(bp::interactionBefore(all[k - 1], all[k])) << k;
  }
}

TEST(Interactions, ANewTraceOrAResumedStateStartsWithNone)
{
  const bp::VectorField field = uniformFlow({ 1.0f, 0, 0 });
  bp::Engine engine =
    started(bp::Boundary::ReleaseAgain, bp::BuiltinShape::Strip4, { 0.5f, 0, 0 }, 1.0f, 1, 10.0f);
  run(engine, field, 0, 100, 0.01);
  ASSERT_GT(engine.interactions().size(), 0u);
  const bp::EngineState state = engine.saveState();
  bp::Engine resumed = engine;
  EXPECT_EQ(resumed.loadState(state), "");
  EXPECT_EQ(resumed.interactions().size(), 0u);
  engine.initialize(bp::serialRunner());
  EXPECT_EQ(engine.interactions().size(), 0u);
}

TEST(Interactions, ALongLogIsFreedWithoutDeepRecursion)
{
  bp::InteractionLog log;
  for (int s = 0; s < 300000; ++s)
    log.append(std::vector<bp::InteractionEvent>(1));
  bp::InteractionLog copy = log;
  log.append(std::vector<bp::InteractionEvent>(2));
  EXPECT_EQ(log.size(), 300002u);
  EXPECT_EQ(copy.size(), 300000u);
  log.clear();
  copy.clear(); // the last holder frees the steps one by one
  EXPECT_EQ(copy.size(), 0u);
}

TEST(Interactions, ALogGivesTheEventsAppendedSinceAMark)
{
  // The Interactions output keeps the events a log shares with the one it
  // last showed and appends the rest: a log that only grew shares them all;
  // a copy gone back in time (a short step's save) or one that went another
  // way from there shares those up to the last step both hold.
  auto step = [](std::uint32_t first, std::uint32_t count)
  {
    std::vector<bp::InteractionEvent> events(count);
    for (std::uint32_t k = 0; k < count; ++k)
      events[k].element = first + k;
    return events;
  };
  auto elements = [](const std::vector<bp::InteractionEvent>& events)
  {
    std::vector<std::uint32_t> ids;
    for (const bp::InteractionEvent& x : events)
      ids.push_back(x.element);
    return ids;
  };
  using Ids = std::vector<std::uint32_t>;
  bp::InteractionLog log;
  std::vector<bp::InteractionEvent> added;
  EXPECT_EQ(log.eventsSince(bp::InteractionLog::Mark(), added), 0u);
  EXPECT_TRUE(added.empty());
  log.append(step(0, 2));
  EXPECT_EQ(log.eventsSince(bp::InteractionLog::Mark(), added), 0u);
  EXPECT_EQ(elements(added), (Ids{ 0, 1 }));
  const bp::InteractionLog::Mark first = log.mark();
  EXPECT_EQ(first.size(), 2u);
  const bp::InteractionLog back = log;
  log.append(step(2, 3));
  log.append({});
  log.append(step(5, 1));
  EXPECT_EQ(log.eventsSince(first, added), 2u);
  EXPECT_EQ(elements(added), (Ids{ 2, 3, 4, 5 }));
  EXPECT_EQ(log.eventsSince(log.mark(), added), 6u);
  EXPECT_TRUE(added.empty());
  // Back in time: the first two shared, nothing after.
  EXPECT_EQ(back.eventsSince(log.mark(), added), 2u);
  EXPECT_TRUE(added.empty());
  // Another way from `first` (a short step taken back, then steps on): as
  // many events as the later log, another head.
  bp::InteractionLog other = back;
  other.append(step(20, 4));
  EXPECT_EQ(other.size(), log.size());
  EXPECT_EQ(other.eventsSince(log.mark(), added), 2u);
  EXPECT_EQ(elements(added), (Ids{ 20, 21, 22, 23 }));
  EXPECT_EQ(log.eventsSince(other.mark(), added), 2u);
  EXPECT_EQ(elements(added), (Ids{ 2, 3, 4, 5 }));
  // Nothing shared: a cleared log, a new trace.
  other.clear();
  EXPECT_EQ(other.eventsSince(first, added), 0u);
  EXPECT_TRUE(added.empty());
  bp::InteractionLog fresh;
  fresh.append(step(0, 2));
  EXPECT_EQ(fresh.eventsSince(first, added), 0u);
  EXPECT_EQ(elements(added), (Ids{ 0, 1 }));
}

TEST(Interactions, ALogKeepsTheFirstEventsUpToItsCapacity)
{
  // An outflow with Release Again leaves events every step of a long trace:
  // the log stops at its capacity, keeps the first events in order, and says
  // it is full; a copy taken before stays as it was.
  bp::InteractionLog log;
  EXPECT_EQ(log.capacity(), bp::InteractionLog::DefaultCapacity);
  log.setCapacity(5);
  auto step = [](std::uint32_t first, std::uint32_t count)
  {
    std::vector<bp::InteractionEvent> events(count);
    for (std::uint32_t k = 0; k < count; ++k)
      events[k].element = first + k;
    return events;
  };
  log.append(step(0, 3));
  const bp::InteractionLog before = log;
  EXPECT_FALSE(log.full());
  log.append(step(3, 4)); // two fit
  EXPECT_TRUE(log.full());
  EXPECT_EQ(log.size(), 5u);
  log.append(step(7, 1));
  EXPECT_EQ(log.size(), 5u);
  const std::vector<bp::InteractionEvent> kept = log.events();
  ASSERT_EQ(kept.size(), 5u);
  for (std::uint32_t k = 0; k < 5; ++k)
    EXPECT_EQ(kept[k].element, k);
  EXPECT_FALSE(before.full());
  EXPECT_EQ(before.size(), 3u);
  // Exactly full with nothing left out is not full; the next event is.
  bp::InteractionLog exact;
  exact.setCapacity(3);
  exact.append(step(0, 3));
  EXPECT_FALSE(exact.full());
  exact.append(step(3, 1));
  EXPECT_TRUE(exact.full());
  EXPECT_EQ(exact.size(), 3u);
  log.clear();
  EXPECT_FALSE(log.full());
}

TEST(Interactions, AnElementNotShownRecordsNothing)
{
  // One burst at t = 0 (a release window [0, 0.05]) of strips whose
  // leading particles reach the wall x = 1 in their first step; their
  // lifetime ends at 0.1 and the next release waits, hidden, for a window
  // that never comes: placed and moved every step, but not shown, so
  // nothing after the first generation is an event (it was, every step).
  const bp::VectorField field = uniformFlow({ 1.0f, 0.0f, 0 });
  bp::Parameters p;
  p.numberOfElements = 3;
  p.elementSize = 0.5f;
  p.emitterMin = p.emitterMax = { 0.79f, 0.0f, 0.0f };
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = 0.1f;
  p.boundary = bp::Boundary::Slip;
  p.releaseStart = 0.0;
  p.releaseStop = 0.05;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.initialize(bp::serialRunner());
  const double h = 0.02;
  run(engine, field, 0, 50, h);
  const std::vector<bp::InteractionEvent> events = engine.interactions().events();
  EXPECT_FALSE(events.empty()); // the first generation's contacts
  for (const bp::InteractionEvent& x : events)
    EXPECT_LE(x.time, 0.1 + h + 1e-9) << "an event of a hidden element";
  EXPECT_EQ(events.size(), 6u); // two particles of each strip, once
}
