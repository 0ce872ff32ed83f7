// SPDX-License-Identifier: BSD-3-Clause
// The table of output arrays (Core/Output/OutputArrays.h).
#include "OutputArrays.h"

#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

TEST(OutputArrays, EveryIdHasItsRowInOrder)
{
  const auto& rows = bp::outputArrays();
  EXPECT_EQ(rows.size(), std::size_t(bp::OutputArrayId::Count));
  std::set<std::string> names;
  for (std::size_t k = 0; k < rows.size(); ++k)
  {
    EXPECT_EQ(std::size_t(rows[k].id), k);
    EXPECT_TRUE(names.insert(rows[k].name).second) << rows[k].name;
    EXPECT_EQ(bp::findOutputArray(rows[k].name), &rows[k]);
  }
  EXPECT_EQ(bp::findOutputArray("NoSuchArray"), nullptr);
  EXPECT_STREQ(bp::outputArray(bp::OutputArrayId::Vorticity).name, "Vorticity");
}

TEST(OutputArrays, ColorSourcesBecomeShaderDefinitions)
{
  const std::string defs = bp::colorSourceDefinitions();
  EXPECT_NE(defs.find("#define BP_COLOR_SOLID 0\n"), std::string::npos);
  EXPECT_NE(defs.find("#define BP_COLOR_FORCE 1\n"), std::string::npos);
  EXPECT_NE(defs.find("#define BP_COLOR_PARTICLE_INDEX 8\n"), std::string::npos);
  EXPECT_NE(defs.find("#define BP_COLOR_STRETCH 13\n"), std::string::npos);
  EXPECT_NE(defs.find("#define BP_COLOR_FTLE 14\n"), std::string::npos);
  // Speed is the velocity's magnitude; only Normals cannot be coloured by on
  // the GPU (the deformation arrays' fit is made in the draw shader).
  const bp::OutputArray* speed = bp::findOutputArray("Speed");
  EXPECT_EQ(speed->color, bp::ColorSource::Velocity);
  EXPECT_TRUE(speed->colorsMagnitude);
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    EXPECT_EQ(row.color == bp::ColorSource::Solid, row.id == bp::OutputArrayId::Normals)
      << row.name;
  }
}

TEST(OutputArrays, ExpectedRangesFollowTheParameters)
{
  const bp::GridGeometry g = bptest::grid(9);
  const bp::VectorField field = bptest::steadyFlow(bp::AnalyticFlow::SolidBodyRotation, g);
  bp::Parameters p;
  p.numberOfElements = 50;
  p.emitterMin = { 0.25f, 0.25f, 0.5f };
  p.emitterMax = { 1.75f, 1.75f, 1.0f };
  p.lifetimeMax = 4.0f;
  const std::array<double, 3> offset = { -1, -1, -1 };
  const bp::RangeFacts f = bp::rangeFactsOf(field, p, 0.1, 2, offset, { 0, 2, 0, 2, 0, 2 }, 8);
  auto range = [&](const char* name) { return bp::expectedRange(*bp::findOutputArray(name), f); };
  EXPECT_DOUBLE_EQ(range("Lifetime")[1], 4.0);
  EXPECT_DOUBLE_EQ(range("Layer")[0], -0.5);
  EXPECT_DOUBLE_EQ(range("Layer")[1], 0.0);
  EXPECT_DOUBLE_EQ(range("ElementId")[1], 49.0);
  EXPECT_DOUBLE_EQ(range("ParticleIndex")[1], 7.0);
  EXPECT_DOUBLE_EQ(range("Radius")[1], std::hypot(0.75, 0.75));
  EXPECT_DOUBLE_EQ(range("Speed")[1], field.maxSpeed());
  EXPECT_DOUBLE_EQ(range("Velocity")[0], -field.maxSpeed());
  EXPECT_DOUBLE_EQ(range("Force")[1], 0.1 * field.maxSpeed());
  // Solid rotation of unit rate about z: |curl v| = 2 everywhere.
  EXPECT_NEAR(range("Vorticity")[1], 2.0, 1e-3);
  EXPECT_DOUBLE_EQ(range("ElementStretch")[1], 2.0);
  EXPECT_NEAR(range("ElementFTLE")[1], 2.0, 1e-3);
  EXPECT_FALSE(bp::findOutputArray("ElementFTLE")->onByDefault);
  EXPECT_FALSE(bp::findOutputArray("ElementStretch")->needsPoses);
}
