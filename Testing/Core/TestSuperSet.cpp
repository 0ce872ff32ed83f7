// SPDX-License-Identifier: BSD-3-Clause
// Super sets (Core/Elements/SuperSet.h): lattices, links and their rest lengths, and
// the CPU engine's linked step.
#include "AnalyticFlows.h"
#include "Engine.h"
#include "SuperSet.h"

#include <cstdint>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace
{
const std::array<float, 3> Lo = { 0, 0, 0 };
const std::array<float, 3> Hi = { 4, 2, 1 };

/// Every link is listed from both ends with the same rest length, which is
/// the distance between the two sites; returns the links counted once.
std::size_t checkSymmetric(const bp::LinkTable& t)
{
  const std::size_t N = t.sites.size() / 3;
  std::size_t halfLinks = 0;
  for (std::size_t e = 0; e < N; ++e)
  {
    for (int d = 0; d < bp::LinkDirections; ++d)
    {
      const std::int32_t f = t.neighbours[4 * e + d];
      if (f < 0)
        continue;
      ++halfLinks;
      EXPECT_NE(std::size_t(f), e);
      const int back = d ^ 1; // +u <-> -u, +v <-> -v
      EXPECT_EQ(t.neighbours[4 * std::size_t(f) + back], std::int32_t(e)) << e << " dir " << d;
      EXPECT_EQ(t.rest[4 * std::size_t(f) + back], t.rest[4 * e + d]);
      const float* a = &t.sites[3 * e];
      const float* b = &t.sites[3 * std::size_t(f)];
      EXPECT_NEAR(t.rest[4 * e + d], std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]), 1e-6);
    }
  }
  EXPECT_EQ(halfLinks % 2, 0u);
  EXPECT_EQ(halfLinks / 2, t.linkCount());
  return halfLinks / 2;
}
} // namespace

TEST(SuperSet, NoneHasNoLinks)
{
  EXPECT_TRUE(bp::makeLinkTable(bp::Linking::None, 100, 0, Lo, Hi).empty());
}

TEST(SuperSet, ChainAndRingAreOneRow)
{
  const bp::LinkTable chain = bp::makeLinkTable(bp::Linking::Chain, 10, 0, Lo, Hi);
  EXPECT_EQ(chain.width, 10);
  EXPECT_EQ(chain.height, 1);
  EXPECT_EQ(checkSymmetric(chain), 9u);
  // Along the longest axis (x), evenly from one side of the box to the other.
  EXPECT_FLOAT_EQ(chain.sites[0], 0.0f);
  EXPECT_FLOAT_EQ(chain.sites[3 * 9], 4.0f);
  EXPECT_FLOAT_EQ(chain.sites[1], 1.0f);
  EXPECT_FLOAT_EQ(chain.rest[0], 4.0f / 9.0f);
  const bp::LinkTable ring = bp::makeLinkTable(bp::Linking::Ring, 10, 0, Lo, Hi);
  EXPECT_EQ(checkSymmetric(ring), 10u);
  EXPECT_EQ(ring.neighbours[4 * 9 + 0], 0); // closes
  for (std::size_t e = 0; e < 10; ++e)
  {
    // On the ellipse in the x-y plane through the box's middle.
    const double x = (ring.sites[3 * e] - 2.0) / 2.0, y = (ring.sites[3 * e + 1] - 1.0) / 1.0;
    EXPECT_NEAR(x * x + y * y, 1.0, 1e-5);
    EXPECT_FLOAT_EQ(ring.sites[3 * e + 2], 0.5f);
  }
  // Two elements would be linked twice by a closing link: they are a chain.
  EXPECT_EQ(bp::makeLinkTable(bp::Linking::Ring, 2, 0, Lo, Hi).linkCount(), 1u);
}

TEST(SuperSet, LatticesAndTheirWraps)
{
  // 12 = 4 x 3: a sheet has 3 * 3 + 4 * 2 links, a tube closes its 3 rows,
  // a torus also its 4 columns.
  EXPECT_EQ(checkSymmetric(bp::makeLinkTable(bp::Linking::Sheet, 12, 4, Lo, Hi)), 17u);
  EXPECT_EQ(checkSymmetric(bp::makeLinkTable(bp::Linking::Tube, 12, 4, Lo, Hi)), 20u);
  EXPECT_EQ(checkSymmetric(bp::makeLinkTable(bp::Linking::Torus, 12, 4, Lo, Hi)), 24u);
  // Near square by default: 10 elements on a 4-wide lattice, the last row partial.
  const bp::LinkTable partial = bp::makeLinkTable(bp::Linking::Torus, 10, 0, Lo, Hi);
  EXPECT_EQ(partial.width, 4);
  EXPECT_EQ(partial.height, 3);
  checkSymmetric(partial);
  EXPECT_EQ(partial.neighbours[4 * 9 + 0], -1); // the partial row does not close
  EXPECT_EQ(partial.neighbours[4 * 8 + 2], 0);  // its columns close onto row 0
  EXPECT_EQ(partial.neighbours[4 * 7 + 2], -1); // a column without a last-row site does not
  // Sites of a sheet are distinct and inside the box.
  const bp::LinkTable sheet = bp::makeLinkTable(bp::Linking::Sheet, 100, 0, Lo, Hi);
  std::set<std::array<float, 3>> distinct;
  for (std::size_t e = 0; e < 100; ++e)
  {
    distinct.insert({ sheet.sites[3 * e], sheet.sites[3 * e + 1], sheet.sites[3 * e + 2] });
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_GE(sheet.sites[3 * e + a], Lo[a]);
      EXPECT_LE(sheet.sites[3 * e + a], Hi[a]);
    }
  }
  EXPECT_EQ(distinct.size(), 100u);
}

TEST(SuperSet, ElementsAreReleasedTogetherAtTheirSites)
{
  bp::GridGeometry g;
  g.dims = { 9, 9, 9 };
  g.origin = { 0, 0, 0 };
  g.spacing = { 0.5, 0.25, 0.125 };
  bp::FieldSlice slice;
  slice.velocity =
    std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(bp::AnalyticFlow::ABC, g, 0.0));
  const bp::VectorField field(g, slice);
  bp::Parameters p;
  p.numberOfElements = 30;
  p.elementSize = 0.1f;
  p.emitterMin = { 0.5f, 0.5f, 0.25f };
  p.emitterMax = { 3.5f, 1.5f, 0.75f };
  p.lifetimeMin = 0.05f;
  p.lifetimeMax = 0.2f;
  p.linking = bp::Linking::Tube;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
  engine.initialize(bp::serialRunner());
  const auto& links = engine.links();
  for (int s = 0; s < 40; ++s)
  {
    engine.step(field, s * 0.01, 0.01, bp::serialRunner());
    // One lifetime, one generation, one orientation for all.
    for (std::size_t e = 1; e < p.numberOfElements; ++e)
    {
      ASSERT_EQ(engine.lifetimes()[e], engine.lifetimes()[0]);
      ASSERT_EQ(engine.generations()[e], engine.generations()[0]);
      for (int k = 0; k < 4; ++k)
        ASSERT_EQ(engine.orientations()[4 * e + k], engine.orientations()[k]);
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(engine.initialCenters()[3 * e + k], links.sites[3 * e + k]);
    }
    for (float v : engine.positions())
      ASSERT_TRUE(std::isfinite(v));
  }
  EXPECT_GE(engine.generations()[0], 2u); // released again, as a whole
}

TEST(SuperSet, SaysWhatIsWrong)
{
  bp::Parameters p;
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Point);
  p.linking = bp::Linking::Sheet;
  p.latticeWidth = -1;
  EXPECT_NE(bp::Engine::validate(shape, p).find("LatticeWidth"), std::string::npos);
  p.latticeWidth = 0;
  p.linkStiffness = 1.5f;
  EXPECT_NE(bp::Engine::validate(shape, p).find("LinkStiffness"), std::string::npos);
  p.linkStiffness = 1.0f;
  p.linking = bp::Linking(9);
  EXPECT_NE(bp::Engine::validate(shape, p).find("Linking"), std::string::npos);
  p.linking = bp::Linking::Sheet;
  p.linearBlend = -0.1f;
  EXPECT_NE(bp::Engine::validate(shape, p).find("beta"), std::string::npos);
}
