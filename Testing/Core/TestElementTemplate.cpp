// SPDX-License-Identifier: BSD-3-Clause
#include "ElementTemplate.h"
#include "Engine.h"
#include "ParticleLayout.h"

#include <cstdint>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace
{
struct Counts
{
  bp::BuiltinShape shape;
  std::size_t particles, triangles, springs;
};

// Thesis Table 4.1 gives particles(triangles)[springs] for the square and the
// strips; the fish is Tu and Terzopoulos' full 23-node, 91-spring model.
const Counts expected[] = {
  { bp::BuiltinShape::Point, 1, 0, 0 },
  { bp::BuiltinShape::Square, 4, 2, 6 },
  { bp::BuiltinShape::Strip4, 4, 2, 6 },
  { bp::BuiltinShape::Strip8, 8, 6, 16 },
  { bp::BuiltinShape::Strip16, 16, 14, 36 },
  { bp::BuiltinShape::Cross, 12, 10, 29 },
  { bp::BuiltinShape::Paddlewheel, 8, 4, 28 },
  { bp::BuiltinShape::Tetrahedron, 4, 4, 6 },
  { bp::BuiltinShape::Fish, 23, 40, 91 },
};
} // namespace

TEST(ElementTemplate, BuiltinsHaveTheirCounts)
{
  for (const Counts& c : expected)
  {
    const bp::ElementTemplate t = bp::builtinTemplate(c.shape);
    SCOPED_TRACE(t.name);
    EXPECT_EQ(t.name, bp::enumName(c.shape));
    EXPECT_EQ(t.validate(), "");
    EXPECT_EQ(t.particleCount(), c.particles);
    EXPECT_EQ(t.triangles.size(), c.triangles);
    EXPECT_EQ(t.springs.size(), c.springs);
  }
}

TEST(ElementTemplate, BuiltinsAreNormalised)
{
  for (const Counts& c : expected)
  {
    const bp::ElementTemplate t = bp::builtinTemplate(c.shape);
    SCOPED_TRACE(t.name);
    double centroid[3] = { 0, 0, 0 }, radius = 0;
    for (const auto& p : t.rest)
    {
      for (int k = 0; k < 3; ++k)
      {
        centroid[k] += p[k] / t.particleCount();
      }
      radius = std::max(radius, std::sqrt(double(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])));
    }
    for (double v : centroid)
    {
      EXPECT_NEAR(v, 0.0, 1e-6);
    }
    if (t.particleCount() > 1)
    {
      EXPECT_NEAR(radius, 0.5, 1e-6);
    }
    for (const bp::Spring& s : t.springs)
    {
      const auto& a = t.rest[s.a];
      const auto& b = t.rest[s.b];
      const double d =
        std::sqrt(std::pow(a[0] - b[0], 2) + std::pow(a[1] - b[1], 2) + std::pow(a[2] - b[2], 2));
      EXPECT_NEAR(s.restLength, d, 1e-6);
      EXPECT_GT(s.restLength, 0.0f);
    }
  }
}

TEST(ElementTemplate, ClosedShapesFaceOutwards)
{
  // Signed volume by the divergence theorem: positive for outward triangles.
  for (bp::BuiltinShape shape : { bp::BuiltinShape::Tetrahedron, bp::BuiltinShape::Fish })
  {
    const bp::ElementTemplate t = bp::builtinTemplate(shape);
    double volume = 0.0;
    for (std::size_t i = 0; i < t.triangles.size(); ++i)
    {
      const auto& a = t.rest[t.triangles[i][0]];
      const auto& b = t.rest[t.triangles[i][1]];
      const auto& c = t.rest[t.triangles[i][2]];
      const double part = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                            a[2] * (b[0] * c[1] - b[1] * c[0])) /
        6.0;
      volume += part;
      if (shape == bp::BuiltinShape::Tetrahedron)
      {
        EXPECT_GT(part, 0.0) << "triangle " << i;
      }
    }
    EXPECT_GT(volume, 0.0) << t.name;
  }
}

TEST(ElementTemplate, ValidateNamesTheProblem)
{
  bp::ElementTemplate t = bp::builtinTemplate(bp::BuiltinShape::Square);
  t.springs[0].b = 9;
  EXPECT_NE(t.validate().find("only 4 particles"), std::string::npos) << t.validate();

  t = bp::builtinTemplate(bp::BuiltinShape::Square);
  t.springs[1].b = t.springs[1].a;
  EXPECT_NE(t.validate().find("to itself"), std::string::npos);

  t = bp::builtinTemplate(bp::BuiltinShape::Square);
  t.springs[2].stiffness = 1.5f;
  EXPECT_NE(t.validate().find("stiffness"), std::string::npos);

  t = bp::builtinTemplate(bp::BuiltinShape::Square);
  t.triangles[0][2] = 7;
  EXPECT_NE(t.validate().find("triangle 0"), std::string::npos);

  t = bp::builtinTemplate(bp::BuiltinShape::Square);
  t.rest[0][1] = std::nanf("");
  EXPECT_NE(t.validate().find("non-finite"), std::string::npos);

  EXPECT_NE(bp::ElementTemplate().validate(), "");
}

TEST(ElementTemplate, MakeTemplateUsesTriangleEdgesWithoutSprings)
{
  const bp::ElementTemplate t =
    bp::makeTemplate("tri", { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } }, {});
  EXPECT_EQ(t.validate(), "");
  EXPECT_EQ(t.springs.size(), 3u);
}

TEST(ElementTemplate, MeshSpringsFromTriangles)
{
  // Two triangles sharing the diagonal of a unit square.
  const std::vector<std::array<std::uint32_t, 3>> square = { { 0, 1, 2 }, { 0, 2, 3 } };
  EXPECT_EQ(bp::meshSprings(4, square, bp::MeshSprings::Edges).size(), 5u);
  const auto braced = bp::meshSprings(4, square, bp::MeshSprings::EdgesAndDiagonals);
  ASSERT_EQ(braced.size(), 6u); // plus the other diagonal, 1-3
  EXPECT_EQ(std::min(braced[5][0], braced[5][1]), 1u);
  EXPECT_EQ(std::max(braced[5][0], braced[5][1]), 3u);
  EXPECT_EQ(bp::meshSprings(5, square, bp::MeshSprings::AllPairs).size(), 10u);
}

TEST(ElementTemplate, SpringColoursShareNoParticle)
{
  for (int shape = 0; shape < bp::enumCount<bp::BuiltinShape>(); ++shape)
  {
    const bp::ElementTemplate t = bp::builtinTemplate(bp::BuiltinShape(shape));
    const std::vector<int> colour = bp::colourSprings(t.particleCount(), t.springs);
    ASSERT_EQ(colour.size(), t.springs.size());
    for (std::size_t i = 0; i < t.springs.size(); ++i)
      for (std::size_t j = i + 1; j < t.springs.size(); ++j)
        if (colour[i] == colour[j])
        {
          const auto& a = t.springs[i];
          const auto& b = t.springs[j];
          EXPECT_TRUE(a.a != b.a && a.a != b.b && a.b != b.a && a.b != b.b) << t.name;
        }
  }
}

TEST(ElementTemplate, StableRelaxationFollowsTheBusiestParticle)
{
  // A chain: inner particles carry two half-shares, so 1 / (2 * 0.5) = 1.
  const auto chain = bp::makeTemplate(
    "chain", { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, {}, { { 0, 1 }, { 1, 2 } });
  EXPECT_FLOAT_EQ(bp::stableRelaxation(chain), 1.0f);
  // Every built-in shape is stable at the default factor.
  for (int s = 0; s <= int(bp::BuiltinShape::Fish); ++s)
  {
    EXPECT_GE(bp::stableRelaxation(bp::builtinTemplate(bp::BuiltinShape(s))), 0.2f) << s;
  }
  EXPECT_TRUE(std::isinf(bp::stableRelaxation(bp::builtinTemplate(bp::BuiltinShape::Point))));
}

TEST(ElementTemplate, GpuTextureLimitsNameWhatDoesNotFit)
{
  const auto strip = bp::builtinTemplate(bp::BuiltinShape::Strip16);
  EXPECT_EQ(bp::gpuTextureError(strip, 65536, 16384), "");
  EXPECT_NE(bp::gpuTextureError(strip, 1 << 26, 16384).find("state texture"), std::string::npos);
  std::vector<std::array<float, 3>> points(20000, { 0, 0, 0 });
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = { float(i), float(i % 7), 0.0f };
  const auto big = bp::makeTemplate("big", points, {}, { { 0, 1 } });
  const std::string error = bp::gpuTextureError(big, 10, 16384);
  EXPECT_NE(error.find("template"), std::string::npos) << error;
  EXPECT_NE(error.find("at most 8192 particles"), std::string::npos) << error;
}

namespace
{
/// The triangles VTK reads from strip s, each rotated to start at its smallest vertex.
std::multiset<std::array<std::uint32_t, 3>> stripTriangles(const std::vector<std::uint32_t>& s)
{
  std::multiset<std::array<std::uint32_t, 3>> out;
  for (std::size_t k = 0; k + 2 < s.size(); ++k)
  {
    std::array<std::uint32_t, 3> t = k % 2
      ? std::array<std::uint32_t, 3>{ s[k + 1], s[k], s[k + 2] }
      : std::array<std::uint32_t, 3>{ s[k], s[k + 1], s[k + 2] };
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

std::multiset<std::array<std::uint32_t, 3>> templateTriangles(const bp::ElementTemplate& shape)
{
  std::multiset<std::array<std::uint32_t, 3>> out;
  for (auto t : shape.triangles)
  {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}
} // namespace

TEST(ElementTemplate, StripsAreOneTriangleStripWithTheSameTriangles)
{
  for (auto shape : { bp::BuiltinShape::Square, bp::BuiltinShape::Strip4, bp::BuiltinShape::Strip8,
         bp::BuiltinShape::Strip16 })
  {
    const bp::ElementTemplate t = bp::builtinTemplate(shape);
    const std::vector<std::uint32_t> strip = bp::triangleStrip(t);
    ASSERT_EQ(strip.size(), t.triangles.size() + 2) << t.name;
    EXPECT_EQ(stripTriangles(strip), templateTriangles(t))
      << t.name << ": same triangles, same winding";
  }
  // Shapes whose triangles form no single strip keep their triangles.
  for (auto shape :
    { bp::BuiltinShape::Cross, bp::BuiltinShape::Paddlewheel, bp::BuiltinShape::Fish })
  {
    EXPECT_TRUE(bp::triangleStrip(bp::builtinTemplate(shape)).empty()) << bp::enumName(shape);
  }
  // A fan of three triangles is a strip (1 2 0 3 4); of four it is not: a
  // strip's vertex is in at most three triangles.
  bp::ElementTemplate fan;
  fan.triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 } };
  EXPECT_EQ(stripTriangles(bp::triangleStrip(fan)), templateTriangles(fan));
  fan.triangles.push_back({ 0, 4, 5 });
  EXPECT_TRUE(bp::triangleStrip(fan).empty());
  // Degenerate triangles are refused, not read past.
  bp::ElementTemplate degenerate;
  degenerate.triangles = { { 0, 1, 2 }, { 2, 1, 1 } };
  EXPECT_TRUE(bp::triangleStrip(degenerate).empty());
}
