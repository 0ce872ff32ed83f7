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
 * The triangles are kept in a uniform grid of buckets over their bounds, so
 * a step tests only the triangles of the buckets its segment's box touches;
 * a triangle that would touch more than MaxBucketsPerTriangle buckets (a
 * long sliver of a fan) is kept apart and tested by every step, so that the
 * buckets hold at most that many entries a triangle.
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
  /// The buckets' members (Start, Members) and the triangles kept apart
  /// (Large), once the triangles and the grid are set.
  void fillBuckets();
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
  /// The triangles that touch more than MaxBucketsPerTriangle buckets, in
  /// no bucket: every step tests them.
  std::vector<std::uint32_t> Large;
  static constexpr int MaxBucketsPerTriangle = 64;
};

} // namespace bp

#endif
