// SPDX-License-Identifier: BSD-3-Clause
// Parameter resolution (Core/TraceSettings.h): automatic step, element size,
// emitter and lifetimes, and the messages for settings that cannot work.
#include "TraceSettings.h"

#include <gtest/gtest.h>

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

TEST(TraceSettings, AutomaticLifetimesSpanHalfToAllOfTheAnimation)
{
  bp::Resolution r = bp::resolveSettings(bp::TraceSettings(), box());
  EXPECT_FLOAT_EQ(r.parameters.lifetimeMin, 3.0f);
  EXPECT_FLOAT_EQ(r.parameters.lifetimeMax, 6.0f);
  bp::FieldFacts f = box();
  f.timeSpan = 0.0;
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
