// SPDX-License-Identifier: BSD-3-Clause
// Tests of Core/Elements/ElementNormals.h: per-particle normals of whole elements.
#include "ElementNormals.h"
#include "ElementTemplate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

TEST(ElementNormals, FourAtATimeAreTheSameBitsAsOneByOne)
{
  // Seven elements (four in lanes, three alone): bent, flat, collapsed to a
  // point (no triangle counts) and one with a NaN corner.
  for (bp::BuiltinShape kind : { bp::BuiltinShape::Strip16, bp::BuiltinShape::Cross,
         bp::BuiltinShape::Paddlewheel, bp::BuiltinShape::Fish })
  {
    SCOPED_TRACE(bp::enumName(kind));
    const bp::ElementTemplate shape = bp::builtinTemplate(kind);
    const std::size_t n = shape.particleCount(), E = 7;
    std::mt19937 random(17);
    std::normal_distribution<float> jitter(0.0f, 0.3f);
    std::vector<float> positions(3 * n * E);
    for (std::size_t e = 0; e < E; ++e)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          positions[3 * (e * n + i) + std::size_t(k)] =
            shape.rest[i][std::size_t(k)] + (e == 1 ? 0.0f : jitter(random));
        }
      }
    }
    std::fill_n(positions.begin() + std::ptrdiff_t(3 * n * 2), 3 * n, 0.5f); // a point
    positions[3 * n * 5 + 4] = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> together(positions.size()), alone(positions.size());
    bp::elementsNormals(shape, positions.data(), together.data(), E);
    for (std::size_t e = 0; e < E; ++e)
    {
      bp::elementNormals(shape, positions.data() + 3 * n * e, alone.data() + 3 * n * e);
    }
    EXPECT_EQ(0, std::memcmp(together.data(), alone.data(), sizeof(float) * together.size()));
    for (std::size_t i = 0; i < n; ++i) // the collapsed element: the fixed normal
    {
      EXPECT_EQ(alone[3 * (2 * n + i) + 2], 1.0f);
    }
    for (float v : together)
    {
      EXPECT_FALSE(std::isnan(v)); // the NaN corner's triangles are skipped
    }
  }
}
