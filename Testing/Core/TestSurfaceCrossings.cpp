// SPDX-License-Identifier: BSD-3-Clause
// Where a step crosses a surface of triangles (Core/Field/SurfaceCrossings.h).
#include "SurfaceCrossings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace
{
/// The unit square in z = 0 as two triangles, counter-clockwise seen from
/// +z (normal +z), sharing the diagonal (0, 0) - (1, 1), offset by `o`.
std::vector<float> unitSquare(float o = 0.0f)
{
  return { o, o, 0, 1 + o, o, 0, 1 + o, 1 + o, 0, o, o, 0, 1 + o, 1 + o, 0, o, 1 + o, 0 };
}

/// An open pipe of radius 0.3 along y from -0.9 to 0.9, cut into `around`
/// x `along` quads, two triangles each (around = 10000, along = 1: long
/// slivers, as an extrusion gives).
std::vector<float> pipe(int around, int along)
{
  std::vector<float> corners;
  auto corner = [&](int i, int r)
  {
    const double a = 2 * M_PI * (i % around) / around, y = -0.9 + 1.8 * r / along;
    corners.insert(corners.end(), { float(0.3 * std::cos(a)), float(y), float(0.3 * std::sin(a)) });
  };
  for (int r = 0; r < along; ++r)
    for (int i = 0; i < around; ++i)
    {
      for (const auto& [di, dr] :
        { std::pair{ 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 0 }, { 1, 1 }, { 0, 1 } })
      {
        corner(i + di, r + dr);
      }
    }
  return corners;
}

bool cross(const bp::SurfaceCrossings& s, std::vector<float> a, std::vector<float> b,
  bp::SurfaceCrossing* out = nullptr)
{
  bp::SurfaceCrossing c;
  const bool hit = s.firstCrossing(a.data(), b.data(), c);
  if (out)
  {
    *out = c;
  }
  return hit;
}
} // namespace

TEST(SurfaceCrossings, AStepThroughATriangleCrossesWhereItMeetsIt)
{
  const bp::SurfaceCrossings square(unitSquare(), { 7, 7 });
  ASSERT_EQ(square.triangleCount(), 2u);
  bp::SurfaceCrossing c;
  ASSERT_TRUE(cross(square, { 0.75f, 0.25f, 1 }, { 0.75f, 0.25f, -1 }, &c));
  EXPECT_DOUBLE_EQ(c.t, 0.5);
  EXPECT_FLOAT_EQ(c.point[0], 0.75f);
  EXPECT_FLOAT_EQ(c.point[1], 0.25f);
  EXPECT_FLOAT_EQ(c.point[2], 0.0f);
  EXPECT_FLOAT_EQ(c.normal[2], 1.0f);
  EXPECT_EQ(c.direction, -1); // down, against the normal
  EXPECT_EQ(c.surface, 7);
  EXPECT_EQ(c.triangle, 0u);
  ASSERT_TRUE(cross(square, { 0.25f, 0.75f, -0.5f }, { 0.25f, 0.75f, 1.5f }, &c));
  EXPECT_DOUBLE_EQ(c.t, 0.25);
  EXPECT_EQ(c.direction, 1);
  EXPECT_EQ(c.triangle, 1u);
}

TEST(SurfaceCrossings, AStepThroughASharedEdgeOrCornerIsOneCrossing)
{
  const bp::SurfaceCrossings square(unitSquare(), {});
  bp::SurfaceCrossing c;
  // The diagonal both triangles share: the first triangle's crossing.
  ASSERT_TRUE(cross(square, { 0.5f, 0.5f, 1 }, { 0.5f, 0.5f, -1 }, &c));
  EXPECT_EQ(c.triangle, 0u);
  EXPECT_EQ(c.surface, 0);
  // A corner of both, and the square's outer edge: still crossed.
  EXPECT_TRUE(cross(square, { 0, 0, 1 }, { 0, 0, -1 }));
  EXPECT_TRUE(cross(square, { 1, 0.3f, 1 }, { 1, 0.3f, -1 }));
  // Just outside the edge: not.
  EXPECT_FALSE(cross(square, { 1.001f, 0.3f, 1 }, { 1.001f, 0.3f, -1 }));
}

TEST(SurfaceCrossings, AParticleLandingOnASurfaceCrossesItOnce)
{
  const bp::SurfaceCrossings square(unitSquare(), {});
  bp::SurfaceCrossing c;
  // Ends on it: crossed at t = 1; starts from it next step: not again.
  ASSERT_TRUE(cross(square, { 0.3f, 0.6f, 1 }, { 0.3f, 0.6f, 0 }, &c));
  EXPECT_DOUBLE_EQ(c.t, 1.0);
  EXPECT_FALSE(cross(square, { 0.3f, 0.6f, 0 }, { 0.3f, 0.6f, -1 }));
  // Along it, standing still, or beside it: no crossing.
  EXPECT_FALSE(cross(square, { 0.1f, 0.1f, 0 }, { 0.9f, 0.2f, 0 }));
  EXPECT_FALSE(cross(square, { 0.3f, 0.6f, 0.5f }, { 0.3f, 0.6f, 0.5f }));
  EXPECT_FALSE(cross(square, { 0.3f, 0.6f, 0.5f }, { 0.3f, 0.6f, 0.1f }));
  EXPECT_FALSE(cross(square, { 3, 3, 1 }, { 3, 3, -1 }));
}

TEST(SurfaceCrossings, TrianglesWithoutAreaOrFiniteCornersAreLeftOutAndCounted)
{
  std::vector<float> corners = unitSquare();
  const std::vector<float> flat = { 0, 0, 0, 1, 1, 1, 2, 2, 2 }; // on a line
  const std::vector<float> nan = { 0, 0, 0, NAN, 0, 0, 0, 1, 0 };
  corners.insert(corners.end(), flat.begin(), flat.end());
  corners.insert(corners.end(), nan.begin(), nan.end());
  corners.insert(corners.end(), { 0, 0, 5, 1, 0, 5, 0, 1, 5 }); // kept, index 4
  const bp::SurfaceCrossings s(corners, { 1, 2, 3, 4, 5 });
  EXPECT_EQ(s.triangleCount(), 3u);
  EXPECT_EQ(s.droppedTriangles(), 2u);
  bp::SurfaceCrossing c;
  ASSERT_TRUE(cross(s, { 0.2f, 0.2f, 6 }, { 0.2f, 0.2f, 4 }, &c));
  EXPECT_EQ(c.triangle, 4u); // its index as given
  EXPECT_EQ(c.surface, 5);
  // A step that is not finite crosses nothing; no triangles, nothing either.
  EXPECT_FALSE(cross(s, { NAN, 0.2f, 6 }, { 0.2f, 0.2f, -1 }));
  EXPECT_FALSE(cross(s, { 0.2f, 0.2f, 6 }, { 0.2f, INFINITY, -1 }));
  const bp::SurfaceCrossings none({}, {});
  EXPECT_EQ(none.triangleCount(), 0u);
  EXPECT_FALSE(cross(none, { 0, 0, 1 }, { 0, 0, -1 }));
}

TEST(SurfaceCrossings, FarFromTheOriginAStepStillCrosses)
{
  const bp::SurfaceCrossings square(unitSquare(1.0e6f), {});
  bp::SurfaceCrossing c;
  ASSERT_TRUE(cross(
    square, { 1.0e6f + 0.5f, 1.0e6f + 0.25f, 0.5f }, { 1.0e6f + 0.5f, 1.0e6f + 0.25f, -0.5f }, &c));
  EXPECT_DOUBLE_EQ(c.t, 0.5);
  EXPECT_FLOAT_EQ(c.point[0], 1.0e6f + 0.5f);
}

TEST(SurfaceCrossings, TheBucketsFindTheFirstCrossingOfEveryTriangle)
{
  // Many small triangles anywhere in a box, many steps: the first crossing
  // the buckets find is the first of all triangles, each tested alone.
  std::mt19937 random(5);
  std::uniform_real_distribution<float> where(-2.0f, 2.0f), small(-0.3f, 0.3f);
  std::vector<float> corners;
  for (int k = 0; k < 3000; ++k)
  {
    const float c[3] = { where(random), where(random), where(random) };
    for (int i = 0; i < 9; ++i)
      corners.push_back(c[i % 3] + small(random));
  }
  const bp::SurfaceCrossings all(corners, {});
  std::vector<bp::SurfaceCrossings> alone;
  for (std::size_t k = 0; k < corners.size() / 9; ++k)
  {
    alone.emplace_back(std::vector<float>(corners.begin() + 9 * k, corners.begin() + 9 * k + 9),
      std::vector<std::int32_t>{});
  }
  int crossings = 0;
  for (int s = 0; s < 2000; ++s)
  {
    const float a[3] = { where(random), where(random), where(random) };
    const float b[3] = { a[0] + small(random), a[1] + small(random), a[2] + small(random) };
    bp::SurfaceCrossing found, best;
    best.t = 2.0;
    for (std::size_t k = 0; k < alone.size(); ++k)
    {
      bp::SurfaceCrossing c;
      if (alone[k].firstCrossing(a, b, c) && c.t < best.t)
      {
        best = c;
        best.triangle = std::uint32_t(k);
      }
    }
    const bool hit = all.firstCrossing(a, b, found);
    ASSERT_EQ(hit, best.t <= 1.0) << "step " << s;
    if (hit)
    {
      ++crossings;
      EXPECT_EQ(found.triangle, best.triangle) << "step " << s;
      EXPECT_EQ(found.t, best.t) << "step " << s;
    }
  }
  EXPECT_GT(crossings, 100); // the case crosses often enough to mean something
}

TEST(SurfaceCrossings, AGateOnAHalfPlaneIsCrossedOncePerTurnOfARotation)
{
  // The half-plane y = 0, x in [0, 2], z in [-1, 1] (two triangles, normal
  // -y); a particle turning anticlockwise on a circle of radius 1 about the
  // z axis, in steps of 1/40 turn started a quarter step past the gate: five
  // turns cross it five times, each in the step over angle 0 (and never the
  // other half of the plane, at angle pi).
  const std::vector<float> gate = { 0, 0, -1, 2, 0, -1, 2, 0, 1, 0, 0, -1, 2, 0, 1, 0, 0, 1 };
  const bp::SurfaceCrossings s(gate, {});
  const double pi = std::acos(-1.0), step = 2 * pi / 40;
  int crossed = 0;
  for (int k = 0; k < 5 * 40; ++k)
  {
    const double t0 = (k + 0.25) * step, t1 = t0 + step;
    const float a[3] = { float(std::cos(t0)), float(std::sin(t0)), 0.0f };
    const float b[3] = { float(std::cos(t1)), float(std::sin(t1)), 0.0f };
    bp::SurfaceCrossing c;
    if (s.firstCrossing(a, b, c))
    {
      ++crossed;
      EXPECT_EQ(k % 40, 39) << "the step over angle 0";
      // Where the chord meets y = 0.
      const double x = a[0] + (double(b[0]) - a[0]) * (-double(a[1])) / (double(b[1]) - a[1]);
      EXPECT_NEAR(c.point[0], x, 1e-6);
      EXPECT_NEAR(c.point[1], 0.0, 1e-6);
      EXPECT_EQ(c.direction, -1); // moving +y, against the normal
    }
  }
  EXPECT_EQ(crossed, 5);
}

TEST(SurfaceCrossings, EveryCrossingOfAStepComesInOrderOnceEach)
{
  // Two squares, z = 0 (surface 3) and z = 0.5 (surface 4), and a step
  // through both, through the diagonal each square's triangles share.
  std::vector<float> corners = unitSquare();
  std::vector<float> upper = unitSquare();
  for (std::size_t k = 2; k < upper.size(); k += 3)
    upper[k] = 0.5f;
  corners.insert(corners.end(), upper.begin(), upper.end());
  const bp::SurfaceCrossings two(corners, { 3, 3, 4, 4 });
  std::vector<bp::SurfaceCrossing> all;
  const float a[3] = { 0.5f, 0.5f, -0.5f }, b[3] = { 0.5f, 0.5f, 1.5f };
  two.allCrossings(a, b, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].surface, 3);
  EXPECT_EQ(all[0].triangle, 0u); // the diagonal: the first triangle's
  EXPECT_EQ(all[1].triangle, 2u);
  EXPECT_NEAR(all[0].t, 0.25, 1e-12);
  EXPECT_EQ(all[1].surface, 4);
  EXPECT_NEAR(all[1].t, 0.5, 1e-12);
  EXPECT_EQ(all[1].direction, 1);
  // The first crossing is firstCrossing's.
  bp::SurfaceCrossing first;
  ASSERT_TRUE(two.firstCrossing(a, b, first));
  EXPECT_EQ(first.triangle, all[0].triangle);
  EXPECT_EQ(first.t, all[0].t);
  // Back the other way: the same crossings, reversed in order and direction.
  two.allCrossings(b, a, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].surface, 4);
  EXPECT_EQ(all[0].direction, -1);
  // A step that misses, or is not finite: none.
  const float beside[3] = { 2, 2, -1 }, nan[3] = { NAN, 0, 0 };
  two.allCrossings(beside, b, all);
  EXPECT_TRUE(all.empty());
  two.allCrossings(nan, b, all);
  EXPECT_TRUE(all.empty());
}

TEST(SurfaceCrossings, AFanOfLongThinTrianglesIsCrossedOnceWherever)
{
  // A disc cut as a fan (every triangle shares the centre): its slivers
  // span many buckets, and every one is found wherever a step crosses.
  const int n = 3000;
  std::vector<float> fan;
  for (int k = 0; k < n; ++k)
  {
    const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
    fan.insert(fan.end(),
      { 0, 0, 0, float(std::cos(a0)), float(std::sin(a0)), 0, float(std::cos(a1)),
        float(std::sin(a1)), 0 });
  }
  const bp::SurfaceCrossings disc(fan, {});
  EXPECT_EQ(disc.triangleCount(), std::size_t(n));
  std::mt19937 draw(5);
  std::uniform_real_distribution<float> within(-0.6f, 0.6f);
  for (int k = 0; k < 50; ++k)
  {
    const float x = within(draw), y = within(draw);
    std::vector<bp::SurfaceCrossing> all;
    const float a[3] = { x, y, -1 }, b[3] = { x, y, 1 };
    disc.allCrossings(a, b, all);
    EXPECT_EQ(all.size(), 1u) << x << " " << y;
    const float on[3] = { x, y, 1e-7f }, off[3] = { x, y, 1e-3f };
    EXPECT_TRUE(disc.lies(on, 1e-6));
    EXPECT_FALSE(disc.lies(off, 1e-6));
  }
  const float beyond[3] = { 1.5f, 0, 0 };
  EXPECT_FALSE(disc.lies(beyond, 1e-3));
}

TEST(SurfaceCrossings, APipeOfLongSliversIsBucketedLikeAWellShapedOne)
{
  // 20,000 slivers the pipe's length: none kept apart (tested by every
  // step), a few buckets each, as the same number of well-shaped triangles.
  const bp::SurfaceCrossings slivers(pipe(10000, 1), {}), quads(pipe(100, 100), {});
  ASSERT_EQ(slivers.triangleCount(), 20000u);
  EXPECT_EQ(slivers.apartTriangles(), 0u);
  EXPECT_EQ(quads.apartTriangles(), 0u);
  EXPECT_LE(slivers.bucketEntries(), 8 * slivers.triangleCount());
  EXPECT_LE(quads.bucketEntries(), 8 * quads.triangleCount());
  // A step across the wall anywhere crosses it once, where it meets the
  // wall's one triangle there.
  std::mt19937 draw(3);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), height(-0.85, 0.85);
  for (int k = 0; k < 200; ++k)
  {
    const double a = angle(draw), y = height(draw);
    const float in[3] = { float(0.29 * std::cos(a)), float(y), float(0.29 * std::sin(a)) };
    const float out[3] = { float(0.31 * std::cos(a)), float(y), float(0.31 * std::sin(a)) };
    std::vector<bp::SurfaceCrossing> all;
    slivers.allCrossings(in, out, all);
    ASSERT_EQ(all.size(), 1u) << a << " " << y;
    EXPECT_NEAR(all[0].t, 0.5, 1e-3);
    EXPECT_EQ(all[0].direction, -1); // the normals point inwards: (b - a) x (c - a)
    EXPECT_TRUE(slivers.lies(all[0].point.data(), 1e-5));
  }
}

TEST(SurfaceCrossings, ADiagonalSliverIsInTheBucketsItTouchesNotItsBoxes)
{
  // Slivers along a cube's diagonal: their boxes cover every bucket, the
  // slivers a line of them; none kept apart, a few buckets each.
  std::vector<float> corners;
  const int n = 20000;
  for (int k = 0; k < n; ++k)
  {
    const float o = float(k) / n;
    corners.insert(corners.end(), { o, 0, 0, o + 1, 1, 1, o + 1.0001f, 1, 1 });
  }
  const bp::SurfaceCrossings diagonal(corners, {});
  EXPECT_EQ(diagonal.apartTriangles(), 0u);
  EXPECT_LE(diagonal.bucketEntries(), 32u * n);
  EXPECT_LT(diagonal.bucketEntries(), std::size_t(n) * diagonal.bucketCount() / 4);
  // Halfway along the slivers, a step across them in z meets each there.
  const float a[3] = { 1.0f, 0.5f, 0.4f }, b[3] = { 1.0f, 0.5f, 0.6f };
  std::vector<bp::SurfaceCrossing> all;
  diagonal.allCrossings(a, b, all);
  EXPECT_GE(all.size(), 1u);
}

TEST(SurfaceCrossings, AFanAmongSmallTrianglesKeepsTheBucketsLinear)
{
  // Small triangles most of all (fine buckets), and a fan of slivers from a
  // corner across the square: the slivers would fill the buckets with
  // hundreds of entries each. The buckets hold at most EntriesPerTriangle
  // entries a triangle plus one a bucket, the slivers that touch the fewest;
  // the others are kept apart, and every one is still found.
  std::vector<float> corners;
  const int slivers = 30000, small = 40000;
  for (int k = 0; k < slivers; ++k)
  {
    // From (0, 0) to the diagonal x + y = 1.
    const float s0 = float(k) / slivers, s1 = float(k + 1) / slivers;
    corners.insert(corners.end(), { 0, 0, 0, s0, 1 - s0, 0, s1, 1 - s1, 0 });
  }
  std::mt19937 draw(9);
  std::uniform_real_distribution<float> where(0.0f, 1.0f);
  for (int k = 0; k < small; ++k)
  {
    // Beyond the diagonal: x + y > 1.05.
    float x = where(draw), y = where(draw);
    if (x + y < 1.05f)
    {
      x = 1.0f - x, y = 1.0f - y;
    }
    x = std::max(x, 1.06f - y);
    corners.insert(corners.end(), { x, y, 0, x + 0.003f, y, 0, x, y + 0.003f, 0 });
  }
  const bp::SurfaceCrossings mixed(corners, {});
  const std::size_t T = mixed.triangleCount();
  ASSERT_EQ(T, std::size_t(slivers + small));
  EXPECT_LE(
    mixed.bucketEntries(), bp::SurfaceCrossings::EntriesPerTriangle * T + mixed.bucketCount());
  EXPECT_GT(mixed.apartTriangles(), 0u);
  EXPECT_LT(mixed.apartTriangles(), std::size_t(slivers));
  std::uniform_real_distribution<float> within(0.02f, 0.45f);
  for (int k = 0; k < 50; ++k)
  {
    const float x = within(draw), y = within(draw);
    std::vector<bp::SurfaceCrossing> all;
    const float a[3] = { x, y, -1 }, b[3] = { x, y, 1 };
    mixed.allCrossings(a, b, all);
    EXPECT_EQ(all.size(), 1u) << x << " " << y;
    const float on[3] = { x, y, 1e-7f }, off[3] = { x, y, 1e-3f };
    EXPECT_TRUE(mixed.lies(on, 1e-6));
    EXPECT_FALSE(mixed.lies(off, 1e-6));
  }
}
