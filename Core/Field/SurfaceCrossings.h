// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SurfaceCrossings.h
 * @brief Where a particle's step crosses a surface of triangles: the
 * geometry under surfaces that record or act on the elements that pass them
 * (issue 58's gates, outlets and walls from any surface).
 *
 * A step is the segment from a particle's position before it (a) to after it
 * (b). It crosses a triangle where the segment meets the triangle at a
 * parameter t in (0, 1] along it: a step that starts on a surface (t = 0)
 * has crossed it already, in the step that ended there, so a particle that
 * lands exactly on a surface is counted once. A segment through an edge or
 * a corner that triangles share meets all of them at the same t and is one
 * crossing (the first triangle in the surface's order); the edges belong to
 * the triangles (closed tests), so no crossing slips between two of them.
 *
 * The triangles are kept in a grid of buckets over their bounds, so a step
 * tests only the triangles of the buckets its segment's box touches. A
 * triangle is in the buckets it really touches (its box's buckets that a
 * triangle-box test, a hair wider than the buckets, keeps), and the buckets
 * are as long along an axis as a quarter of the triangles' median extent
 * along it at least, so that a surface of long slivers (a pipe cut along
 * its axis) is bucketed like a well-shaped one. The buckets hold at most
 * EntriesPerTriangle entries a triangle plus one a bucket: the triangles
 * that touch the fewest buckets first; the rest (the long slivers of a fan,
 * or a triangle touching more than MaxBucketsPerTriangle buckets) are kept
 * apart and tested by every step.
 * Triangles with a corner that is not finite, or without area, are left out
 * (droppedTriangles() counts them, for the caller's warning).
 */
#ifndef BoundParticles_SurfaceCrossings_h
#define BoundParticles_SurfaceCrossings_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace bp
{

/// One crossing of a step with a surface.
struct SurfaceCrossing
{
  /// Where along the step, in (0, 1]: the point is a + t (b - a).
  double t = 0.0;
  std::array<float, 3> point{};
  /// The triangle's unit normal, by its corners' order (right hand).
  std::array<float, 3> normal{};
  /// +1 where the step goes the normal's way, -1 against it.
  int direction = 0;
  /// The surface the triangle belongs to (as given), and its index among the
  /// triangles given.
  std::int32_t surface = 0;
  std::uint32_t triangle = 0;
};

class SurfaceCrossings
{
public:
  /**
   * `corners`: 9 floats a triangle (three corners x, y, z); `surfaces`: one
   * id a triangle (the same size as corners / 9, or empty for all 0).
   */
  SurfaceCrossings(const std::vector<float>& corners, const std::vector<std::int32_t>& surfaces);

  /// How many triangles are kept, and how many were left out (a corner not
  /// finite, or no area).
  std::size_t triangleCount() const { return this->Surface.size(); }
  std::size_t droppedTriangles() const { return this->Dropped; }

  /**
   * The first crossing of the step a -> b (the smallest t in (0, 1]; among
   * equal t the first triangle); false where it crosses none, or a or b is
   * not finite.
   */
  bool firstCrossing(const float a[3], const float b[3], SurfaceCrossing& crossing) const;

  /**
   * Every crossing of the step a -> b, by t (then triangle): one a
   * triangle, and one where the step passes an edge or a corner that
   * triangles of one surface share, crossing them the same way (t within
   * SharedEdgeT; the first triangle, as firstCrossing takes). None where a
   * or b is not finite.
   */
  void allCrossings(
    const float a[3], const float b[3], std::vector<SurfaceCrossing>& crossings) const;

  /**
   * Whether p lies within `distance` of a triangle's plane and its foot on
   * that plane within the triangle (its edges closed, as a crossing's): a
   * point a step put on a surface, that far off it at most. False for a p
   * that is not finite.
   */
  bool lies(const float p[3], double distance) const;

  /// The bucket index's size: its buckets, their entries (at most
  /// EntriesPerTriangle a triangle plus one a bucket), and the triangles
  /// kept apart, which every step tests.
  std::size_t bucketCount() const { return this->Start.size() - 1; }
  std::size_t bucketEntries() const { return this->Members.size(); }
  std::size_t apartTriangles() const { return this->Large.size(); }

  /// The buckets' entries: at most this many a triangle, plus one a bucket.
  static constexpr std::size_t EntriesPerTriangle = 64;
  /// A triangle that touches more buckets is kept apart (and its buckets no
  /// longer counted).
  static constexpr std::size_t MaxBucketsPerTriangle = 1024;

  /// How close two triangles' t along one step are to be one crossing
  /// through their shared edge (the same t, computed from either triangle).
  static constexpr double SharedEdgeT = 1e-9;

private:
  /// Calls visit(kept triangle, t) for each triangle of the buckets the
  /// step's box touches that the step meets (a triangle once per bucket);
  /// false where a or b is not finite or there are no triangles.
  template <typename Visit>
  bool meetAlong(const float a[3], const float b[3], Visit&& visit) const;
  /// The crossing of step a -> b with kept triangle k at t.
  SurfaceCrossing crossingAt(const float a[3], const float b[3], std::uint32_t k, double t) const;
  /// The grid's buckets (Buckets, BucketSize) over the bounds lo, hi.
  void sizeGrid(const double lo[3], const double hi[3]);
  /// The buckets' members (Start, Members) and the triangles kept apart
  /// (Large), once the triangles and the grid are set.
  void fillBuckets();
  /// Calls act(bucket) for each bucket kept triangle k touches (a hair
  /// wider), up to cap + 1 of them; returns how many it called.
  template <typename Act>
  std::size_t touchedBuckets(std::size_t k, std::size_t cap, Act&& act) const;
  /// The bucket range [lo, hi] along each axis that a box touches.
  void bucketRange(const double lo[3], const double hi[3], int first[3], int last[3]) const;

  std::vector<double> Corners; ///< 9 a kept triangle
  std::vector<std::int32_t> Surface;
  std::vector<std::uint32_t> Original; ///< each kept triangle's index as given
  std::size_t Dropped = 0;
  /// The kept triangles' bounds, and the buckets' size along each axis.
  double Lower[3] = { 0, 0, 0 };
  double Upper[3] = { 0, 0, 0 };
  double BucketSize[3] = { 1, 1, 1 };
  int Buckets[3] = { 1, 1, 1 };
  /// Bucket b's triangles are Members[Start[b], Start[b + 1]).
  std::vector<std::uint32_t> Start;
  std::vector<std::uint32_t> Members;
  /// The triangles kept apart, in no bucket: every step tests them.
  std::vector<std::uint32_t> Large;
};

} // namespace bp

#endif
