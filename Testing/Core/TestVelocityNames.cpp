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
