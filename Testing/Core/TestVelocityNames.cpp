// SPDX-License-Identifier: BSD-3-Clause
// Which array a field's velocity is, by its name (Core/Field/VelocityNames.h).
#include "VelocityNames.h"

#include <gtest/gtest.h>

TEST(VelocityNames, AVelocitysOwnNamesRankFirst)
{
  for (const char* name :
    { "velocity", "Velocity", "VEL", "vel", "U", "u", "uvw", "Wind", "flow", "V", "velocities" })
  {
    EXPECT_EQ(bp::velocityNameRank(name), 0) << name;
  }
  for (const char* name : { "velocity_deg_per_hour", "WindVelocity", "U_mean", "mean-velocity",
         "flow velocity", "Velocity3D" })
  {
    EXPECT_EQ(bp::velocityNameRank(name), 1) << name;
  }
}

TEST(VelocityNames, OtherQuantitiesAreNotVelocities)
{
  for (const char* name : { "ACCL", "DISPL", "acceleration", "Normals", "vorticity", "grad(U)",
         "gradU", "VelocityGradient", "coords", "B", "displacement", "Force", "temperature", "" })
  {
    EXPECT_EQ(bp::velocityNameRank(name), -1) << name;
  }
}

TEST(VelocityNames, TheCansVelocityIsPickedOverItsAcceleration)
{
  // Exodus's can: ACCL comes first, and was traced.
  EXPECT_EQ(bp::pickVelocityName({ "ACCL", "DISPL", "VEL" }), 2);
  // An exact name beats one that only holds it; the first of equals wins.
  EXPECT_EQ(bp::pickVelocityName({ "velocity_deg_per_hour", "velocity" }), 1);
  EXPECT_EQ(bp::pickVelocityName({ "velocity", "velocity_deg_per_hour" }), 0);
  EXPECT_EQ(bp::pickVelocityName({ "U", "vel" }), 0);
  EXPECT_EQ(bp::pickVelocityName({ "ACCL", "DISPL" }), -1);
  EXPECT_EQ(bp::pickVelocityName({}), -1);
}

TEST(VelocityNames, TheDefaultByNameIsTheActiveVectorsThenAVelocityThenTheFirst)
{
  EXPECT_EQ(bp::pickDefaultVectors({ "ACCL", "DISPL", "VEL" }, 0), 0);
  EXPECT_EQ(bp::pickDefaultVectors({ "ACCL", "DISPL", "VEL" }, -1), 2);
  EXPECT_EQ(bp::pickDefaultVectors({ "first", "second" }, -1), 0);
  EXPECT_EQ(bp::pickDefaultVectors({ "first", "second" }, 5), 0);
  EXPECT_EQ(bp::pickDefaultVectors({}, 0), -1);
}

TEST(VelocityNames, AnArrayWhoseUnitsFitIsPreferredToOneWhoseUnitsDoNot)
{
  // gfs_wind10m: its active vectors `velocity` are m/s on a degree grid with
  // time in hours; `velocity_deg_per_hour` fits.
  const std::vector<bp::VectorsCandidate> gfs = { { "velocity", false },
    { "velocity_deg_per_hour", true } };
  EXPECT_EQ(bp::preferFittingUnits(gfs, 0), 1);
  // Where the chosen array fits, it stays, whatever the others.
  EXPECT_EQ(bp::preferFittingUnits({ { "velocity", true }, { "wind", true } }, 0), 0);
  EXPECT_EQ(bp::preferFittingUnits({ { "velocity", true }, { "wind", false } }, 0), 0);
  // Where none fits, the chosen one stays (its warning says what to do).
  EXPECT_EQ(bp::preferFittingUnits({ { "velocity", false }, { "wind_kmh", false } }, 0), 0);
  // Of several that fit, the one named most like a velocity, first among equals.
  EXPECT_EQ(bp::preferFittingUnits(
              { { "velocity", false }, { "data", true }, { "wind_deg", true }, { "U", true } }, 0),
    3);
  EXPECT_EQ(
    bp::preferFittingUnits({ { "velocity", false }, { "U_a", true }, { "U_b", true } }, 0), 1);
  EXPECT_EQ(bp::preferFittingUnits({ { "velocity", false }, { "data", true } }, 0), 1);
  // Never another quantity, however well its scale fits.
  EXPECT_EQ(bp::preferFittingUnits(
              { { "VEL", false }, { "ACCL", true }, { "DISPL", true }, { "vorticity", true } }, 0),
    0);
  // No candidate to choose.
  EXPECT_EQ(bp::preferFittingUnits({}, 0), 0);
  EXPECT_EQ(bp::preferFittingUnits({ { "velocity", false } }, -1), -1);
}

TEST(VelocityNames, TheReasonQuotesTheFindingsOfTheUnitsCheck)
{
  const std::string warning =
    "At the field's typical speed (0.43: 90% of its moving points are slower) an element crosses "
    "19% of the field (359 long), 68 cells of 1, between two input time steps (6 apart), so the "
    "trace crumples: the velocity's units may not match the grid's or the time's (e.g. m/s on a "
    "grid in degrees, with time in hours). Pick Vectors in the grid's units per time unit.";
  EXPECT_EQ(bp::fittingUnitsReason("velocity", true, warning),
    "its units fit the grid and the time steps, while those of 'velocity', the input's active "
    "vectors, do not: at the field's typical speed (0.43: 90% of its moving points are slower) an "
    "element crosses 19% of the field (359 long), 68 cells of 1, between two input time steps (6 "
    "apart)");
  EXPECT_EQ(bp::fittingUnitsReason("wind", false,
              "At the field's top speed (9) an element crosses the whole field (1 long) in less "
              "than one step (2): the velocity's units may not match the grid's."),
    "its units fit the grid and the time steps, while those of 'wind' do not: at the field's top "
    "speed (9) an element crosses the whole field (1 long) in less than one step (2)");
  EXPECT_EQ(bp::fittingUnitsReason("wind", false,
              "Even at 1000 frames per input time step a frame takes up to 40 steps; check the "
              "velocity's units, or set Step Size in time units."),
    "its units fit the grid and the time steps, while those of 'wind' do not: even at 1000 frames "
    "per input time step a frame takes up to 40 steps");
}
