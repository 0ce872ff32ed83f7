// SPDX-License-Identifier: BSD-3-Clause
// Parameter resolution (Core/Plan/TraceSettings.h): automatic step, element size,
// emitter and lifetimes, and the messages for settings that cannot work.
#include "TraceSettings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
/// A 2 x 4 x 8 box of cells of length 0.5 (mean), 1 unit/s, at world (10, 20, 30).
bp::FieldFacts box()
{
  bp::FieldFacts f;
  f.bounds = { 0, 2, 0, 4, 0, 8 };
  f.offset = { 10, 20, 30 };
  f.dims = { 5, 9, 17 };
  f.cellLength = 0.5;
  f.maxSpeed = 2.0;
  f.timeSpan = 6.0;
  return f;
}
} // namespace

TEST(TraceSettings, StepInCellLengthsMovesTheFastestParticleThatFar)
{
  bp::TraceSettings s;
  s.stepSize = 0.5;
  const bp::Resolution r = bp::resolveSettings(s, box());
  ASSERT_EQ(r.error, "");
  EXPECT_DOUBLE_EQ(r.dt, 0.5 * 0.5 / 2.0);
  s.stepInCellLengths = false;
  EXPECT_DOUBLE_EQ(bp::resolveSettings(s, box()).dt, 0.5);
}

TEST(TraceSettings, AResponseTimeFarBelowTheStepIsNotedAsNearlyMassless)
{
  bp::TraceSettings s;
  s.stepSize = 0.5;
  s.stepInCellLengths = false;
  s.engine.inertia = bp::Inertia::MaxeyRiley;
  s.engine.responseTime = 1e-5f;
  auto noted = [](const bp::Resolution& r)
  {
    return std::any_of(r.warnings.begin(), r.warnings.end(),
      [](const std::string& w) { return w.find("close to massless") != std::string::npos; });
  };
  EXPECT_TRUE(noted(bp::resolveSettings(s, box())));
  s.engine.responseTime = 0.1f;
  EXPECT_FALSE(noted(bp::resolveSettings(s, box())));
  s.engine.responseTime = 1e-5f;
  s.engine.inertia = bp::Inertia::None;
  EXPECT_FALSE(noted(bp::resolveSettings(s, box())));
}

TEST(TraceSettings, GravityFarOutOfTheDatasUnitsIsSaid)
{
  // carotid.vti: 75 x 48 x 44 cells of 1, a top speed of 22.7; heavy
  // particles of Response Time 0.1 (Density Ratio 1000) live up to ~2.2.
  bp::FieldFacts carotid;
  carotid.bounds = { 0, 75, 0, 48, 0, 44 };
  carotid.dims = { 76, 49, 45 };
  carotid.cellLength = 1.0;
  carotid.maxSpeed = 22.7;
  bp::TraceSettings s;
  s.engine.inertia = bp::Inertia::MaxeyRiley;
  s.engine.responseTime = 0.1f;
  s.engine.densityRatio = 1000.0f;
  auto said = [&]()
  {
    const bp::Resolution r = bp::resolveSettings(s, carotid);
    EXPECT_EQ(r.error, "");
    for (const std::string& w : r.warnings)
      if (w.find("Gravity may not be in the data's units") != std::string::npos)
        return w;
    return std::string();
  };
  // 9.81 m/s^2 as 1.27e5 km/h^2 settles particles ~540 fields in the time the
  // flow takes to cross the field (automatic lifetimes follow the settling).
  s.engine.gravity = { 0, 0, -127137.6f };
  const std::string wrong = said();
  EXPECT_NE(wrong.find("Gravity (0, 0, -127138)"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("times the field's longest side (75"), std::string::npos) << wrong;
  s.engine.gravity = { 0, 0, -1e10f };
  EXPECT_NE(said(), "");
  // Sensible gravity, none, no inertia, or a neutrally buoyant particle: nothing said.
  s.engine.gravity = { 0, 0, -9.81f };
  EXPECT_EQ(said(), "");
  s.engine.gravity = { 0, 0, 0 };
  EXPECT_EQ(said(), "");
  s.engine.gravity = { 0, 0, -1e10f };
  s.engine.densityRatio = 1.0f;
  EXPECT_EQ(said(), "");
  s.engine.densityRatio = 1000.0f;
  s.engine.inertia = bp::Inertia::None;
  EXPECT_EQ(said(), "");
  // Bubbles rise: (1 - beta) is negative, its size counts.
  s.engine.inertia = bp::Inertia::MaxeyRiley;
  s.engine.densityRatio = 0.001f;
  s.engine.gravity = { 0, 0, -127137.6f };
  EXPECT_NE(said(), "");
  // Not finite (beyond float): the engine's validation refuses it, alone.
  s.engine.gravity = { 0, std::numeric_limits<float>::infinity(), 0 };
  EXPECT_EQ(said(), "");
}

TEST(TraceSettings, ZeroFieldWarnsAndStepsAsAtUnitSpeed)
{
  bp::FieldFacts f = box();
  f.maxSpeed = 0.0;
  const bp::Resolution r = bp::resolveSettings(bp::TraceSettings(), f);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("zero everywhere"), std::string::npos);
  EXPECT_DOUBLE_EQ(r.dt, 0.5 * 0.5);
}

TEST(TraceSettings, HeavyParticlesInStillOrNoisyFluidStepByTheirSettling)
{
  // Issue 53: on a field of 1e-12 noise the step followed the noise (3e10)
  // and threw every particle far out of the unit box, with a warning that
  // blamed Gravity's units; on a zero field the tracer said nothing would move.
  bp::FieldFacts f;
  f.bounds = { 0, 1, 0, 1, 0, 1 };
  f.dims = { 17, 17, 17 };
  f.cellLength = 1.0 / 16.0;
  f.timeSpan = 50.0;
  bp::TraceSettings s;
  s.engine.inertia = bp::Inertia::MaxeyRiley;
  s.engine.responseTime = 0.05f;
  s.engine.densityRatio = 1000.0f;
  s.engine.gravity = { 0, 0, -2 };
  const double terminal = bp::terminalSettlingSpeed(s.engine); // about 0.1
  for (const double noise : { 0.0, 1e-12, 1e-9 })
  {
    f.maxSpeed = noise;
    const bp::Resolution r = bp::resolveSettings(s, f);
    ASSERT_EQ(r.error, "") << noise;
    EXPECT_TRUE(r.warnings.empty()) << noise << ": " << r.warnings.front();
    // A settling particle moves at most StepSize cells a step (it falls
    // across the field in 1 / 0.1 = 10, two hundred times its response
    // time: at the terminal speed within 1e-80).
    EXPECT_NEAR(r.dt * terminal, s.stepSize * f.cellLength, 1e-9 * f.cellLength) << noise;
    EXPECT_NEAR(r.speed, terminal, 1e-9 * terminal);
    // Automatic lifetimes: the time it takes to fall across the field.
    EXPECT_NEAR(r.parameters.lifetimeMax, 1.0 / terminal, 1e-5 / terminal) << noise;
  }
  // A flow faster than the settling sets the step, as without gravity.
  f.maxSpeed = 2.0;
  EXPECT_DOUBLE_EQ(bp::resolveSettings(s, f).dt, 0.5 / 16.0 / 2.0);
  // Far above the trace's times the response time is free fall: the speed
  // after falling across the field, sqrt(2 (1 - beta) |g| L).
  f.maxSpeed = 1e-12;
  s.engine.responseTime = 1e30f;
  const double fall = std::sqrt(2.0 * (1.0 - bp::addedMassFactor(1000.0f)) * 2.0 * 1.0);
  EXPECT_NEAR(bp::resolveSettings(s, f).dt, 0.5 / 16.0 / fall, 1e-6 * 0.5 / 16.0 / fall);
  // Massless, neutrally buoyant, or without gravity: a zero field is still, and said to be.
  s.engine.responseTime = 0.05f;
  f.maxSpeed = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    bp::TraceSettings still = s;
    if (k == 0)
    {
      still.engine.inertia = bp::Inertia::None;
    }
    else if (k == 1)
    {
      still.engine.densityRatio = 1.0f;
    }
    else
    {
      still.engine.gravity[2] = 0.0f;
    }
    const bp::Resolution r = bp::resolveSettings(still, f);
    ASSERT_EQ(r.warnings.size(), 1u) << k;
    EXPECT_NE(r.warnings[0].find("zero everywhere"), std::string::npos) << k;
    EXPECT_DOUBLE_EQ(r.dt, 0.5 / 16.0) << k;
  }
}

TEST(TraceSettings, AutomaticElementSizeIsTwoCellsOrADiagonalFortieth)
{
  const bp::Resolution r = bp::resolveSettings(bp::TraceSettings(), box());
  const double diagonal = std::sqrt(4.0 + 16.0 + 64.0);
  EXPECT_DOUBLE_EQ(r.elementSize, std::max(1.0, diagonal / 40.0));
  EXPECT_FLOAT_EQ(r.parameters.elementSize, float(r.elementSize));
  bp::TraceSettings s;
  s.elementSize = 0.3;
  EXPECT_DOUBLE_EQ(bp::resolveSettings(s, box()).elementSize, 0.3);
}

TEST(TraceSettings, EmitterIsTheWholeFieldOrTheUsersBoxInLocalCoordinates)
{
  bp::TraceSettings s;
  bp::Resolution r = bp::resolveSettings(s, box());
  EXPECT_FLOAT_EQ(r.parameters.emitterMin[1], 0.0f);
  EXPECT_FLOAT_EQ(r.parameters.emitterMax[2], 8.0f);
  s.emitterCenter = { 11, 21, 31 };
  s.emitterSize = { 1, -1, 0.5 };
  r = bp::resolveSettings(s, box());
  EXPECT_FLOAT_EQ(r.parameters.emitterMin[0], 0.5f);
  EXPECT_FLOAT_EQ(r.parameters.emitterMax[0], 1.5f);
  EXPECT_FLOAT_EQ(r.parameters.emitterMax[1], 4.0f);
  EXPECT_FLOAT_EQ(r.parameters.emitterMin[2], 0.75f);
}

TEST(TraceSettings, AfterAChangeOfGridReleasesLandInTheNewGrid)
{
  // In situ the grid shrank and moved to [0.5, 1.5] x [1, 3] x [0, 8] (the
  // trace's frame stays): a box that spans the field spans the new one.
  bp::FieldFacts moved = box();
  moved.bounds = { 0.5, 1.5, 1, 3, 0, 8 };
  bp::TraceSettings s;
  bp::EmitterBox e = bp::emitterInChangedField(s, moved, 0.1);
  EXPECT_FLOAT_EQ(e.min[0], 0.5f);
  EXPECT_FLOAT_EQ(e.max[0], 1.5f);
  EXPECT_FLOAT_EQ(e.min[1], 1.0f);
  EXPECT_FLOAT_EQ(e.max[1], 3.0f);
  EXPECT_EQ(e.warning, "");
  // The user's box (world 10.2 to 11.8 along X, 21.5 to 22.5 along Y) is cut
  // to the new grid; inside it, it stays as resolved at the start.
  s.emitterCenter = { 11, 22, 34 };
  s.emitterSize = { 1.6, 1, 2 };
  e = bp::emitterInChangedField(s, moved, 0.1);
  EXPECT_FLOAT_EQ(e.min[0], 0.5f);
  EXPECT_FLOAT_EQ(e.max[0], 1.5f);
  const bp::Resolution start = bp::resolveSettings(s, box());
  EXPECT_EQ(e.min[1], start.parameters.emitterMin[1]);
  EXPECT_EQ(e.max[1], start.parameters.emitterMax[1]);
  EXPECT_EQ(e.min[2], start.parameters.emitterMin[2]);
  EXPECT_EQ(e.warning, "");
  // A box that misses the new grid along Y: releases span it there, said.
  s.emitterCenter = { 11, 20.2, 34 };
  s.emitterSize = { 1, 0.2, 2 };
  e = bp::emitterInChangedField(s, moved, 0.1);
  EXPECT_FLOAT_EQ(e.min[1], 1.0f);
  EXPECT_FLOAT_EQ(e.max[1], 3.0f);
  EXPECT_NE(e.warning.find("outside the new grid along Y"), std::string::npos) << e.warning;
  // Any Particle Leaves keeps an element radius inside the new grid too.
  s = bp::TraceSettings();
  s.engine.resetWhen = bp::ResetWhen::AnyParticleLeaves;
  e = bp::emitterInChangedField(s, moved, 0.4);
  EXPECT_FLOAT_EQ(e.min[0], 0.7f);
  EXPECT_FLOAT_EQ(e.max[1], 2.8f);
  // A flat axis keeps its plane.
  moved.dims[2] = 1;
  moved.bounds[4] = moved.bounds[5] = 0.0;
  s = bp::TraceSettings();
  s.emitterCenter = { 11, 22, 30 };
  s.emitterSize = { -1, -1, 0 };
  e = bp::emitterInChangedField(s, moved, 0.1);
  EXPECT_FLOAT_EQ(e.min[2], 0.0f);
  EXPECT_FLOAT_EQ(e.max[2], 0.0f);
  EXPECT_EQ(e.warning, "");
}

TEST(TraceSettings, APointEmitterWarnsWhereEveryElementIsReleased)
{
  bp::TraceSettings s;
  s.emitterCenter = { 11, 21, 31 };
  s.emitterSize = { 0, 0, 0 };
  const bp::Resolution r = bp::resolveSettings(s, box());
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("released at (11, 21, 31)"), std::string::npos);
  s.emitterSize = { 0, 0, 1 }; // a line emitter is a choice, not a placeholder
  EXPECT_TRUE(bp::resolveSettings(s, box()).warnings.empty());
}

TEST(TraceSettings, ASeedSourceLeavesTheEmitterAndReleaseSpeedUnchecked)
{
  bp::TraceSettings s;
  s.emitterCenter = { 1e6, 0, 0 }; // a stale box, far outside the field
  s.emitterSize = { 0, 0, 0 };
  s.minimumReleaseSpeed = 5.0;
  EXPECT_NE(bp::resolveSettings(s, box()).error, "");
  s.seeded = true;
  const bp::Resolution r = bp::resolveSettings(s, box());
  EXPECT_EQ(r.error, "");
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.parameters.releaseMinSpeed, 0.0f);
}

TEST(TraceSettings, TrailSpacingIsCheckedOnlyWithTrailsAndUpToTheLimit)
{
  bp::TraceSettings s;
  s.trailSpacing = 0; // trails off: not used, so not checked
  EXPECT_EQ(bp::resolveSettings(s, box()).error, "");
  s.trailLength = 8;
  for (int bad : { 0, -3, bp::MaxTrailSpacing + 1, 10000000 })
  {
    s.trailSpacing = bad;
    EXPECT_NE(bp::resolveSettings(s, box()).error.find("TrailSpacing"), std::string::npos) << bad;
  }
  s.trailSpacing = bp::MaxTrailSpacing;
  EXPECT_EQ(bp::resolveSettings(s, box()).error, "");
}

TEST(TraceSettings, AnyParticleLeavesKeepsElementsWholeInside)
{
  bp::TraceSettings s;
  s.engine.resetWhen = bp::ResetWhen::AnyParticleLeaves;
  s.elementSize = 1.0;
  bp::Resolution r = bp::resolveSettings(s, box());
  EXPECT_FLOAT_EQ(r.parameters.emitterMin[0], 0.5f);
  EXPECT_FLOAT_EQ(r.parameters.emitterMax[0], 1.5f);
  EXPECT_TRUE(r.warnings.empty());
  s.elementSize = 3.0; // wider than X
  r = bp::resolveSettings(s, box());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("do not fit in the field along X"), std::string::npos);
}

TEST(TraceSettings, AutomaticLifetimesSpanHalfToAllOfACrossingWithinTheAnimation)
{
  // The fastest flow (2) crosses the longest side (8) in 4, within the span 6.
  bp::Resolution r = bp::resolveSettings(bp::TraceSettings(), box());
  EXPECT_FLOAT_EQ(r.parameters.lifetimeMin, 2.0f);
  EXPECT_FLOAT_EQ(r.parameters.lifetimeMax, 4.0f);
  bp::FieldFacts f = box();
  f.timeSpan = 3.0; // a shorter animation bounds it
  EXPECT_FLOAT_EQ(bp::resolveSettings(bp::TraceSettings(), f).parameters.lifetimeMax, 3.0f);
  f.timeSpan = 0.0;
  f.maxSpeed = 0.0; // a still field: 100 steps (at unit speed)
  r = bp::resolveSettings(bp::TraceSettings(), f);
  EXPECT_FLOAT_EQ(r.parameters.lifetimeMax, float(100.0 * r.dt));
  bp::TraceSettings s;
  s.lifetimeRange = { 1, 2 };
  EXPECT_FLOAT_EQ(bp::resolveSettings(s, box()).parameters.lifetimeMin, 1.0f);
}

TEST(TraceSettings, SettingsThatCannotWorkSayWhatToFix)
{
  bp::TraceSettings s;
  s.stepSize = 0.0;
  EXPECT_NE(
    bp::resolveSettings(s, box()).error.find("StepSize must be positive"), std::string::npos);
  s = bp::TraceSettings();
  s.elementSize = -1.0;
  EXPECT_NE(bp::resolveSettings(s, box()).error.find("ElementSize"), std::string::npos);
  s = bp::TraceSettings();
  s.numberOfElements = 0;
  EXPECT_NE(bp::resolveSettings(s, box()).error.find("NumberOfElements"), std::string::npos);
  s = bp::TraceSettings();
  s.rotationDegrees[1] = std::numeric_limits<double>::infinity();
  EXPECT_NE(bp::resolveSettings(s, box()).error.find("ElementRotation"), std::string::npos);
}

TEST(TraceSettings, DirectSettingsPassThrough)
{
  bp::TraceSettings s;
  s.engine.integrator = bp::Integrator::RK4;
  s.engine.restoration = bp::Restoration::ShapeMatching;
  s.engine.iterations = 3;
  s.engine.seed = 42;
  s.engine.linking = bp::Linking::Sheet;
  const bp::Parameters p = bp::resolveSettings(s, box()).parameters;
  EXPECT_EQ(p.integrator, bp::Integrator::RK4);
  EXPECT_EQ(p.restoration, bp::Restoration::ShapeMatching);
  EXPECT_EQ(p.iterations, 3);
  EXPECT_EQ(p.seed, 42u);
  EXPECT_EQ(p.linking, bp::Linking::Sheet);
  EXPECT_EQ(p.numberOfElements, 1000u);
}

TEST(TraceSettings, MinimumReleaseSpeedIsAFractionOfTheTopSpeed)
{
  bp::TraceSettings s;
  EXPECT_DOUBLE_EQ(s.minimumReleaseSpeed, 0.01); // on by default
  s.minimumReleaseSpeed = 0.25;
  const bp::Resolution r = bp::resolveSettings(s, box());
  ASSERT_EQ(r.error, "");
  EXPECT_FLOAT_EQ(r.parameters.releaseMinSpeed, 0.5f); // a quarter of 2 units/s
  s.minimumReleaseSpeed = 0.0;
  EXPECT_EQ(bp::resolveSettings(s, box()).parameters.releaseMinSpeed, 0.0f);
  for (double bad : { -0.1, 1.5, std::numeric_limits<double>::quiet_NaN() })
  {
    s.minimumReleaseSpeed = bad;
    EXPECT_NE(bp::resolveSettings(s, box()).error.find("MinimumReleaseSpeed"), std::string::npos);
  }
}

namespace
{
/// A field 40 units long with cells of 0.5 and a top speed of 2.
bp::TimeScale scaleOfBox()
{
  bp::TimeScale s;
  s.maxSpeed = 2.0;
  s.extent = 40.0;
  s.cellLength = 0.5;
  return s;
}
} // namespace

TEST(TimeLine, AutomaticDurationCrossesTheFieldFiveTimesWithinTenStepsAFrame)
{
  // Five crossings take 5 * 40 / 2 = 100; a step of half a cell at top speed
  // is 0.125, so 100 frames of 10 steps span 125: the crossings decide.
  const bp::TimeLine line = bp::resolveTimeLine(0.0, 0, 101, 0.5, true, {}, scaleOfBox());
  EXPECT_DOUBLE_EQ(line.duration, 100.0);
  EXPECT_TRUE(line.warnings.empty());
  // Ten frames cannot hold 100 in steps of 10 each: 10 * 9 * 0.125.
  EXPECT_DOUBLE_EQ(bp::resolveTimeLine(0.0, 0, 10, 0.5, true, {}, scaleOfBox()).duration, 11.25);
  // The user's Duration stays; an unprobed field falls back.
  EXPECT_DOUBLE_EQ(bp::resolveTimeLine(7.0, 0, 101, 0.5, true, {}, scaleOfBox()).duration, 7.0);
  EXPECT_DOUBLE_EQ(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, {}, bp::TimeScale()).duration,
    bp::FallbackDuration);
}

TEST(TimeLine, HeavyParticlesInNoisyFluidGetATimeLineOfTheirSettling)
{
  // A unit box of 16 cells with 1e-12 of noise: the flow alone would make a
  // step of 3e10 and a Duration of 3e13. Heavy particles falling across it
  // at 0.1 make five crossings, 50, within 100 frames of 10 steps (312.5).
  bp::TimeScale scale;
  scale.maxSpeed = 1e-12;
  scale.extent = 1.0;
  scale.cellLength = 1.0 / 16.0;
  scale.gravitySpeed = 0.1;
  bp::TimeLine line = bp::resolveTimeLine(0.0, 0, 101, 0.5, true, {}, scale);
  EXPECT_NEAR(line.duration, 50.0, 1e-9);
  EXPECT_TRUE(line.warnings.empty()) << line.warnings.front();
  // A still field (nothing probed moving) is timed by the settling alone.
  scale.maxSpeed = 0.0;
  EXPECT_NEAR(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, {}, scale).duration, 50.0, 1e-9);
  // An unsteady input: frames of 10 steps of the settling's step (0.3125).
  line = bp::resolveTimeLine(0.0, 0, 2, 0.5, true, { 0.0, 1000.0 }, scale);
  EXPECT_EQ(line.framesPerInterval, 320);
  EXPECT_TRUE(line.warnings.empty()) << line.warnings.front();
}

TEST(TimeLine, AutomaticFramesKeepEachWithinTenSteps)
{
  // 201 input steps 6 apart (enough frames already), steps of 0.125: 48
  // steps, so 5 frames of <= 10 steps.
  std::vector<double> times;
  for (int k = 0; k <= 200; ++k)
  {
    times.push_back(6.0 * k);
  }
  EXPECT_EQ(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, times, scaleOfBox()).framesPerInterval, 5);
  EXPECT_EQ(bp::resolveTimeLine(0.0, 3, 101, 0.5, true, times, scaleOfBox()).framesPerInterval, 3);
  // A slow field needs no frames between the input's.
  bp::TimeScale slow = scaleOfBox();
  slow.maxSpeed = 0.01;
  EXPECT_EQ(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, times, slow).framesPerInterval, 1);
  EXPECT_EQ(
    bp::resolveTimeLine(0.0, 0, 101, 0.5, true, times, bp::TimeScale()).framesPerInterval, 1);
}

TEST(TimeLine, AShortSeriesGetsEnoughFramesForSmoothPlay)
{
  // nek_eddy: 11 steps of a slow flow once gave 11 frames, a second of Play.
  std::vector<double> eleven;
  for (int k = 0; k <= 10; ++k)
  {
    eleven.push_back(0.05 * k);
  }
  bp::TimeScale slow = scaleOfBox();
  slow.maxSpeed = 0.01;
  const int frames = bp::resolveTimeLine(0.0, 0, 101, 0.5, true, eleven, slow).framesPerInterval;
  EXPECT_EQ(frames, 10);
  EXPECT_GE(10 * frames + 1, bp::MinAutomaticFrames);
  // Also when the field could not be probed; a set value stays.
  EXPECT_EQ(
    bp::resolveTimeLine(0.0, 0, 101, 0.5, true, eleven, bp::TimeScale()).framesPerInterval, 10);
  EXPECT_EQ(bp::resolveTimeLine(0.0, 1, 101, 0.5, true, eleven, slow).framesPerInterval, 1);
  // Two steps: 100 frames between them.
  EXPECT_EQ(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, { 0, 6 }, slow).framesPerInterval, 100);
}

TEST(TimeLine, WarnsWhenTheVelocitysScaleDoesNotFitTheGridsUnits)
{
  // A step of 50 time units at speed 2 crosses the 40-unit field in one step.
  const bp::TimeLine fast = bp::resolveTimeLine(10.0, 0, 101, 50.0, false, {}, scaleOfBox());
  ASSERT_EQ(fast.warnings.size(), 1u);
  EXPECT_NE(fast.warnings[0].find("less than one step"), std::string::npos);
  // Over a range of 0.1 the fastest element moves 0.2 < one cell of 0.5.
  const std::vector<double> times = { 0, 0.05, 0.1 };
  const bp::TimeLine still = bp::resolveTimeLine(0.0, 0, 101, 0.5, true, times, scaleOfBox());
  ASSERT_EQ(still.warnings.size(), 1u);
  EXPECT_NE(still.warnings[0].find("less than one cell"), std::string::npos);
  EXPECT_TRUE(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, {}, scaleOfBox()).warnings.empty());
}

TEST(TraceSettings, AFlatFieldTurnsElementsInItsPlaneOnly)
{
  for (int flat = 0; flat < 3; ++flat)
  {
    bp::FieldFacts f = box();
    f.dims[flat] = 1;
    f.bounds[2 * flat + 1] = f.bounds[2 * flat];
    const bp::Resolution r = bp::resolveSettings(bp::TraceSettings(), f);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.parameters.planeAxis, flat);
    // The frame takes the template's normal (z) onto the flat axis.
    for (int row = 0; row < 3; ++row)
      EXPECT_NEAR(r.parameters.frame[3 * row + 2], row == flat ? 1.0f : 0.0f, 1e-6f);
  }
  // A 3D field, or orientations the user fixed, turn freely / not at all.
  EXPECT_EQ(bp::resolveSettings(bp::TraceSettings(), box()).parameters.planeAxis, -1);
  bp::FieldFacts f = box();
  f.dims[2] = 1;
  bp::TraceSettings fixed;
  fixed.engine.orientation = bp::Orientation::Fixed;
  EXPECT_EQ(bp::resolveSettings(fixed, f).parameters.planeAxis, -1);
}

TEST(TraceSettings, AFlatFieldDropsGravityAcrossItsPlaneAndSaysSo)
{
  auto said = [](const bp::Resolution& r)
  {
    return std::count_if(r.warnings.begin(), r.warnings.end(),
      [](const std::string& w)
      { return w.find("Gravity crosses its plane") != std::string::npos; });
  };
  bp::TraceSettings heavy;
  heavy.engine.inertia = bp::Inertia::MaxeyRiley;
  heavy.engine.responseTime = 0.05f;
  heavy.engine.densityRatio = 1000.0f;
  heavy.engine.gravity = { 1.5f, -2.0f, -9.81f };
  for (int flat = 0; flat < 3; ++flat)
  {
    bp::FieldFacts f = box();
    f.dims[flat] = 1;
    f.bounds[2 * flat + 1] = f.bounds[2 * flat];
    const bp::Resolution r = bp::resolveSettings(heavy, f);
    ASSERT_EQ(r.error, "");
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(r.parameters.gravity[a], a == flat ? 0.0f : heavy.engine.gravity[a]);
    ASSERT_EQ(said(r), 1);
    const std::string w = *std::find_if(r.warnings.begin(), r.warnings.end(),
      [](const std::string& m) { return m.find("Gravity") != std::string::npos; });
    EXPECT_NE(w.find(std::string("along ") + "XYZ"[flat]), std::string::npos) << w;
    EXPECT_EQ(w.find("do not fall"), std::string::npos) << w;
  }
  // Gravity wholly across the plane leaves none: a massless-like trace, said, not an error.
  bp::FieldFacts plane = box();
  plane.dims[2] = 1;
  plane.bounds[5] = plane.bounds[4];
  bp::TraceSettings down = heavy;
  down.engine.gravity = { 0.0f, 0.0f, -9.81f };
  const bp::Resolution r = bp::resolveSettings(down, plane);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.parameters.gravity, (std::array<float, 3>{ 0.0f, 0.0f, 0.0f }));
  ASSERT_EQ(said(r), 1);
  EXPECT_NE(std::find_if(r.warnings.begin(), r.warnings.end(),
              [](const std::string& m)
              {
                return m.find("-9.81 along Z") != std::string::npos &&
                  m.find("do not fall") != std::string::npos;
              }),
    r.warnings.end());
  // Two flat axes (a line of points) drop both.
  bp::FieldFacts line = plane;
  line.dims[1] = 1;
  line.bounds[3] = line.bounds[2];
  EXPECT_EQ(bp::resolveSettings(heavy, line).parameters.gravity,
    (std::array<float, 3>{ 1.5f, 0.0f, 0.0f }));
  // A 3D field keeps it all; in the plane only, nothing is said.
  EXPECT_EQ(bp::resolveSettings(heavy, box()).parameters.gravity, heavy.engine.gravity);
  EXPECT_EQ(said(bp::resolveSettings(heavy, box())), 0);
  bp::TraceSettings inPlane = heavy;
  inPlane.engine.gravity = { 0.0f, -9.81f, 0.0f };
  EXPECT_EQ(said(bp::resolveSettings(inPlane, plane)), 0);
  // Where gravity does not act (massless: no inertia, or tau 0) it is
  // dropped as well but not said; a NaN is left for Engine::validate to name.
  bp::TraceSettings massless = down;
  massless.engine.inertia = bp::Inertia::None;
  EXPECT_EQ(bp::resolveSettings(massless, plane).parameters.gravity[2], 0.0f);
  EXPECT_EQ(said(bp::resolveSettings(massless, plane)), 0);
  massless = down;
  massless.engine.responseTime = 0.0f;
  EXPECT_EQ(said(bp::resolveSettings(massless, plane)), 0);
  bp::TraceSettings nan = down;
  nan.engine.gravity[2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isnan(bp::resolveSettings(nan, plane).parameters.gravity[2]));
}

TEST(TimeLine, ATypicalSpeedCrossingMuchOfTheFieldBetweenTimeStepsIsSaid)
{
  // gfs_wind10m's m/s on a 359-degree grid, time steps 6 hours apart: 11.3
  // units per hour cross 19% of the field between two of them.
  bp::TimeScale s;
  s.maxSpeed = 26.8;
  s.typicalSpeed = 11.3;
  s.extent = 359.0;
  s.cellLength = 1.0;
  const std::vector<double> times = { 0, 6, 12, 18, 24 };
  const bp::TimeLine wrong = bp::resolveTimeLine(0.0, 0, 0, 0.5, true, times, s);
  ASSERT_EQ(wrong.warnings.size(), 1u);
  EXPECT_NE(
    wrong.warnings[0].find("crosses 19% of the field (359 long), 68 cells"), std::string::npos)
    << wrong.warnings[0];
  EXPECT_NE(wrong.warnings[0].find("Calculator"), std::string::npos);
  // Its velocity_deg_per_hour (typical 0.75): 1.3%, nothing said; nor for a
  // steady field, which has no time steps to cross between.
  s.maxSpeed = 5.4;
  s.typicalSpeed = 0.75;
  EXPECT_TRUE(bp::resolveTimeLine(0.0, 0, 0, 0.5, true, times, s).warnings.empty());
  s.typicalSpeed = 1e6;
  EXPECT_TRUE(bp::resolveTimeLine(0.0, 0, 101, 0.5, true, {}, s).warnings.empty());
}

TEST(TimeLine, AFlowThatCrossesMuchOfACoarseFieldInFewCellsIsNotSaidToBeOutOfUnits)
{
  // Analytic Flow's Double Gyre with its defaults: 32 points over [-1, 1],
  // 21 time steps 0.5 apart. Its typical speed 0.54 crosses 13% of the field
  // between two steps, but only 4 cells: the data is written often enough
  // for its own flow (a period of 10), so nothing is said.
  bp::TimeScale gyre;
  gyre.maxSpeed = 0.94;
  gyre.typicalSpeed = 0.54;
  gyre.extent = 2.0;
  gyre.cellLength = 2.0 / 31.0;
  std::vector<double> times;
  for (int k = 0; k < 21; ++k)
    times.push_back(0.5 * k);
  EXPECT_TRUE(bp::resolveTimeLine(0.0, 0, 0, 0.5, true, times, gyre).warnings.empty());
  // The same velocity in the wrong units (ten times too fast) is said, naming the cells.
  gyre.maxSpeed *= 10.0;
  gyre.typicalSpeed *= 10.0;
  const bp::TimeLine wrong = bp::resolveTimeLine(0.0, 0, 0, 0.5, true, times, gyre);
  ASSERT_EQ(wrong.warnings.size(), 1u);
  EXPECT_NE(wrong.warnings[0].find("135% of the field (2 long), 42 cells"), std::string::npos)
    << wrong.warnings[0];
}
