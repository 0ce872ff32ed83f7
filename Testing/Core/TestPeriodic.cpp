// SPDX-License-Identifier: BSD-3-Clause
// Periodic axes (Periodic.h, engine specification 2.8 "Periodic domains"):
// the wrap rules, the field sampled across the seam, a periodic axis without
// sides, and the CPU engine's elements moved whole across it.
#include "Periodic.h"
#include "TestHelpers.h"
#include "Walls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace
{
/// The flow (sin(pi x), 0, 0) on [-1, 1]^3 (9 points a side): its last x
/// plane repeats its first (sin(-pi) = sin(pi) = 0, and both are written 0).
bp::VectorField sineFlow(const bp::GridGeometry& g)
{
  auto velocity = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        const bool side = i == 0 || i == g.dims[0] - 1;
        const double x = g.coordinate(0, i);
        velocity->insert(velocity->end(),
          { side ? 0.0f : float(std::sin(M_PI * x)), float(0.5 * g.coordinate(1, j)), 0.0f });
      }
  bp::FieldSlice s;
  s.velocity = velocity;
  return bp::VectorField(g, s);
}

bp::GridGeometry periodicGrid(std::array<bool, 3> periodic)
{
  bp::GridGeometry g = bptest::grid(9);
  g.periodic = periodic;
  return g;
}

/// Eight Strip4 elements of size 0.5 over x in [-0.6, 0.6], y in [-0.5, 0.5].
bp::Parameters strips(bp::Boundary boundary)
{
  bp::Parameters p;
  p.numberOfElements = 8;
  p.elementSize = 0.5f;
  p.emitterMin = { -0.6f, -0.5f, 0 };
  p.emitterMax = { 0.6f, 0.5f, 0 };
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = p.lifetimeMax = 1000.0f;
  p.iterations = 4;
  p.boundary = boundary;
  return p;
}

bp::Engine started(const bp::Parameters& p)
{
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip4), p), "");
  engine.initialize(bp::serialRunner());
  return engine;
}

std::array<float, 3> centerOf(const bp::Engine& engine, std::size_t e)
{
  const std::size_t n = engine.particlesPerElement();
  std::array<float, 3> c = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      c[k] += engine.positions()[3 * (e * n + i) + k] / float(n);
  return c;
}
} // namespace

TEST(Periodic, WrapMovesByWholePeriodsIntoTheExtent)
{
  EXPECT_EQ(bp::wrapPeriodic(0.25f, -1, 1), 0.25f);
  EXPECT_EQ(bp::wrapPeriodic(1.0f, -1, 1), 1.0f); // the last plane stands for the first
  EXPECT_EQ(bp::wrapPeriodic(-1.0f, -1, 1), -1.0f);
  EXPECT_FLOAT_EQ(bp::wrapPeriodic(1.25f, -1, 1), -0.75f);
  EXPECT_FLOAT_EQ(bp::wrapPeriodic(-1.5f, -1, 1), 0.5f);
  EXPECT_FLOAT_EQ(bp::wrapPeriodic(7.5f, -1, 1), -0.5f); // several periods
  for (float x : { 1.0000001f, -1.0000001f, 3.0f, -3.0f, 1e6f, -1e6f })
  {
    const float w = bp::wrapPeriodic(x, -1, 1);
    EXPECT_GE(w, -1.0f) << x;
    EXPECT_LT(w, 1.0f) << x;
  }
  EXPECT_TRUE(std::isnan(bp::wrapPeriodic(NAN, -1, 1)));
  EXPECT_EQ(bp::wrapPeriodic(INFINITY, -1, 1), INFINITY);
  // The element's shift: 0 inside (sides included), whole periods beyond.
  EXPECT_EQ(bp::periodicShift(1.0f, -1, 1), 0.0f);
  EXPECT_EQ(bp::periodicShift(-1.0f, -1, 1), 0.0f);
  EXPECT_EQ(bp::periodicShift(1.25f, -1, 1), -2.0f);
  EXPECT_EQ(bp::periodicShift(-1.25f, -1, 1), 2.0f);
  EXPECT_EQ(bp::periodicShift(5.5f, -1, 1), -6.0f);
  EXPECT_EQ(bp::periodicShift(NAN, -1, 1), 0.0f);
  EXPECT_EQ(bp::periodicShift(-INFINITY, -1, 1), 0.0f);
}

TEST(Periodic, TheFieldIsSampledAcrossTheSeam)
{
  const bp::VectorField periodic = sineFlow(periodicGrid({ true, false, false }));
  const bp::VectorField clamped = sineFlow(periodicGrid({ false, false, false }));
  const float beyond[3] = { 1.3f, 0.3f, 0.1f }, across[3] = { -0.7f, 0.3f, 0.1f };
  float v[3], w[3], c[3];
  periodic.sample(beyond, 0.0, v);
  periodic.sample(across, 0.0, w);
  clamped.sample(beyond, 0.0, c);
  for (int k = 0; k < 3; ++k)
    EXPECT_FLOAT_EQ(v[k], w[k]) << k; // the same cell, the same weights
  EXPECT_LT(v[0], -0.5f);             // sin(pi * 1.3) < 0, read across the seam
  EXPECT_EQ(c[0], 0.0f);              // without Periodic: the boundary's value
  // y is not periodic: beyond its side it still reads the boundary's value.
  const float above[3] = { 0.0f, 1.5f, 0.0f };
  periodic.sample(above, 0.0, v);
  EXPECT_FLOAT_EQ(v[1], 0.5f);
  // The curl and the derivatives read the same cell.
  float curl[3], u[3];
  periodic.sampleWithCurl(beyond, 0.0f, v, curl);
  periodic.sampleWithCurl(across, 0.0f, w, c);
  periodic.sample(across, 0.0, u);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_FLOAT_EQ(curl[k], c[k]) << k;
    EXPECT_FLOAT_EQ(v[k], u[k]) << k;
  }
  // A rectilinear periodic axis wraps by its own extent.
  bp::GridGeometry r = periodicGrid({ true, false, false });
  r.setCoordinates(0, { -1.0, -0.9, -0.5, 0.0, 0.2, 0.5, 0.7, 0.95, 1.0 });
  const bp::VectorField rect = sineFlow(r);
  rect.sample(beyond, 0.0, v);
  rect.sample(across, 0.0, w);
  EXPECT_FLOAT_EQ(v[0], w[0]);
  EXPECT_TRUE(rect.samplingConstants().periodic[0]);
  EXPECT_FALSE(rect.samplingConstants().periodic[1]);
}

TEST(Periodic, APeriodicAxisHasNoSidesAndAPlaneIsNeverPeriodic)
{
  const bp::VectorField field = sineFlow(periodicGrid({ true, false, false }));
  const bp::Domain& box = field.domain();
  EXPECT_TRUE(box.periodic[0]);
  EXPECT_FALSE(box.bounded(0));
  EXPECT_TRUE(box.bounded(1));
  const float beyondX[3] = { 3, 0, 0 }, beyondY[3] = { 0, 3, 0 }, onX[3] = { 1, 0, 0 };
  EXPECT_TRUE(box.contains(beyondX));
  EXPECT_FALSE(box.contains(beyondY));
  EXPECT_FALSE(bp::onWall(box, onX)); // no wall on a periodic side
  float p[3] = { 3, 3, 0 };
  EXPECT_EQ(bp::clampToBox(box, p), 1u << 3); // upper y only
  EXPECT_EQ(p[0], 3.0f);
  // An axis of one point is a plane, periodic or not.
  bp::GridGeometry flat = bptest::grid(9, -1.0, 1.0, 1);
  flat.periodic = { false, false, true };
  const bp::VectorField plane = sineFlow(flat);
  EXPECT_FALSE(plane.domain().periodic[2]);
  EXPECT_FALSE(plane.samplingConstants().periodic[2]);
}

TEST(Periodic, AUniformFlowBringsEveryElementBackAfterOnePeriod)
{
  // Period 2 along x at speed 1: after 2 time units every element is back
  // where it started, never released, its springs at rest all the way.
  const bp::VectorField field =
    bptest::uniformFlow({ 1, 0, 0 }, periodicGrid({ true, false, false }));
  for (bp::Boundary b : { bp::Boundary::ReleaseAgain, bp::Boundary::Terminate, bp::Boundary::Bounce,
         bp::Boundary::Stick })
  {
    bp::Engine engine = started(strips(b));
    const double h = 0.01;
    engine.step(field, 0.0, h, bp::serialRunner());
    const std::vector<float> start = engine.positions();
    double worst = 0.0;
    float lowest = 1, highest = -1;
    for (int s = 1; s <= 200; ++s)
    {
      engine.step(field, s * h, h, bp::serialRunner());
      worst = std::max(worst, bptest::worstSpringStrain(engine));
      for (std::size_t e = 0; e < engine.elementCount(); ++e)
      {
        lowest = std::min(lowest, centerOf(engine, e)[0]);
        highest = std::max(highest, centerOf(engine, e)[0]);
      }
    }
    EXPECT_LT(worst, 1e-4) << bp::enumName(b); // springs stay short across the seam
    EXPECT_GE(lowest, -1.0f) << bp::enumName(b);
    EXPECT_LE(highest, 1.0f) << bp::enumName(b);
    for (std::size_t e = 0; e < engine.elementCount(); ++e)
    {
      EXPECT_EQ(engine.generations()[e], 0u) << bp::enumName(b) << " element " << e;
      EXPECT_EQ(engine.resetFlags()[e], 0u) << bp::enumName(b) << " element " << e;
    }
    for (std::size_t i = 0; i < start.size(); ++i)
      EXPECT_NEAR(engine.positions()[i], start[i], 1e-4f) << bp::enumName(b) << " value " << i;
  }
}

TEST(Periodic, AnyParticleLeavesNeverReleasesAnElementOnTheSeam)
{
  const bp::VectorField field =
    bptest::uniformFlow({ 1, 0.5f, 0 }, periodicGrid({ true, true, false }));
  bp::Parameters p = strips(bp::Boundary::ReleaseAgain);
  p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
  bp::Engine engine = started(p);
  for (int s = 0; s < 300; ++s)
    engine.step(field, s * 0.01, 0.01, bp::serialRunner());
  for (std::size_t e = 0; e < engine.elementCount(); ++e)
  {
    EXPECT_EQ(engine.generations()[e], 0u) << e;
    for (int a = 0; a < 2; ++a) // moved back across the seam, not drifting away
    {
      EXPECT_GE(centerOf(engine, e)[a], -1.0f) << e;
      EXPECT_LE(centerOf(engine, e)[a], 1.0f) << e;
    }
  }
  EXPECT_LT(bptest::worstSpringStrain(engine), 1e-4);
}

TEST(Periodic, WithoutPeriodicTheSameTraceReleasesAgainAndTheOtherSidesStayWalls)
{
  // The control: the same flow without Periodic releases the elements again.
  const bp::VectorField open =
    bptest::uniformFlow({ 1, 0, 0 }, periodicGrid({ false, false, false }));
  bp::Engine engine = started(strips(bp::Boundary::ReleaseAgain));
  for (int s = 0; s < 201; ++s)
    engine.step(open, s * 0.01, 0.01, bp::serialRunner());
  std::uint64_t released = 0;
  for (std::size_t e = 0; e < engine.elementCount(); ++e)
    released += engine.generations()[e];
  EXPECT_GT(released, 0u);
  // Periodic along x, Slip walls along y: the flow's y part lays the strips
  // on the upper y wall while they keep crossing the x seam.
  const bp::VectorField mixed =
    bptest::uniformFlow({ 1, 0.5f, 0 }, periodicGrid({ true, false, false }));
  bp::Engine slip = started(strips(bp::Boundary::Slip));
  for (int s = 0; s < 400; ++s)
    slip.step(mixed, s * 0.01, 0.01, bp::serialRunner());
  for (std::size_t i = 1; i < slip.positions().size(); i += 3)
    EXPECT_LE(slip.positions()[i], 1.0f);
  for (std::size_t e = 0; e < slip.elementCount(); ++e)
  {
    EXPECT_EQ(slip.generations()[e], 0u);
    EXPECT_GE(centerOf(slip, e)[0], -1.0f);
    EXPECT_LE(centerOf(slip, e)[0], 1.0f);
  }
}

TEST(Periodic, TheSeamMismatchTellsACopiedLastPlaneFromAShortOne)
{
  // sineFlow's last x plane repeats its first; its y component, 0.5 y, is
  // the same on the first and last y planes only where y = 0, so along y
  // the planes differ by 1 (y = -1 against y = 1) of a top speed near 1.12.
  const bp::GridGeometry g = bptest::grid(9);
  const bp::VectorField field = sineFlow(g);
  const std::vector<float>& v = *field.firstSlice().velocity;
  EXPECT_EQ(bp::periodicSeamMismatch(g, v, 0), 0.0);
  EXPECT_NEAR(bp::periodicSeamMismatch(g, v, 1), 1.0 / std::sqrt(1.0 + 0.25), 1e-6);
  // Its two parts, which a distributed run takes the largest of over its
  // pieces: the difference itself and the largest speed.
  EXPECT_NEAR(bp::periodicSeamDifference(g, v, 1), 1.0, 1e-6);
  EXPECT_EQ(bp::periodicSeamDifference(g, v, 0), 0.0);
  EXPECT_NEAR(bp::largestFiniteSpeed(v), std::sqrt(1.0 + 0.25), 1e-6);
  std::vector<float> withInf = v;
  withInf[0] = INFINITY;
  EXPECT_NEAR(bp::largestFiniteSpeed(withInf), std::sqrt(1.0 + 0.25), 1e-6);
  // A sine sampled at 0, h, ..., L - h (its last plane one spacing short of
  // the period) differs at the seam by about the step to the next plane.
  std::vector<float> shortOne;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        shortOne.insert(shortOne.end(), { float(std::sin(2.0 * M_PI * i / 9.0)), 0.0f, 0.0f });
  EXPECT_NEAR(bp::periodicSeamMismatch(g, shortOne, 0),
    std::sin(2.0 * M_PI * 8 / 9.0) * -1.0 / std::sin(2.0 * M_PI * 2 / 9.0), 1e-5);
  // At rest, or along an axis of one point: nothing to say.
  EXPECT_EQ(bp::periodicSeamMismatch(g, std::vector<float>(3 * g.pointCount(), 0.0f), 0), 0.0);
  bp::GridGeometry flat = g;
  flat.dims[2] = 1;
  EXPECT_EQ(
    bp::periodicSeamMismatch(flat, std::vector<float>(3 * flat.pointCount(), 1.0f), 2), 0.0);
}

TEST(Periodic, ATrailBreaksWhereItsElementMovesAcrossTheSeam)
{
  // x and y periodic (period 2) in the flow (1, 0.5, 0); a trail of 6 poses
  // every 4 steps. A pose belongs to the element's shown trail exactly when
  // it was recorded after the element's last move across a seam: before it,
  // Engine::trailAcrossSeam (its first particle over half a period away).
  const bp::VectorField field =
    bptest::uniformFlow({ 1, 0.5f, 0 }, periodicGrid({ true, true, false }));
  bp::Parameters p = strips(bp::Boundary::ReleaseAgain);
  p.trailLength = 6;
  p.trailInterval = 0.04;
  bp::Engine engine = started(p);
  const std::size_t E = engine.elementCount(), n = engine.particlesPerElement();
  std::vector<double> lastMove(E, -INFINITY); // the end of the step that moved it by a period
  int moves = 0, shown = 0, left = 0, wrong = 0;
  float farthest = 0.0f; // a shown pose's centre from its element's, along x or y
  for (int s = 0; s < 300; ++s)
  {
    std::vector<std::array<float, 3>> before(E);
    for (std::size_t e = 0; e < E; ++e)
      before[e] = centerOf(engine, e);
    engine.step(field, s * 0.01, 0.01, bp::serialRunner());
    for (std::size_t e = 0; e < E; ++e)
    {
      const std::array<float, 3> c = centerOf(engine, e);
      if (std::abs(c[0] - before[e][0]) > 1.0f || std::abs(c[1] - before[e][1]) > 1.0f)
      {
        lastMove[e] = (s + 1) * 0.01;
        ++moves;
      }
    }
    for (int k = 0; k < p.trailLength; ++k)
    {
      const std::size_t slot = std::size_t(engine.trailSlot(k));
      const double recorded = engine.trailTimes()[slot];
      for (std::size_t e = 0; std::isfinite(recorded) && e < E; ++e)
      {
        const bool across = engine.trailAcrossSeam(slot, e, field);
        wrong += across != (recorded < lastMove[e] - 1e-9);
        if (across)
        {
          ++left;
          continue;
        }
        ++shown;
        std::array<float, 3> pose = { 0, 0, 0 };
        for (std::size_t i = 0; i < n; ++i)
          for (int a = 0; a < 3; ++a)
            pose[a] += engine.trailPositions()[3 * (slot * E * n + e * n + i) + a] / float(n);
        const std::array<float, 3> c = centerOf(engine, e);
        farthest = std::max({ farthest, std::abs(pose[0] - c[0]), std::abs(pose[1] - c[1]) });
      }
    }
  }
  EXPECT_EQ(wrong, 0) << "poses shown or left out against the last move across a seam";
  EXPECT_GT(moves, 8);       // every strip crossed a seam
  EXPECT_GT(left, 100);      // poses left out after the crossings
  EXPECT_GT(shown, 5000);    // and the rest shown, on the element's side
  EXPECT_LT(farthest, 0.3f); // at most the trail's span, 0.24 at speed 1.12
  for (std::size_t e = 0; e < E; ++e)
    EXPECT_EQ(engine.generations()[e], 0u);
  // Without Periodic no pose is ever across a seam, however far it lies
  // (the same trace releases elements again at the sides).
  const bp::VectorField open =
    bptest::uniformFlow({ 1, 0.5f, 0 }, periodicGrid({ false, false, false }));
  bp::Engine plain = started(p);
  int across = 0;
  for (int s = 0; s < 300; ++s)
  {
    plain.step(open, s * 0.01, 0.01, bp::serialRunner());
    for (int k = 0; k < p.trailLength; ++k)
      for (std::size_t e = 0; e < E; ++e)
        across += plain.trailAcrossSeam(std::size_t(plain.trailSlot(k)), e, open);
  }
  EXPECT_EQ(across, 0);
}

TEST(Periodic, APoseIsAcrossTheSeamOverHalfAPeriodAway)
{
  // Domain::acrossPeriodicSeam on [-1, 1] along x (period 2) and y (period
  // 3 on [0, 3]), z not periodic: strictly over half a period, in float.
  bp::Domain box;
  box.lower = { -1, 0, -1 };
  box.upper = { 1, 3, 1 };
  box.degenerate = { false, false, false };
  box.periodic = { true, true, false };
  EXPECT_EQ(box.halfPeriods(), (std::array<float, 3>{ 1.0f, 1.5f, 0.0f }));
  const float now[3] = { 0.5f, 1.0f, 0.0f };
  const float same[3] = { -0.5f, 2.5f, 0.9f }, x[3] = { -0.51f, 1.0f, 0.0f },
              y[3] = { 0.5f, 2.6f, 0.0f }, z[3] = { 0.5f, 1.0f, 100.0f },
              nan[3] = { NAN, NAN, NAN };
  EXPECT_FALSE(box.acrossPeriodicSeam(same, now)); // exactly half a period: shown
  EXPECT_TRUE(box.acrossPeriodicSeam(x, now));
  EXPECT_TRUE(box.acrossPeriodicSeam(y, now));
  EXPECT_FALSE(box.acrossPeriodicSeam(z, now)); // z has sides, no seam
  EXPECT_FALSE(box.acrossPeriodicSeam(nan, now));
  box.degenerate[0] = true; // a plane is never periodic
  EXPECT_FALSE(box.acrossPeriodicSeam(x, now));
  box.periodic = { false, false, false };
  EXPECT_EQ(box.halfPeriods(), (std::array<float, 3>{ 0.0f, 0.0f, 0.0f }));
  EXPECT_FALSE(box.acrossPeriodicSeam(y, now));
}
