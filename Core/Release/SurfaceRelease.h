// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SurfaceRelease.h
 * @brief Seed Type Surface (an inlet): release points spread over a
 * triangulated surface in proportion to the flux through each triangle.
 *
 * A triangle (a, b, c) has the normal n = (b − a) × (c − a) / |…| (its own
 * orientation, flipped on request) and the area A = |(b − a) × (c − a)| / 2;
 * its weight is max(0, u · n) × A, u the field's velocity at its centroid.
 * That is the flux into the side n points to, exact for a velocity linear
 * over the triangle wherever it is positive; a surface whose flux varies
 * within a triangle follows it as finely as it is cut. A point is drawn by
 * choosing a triangle in proportion to its weight, then a point uniform in it
 * (the square-root barycentric draw). Every draw is counter-based
 * (CounterHash.h) on the tracer's Seed, so every process and every run draws
 * the same points from the same weights. The filter reads the surface and
 * samples the field (Filters/TracerSurfaceSeeds.cxx); this holds the maths.
 */
#ifndef BoundParticles_SurfaceRelease_h
#define BoundParticles_SurfaceRelease_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace bp
{

/// The counter lane of the surface's draws (the Point Cloud's is
/// 0xffffffff; releases use their generation there, counting up from 0).
constexpr std::uint32_t SurfaceLane = 0xfffffffeu;

/// The weight of a triangle whose centroid has no velocity on this process
/// (outside the field, in a cell outside the flow's domain, or a non-finite
/// vector). Below every real weight, so the largest over processes is the
/// weight of whichever process holds the centroid.
constexpr double NoVelocity = -1.0;

/// Area of triangle `t` (9 coordinates: a, b, c); 0 where a corner is not finite.
double triangleArea(const double t[9]);
/// Unit normal of `t`, (b − a) × (c − a) normalised; zero when it has no area.
std::array<double, 3> triangleNormal(const double t[9]);
/// Centroid of `t`.
std::array<double, 3> triangleCentroid(const double t[9]);
/// max(0, ±u · n) × area (− with `flip`); 0 for a triangle with no area or a
/// non-finite corner, or a non-finite u.
double fluxWeight(const double t[9], const double u[3], bool flip);

/// The velocity at a point (world coordinates); false where there is none.
using SurfaceVelocity = std::function<bool(const std::array<double, 3>& x, double u[3])>;

/**
 * Where a triangle's velocity is sampled, tried in this order: at its
 * centroid; where that has no velocity (a mesh's own boundary, whose
 * resampled cells straddle the mesh's side and are outside the flow), a
 * step into the side the flux counts towards (n, or −n with flip), then a
 * step the other way. NoSample: none of the three has a velocity (or the
 * triangle has no area). Ordered, so the lowest over processes is the one
 * every process takes.
 */
enum SurfaceSide : int
{
  AtCentroid = 0,
  IntoFlux = 1,
  AgainstFlux = 2,
  NoSample = 3
};

/// The signed distance along the triangle's own normal n at which `side`
/// samples, `step` the step's length (0 at the centroid and for NoSample).
double sideShift(int side, double step, bool flip);

/// Each triangle's SurfaceSide: the first of the centroid, the centroid
/// moved by `step` along the flux's side of n, then the other way, where
/// `velocity` has one (`step` 0: the centroid only).
std::vector<int> surfaceSides(
  const std::vector<double>& triangles, const SurfaceVelocity& velocity, bool flip, double step);

/**
 * Each triangle's weight (9 coordinates a triangle in `triangles`):
 * fluxWeight at the velocity where its side (`sides`, SurfaceSide; empty:
 * surfaceSides with this `step`) samples, NoVelocity where `velocity` has
 * none there, 0 for a triangle with no area or a non-finite corner. With
 * `against`, also the weights the other way (fluxWeight with !flip, at the
 * same velocities: the flux against the normals counted).
 */
std::vector<double> surfaceWeights(const std::vector<double>& triangles,
  const SurfaceVelocity& velocity, bool flip, double step = 0.0, const std::vector<int>& sides = {},
  std::vector<double>* against = nullptr);

/// What a surface's weights say, for the messages.
struct SurfaceSummary
{
  std::size_t triangles = 0;  ///< triangles given
  std::size_t nonFinite = 0;  ///< with a corner not finite
  std::size_t noArea = 0;     ///< finite but of zero area
  std::size_t noVelocity = 0; ///< finite, with area, but no velocity at the centroid
  std::size_t crossing = 0;   ///< with weight above 0
  double area = 0.0;          ///< total area of the finite triangles
  double total = 0.0;         ///< total weight (the flux)
  /// The flux the other way, Σ max(0, ∓u · n) × area (from the weights
  /// with flip reversed; 0 where none are given).
  double against = 0.0;
};
/// `against`: the weights the other way (surfaceWeights' `against`), or empty.
SurfaceSummary summarizeSurface(const std::vector<double>& triangles,
  const std::vector<double>& weights, const std::vector<double>& against = {});

/// A flux against the normals above this many times the flux along them is
/// warned about (surfaceWarning): more than two thirds of the flux through
/// the surface crosses it the other way. A closed volume's boundary, where
/// inflow and outflow balance, stays below.
constexpr double AgainstFluxRatio = 2.0;

/// The warning about a surface most of whose flux crosses it against the
/// normals counted (s.against above AgainstFluxRatio × s.total), or empty.
std::string surfaceWarning(const SurfaceSummary& s, bool flip);

/**
 * Why nothing can be released from the surface `name` names ("the Seed
 * Source's surface"), or empty where something can: no triangle (no cells,
 * or only points and lines), none finite, none with area, none in the flow,
 * or no flux through it along its normals (`flip` says which way they were
 * taken, for the advice).
 */
std::string surfaceProblem(const SurfaceSummary& s, bool flip);

/// A uniform double in [0, 1) with 53 random bits: draw `draw` of point `point`.
double surfaceDraw(std::uint32_t seed, std::uint32_t point, std::uint32_t draw);

/// The point of `t` at the square-root barycentric draw (r1, r2 in [0, 1)):
/// s = √r1, (1 − s) a + s (1 − r2) b + s r2 c, uniform over the triangle.
std::array<double, 3> pointInTriangle(const double t[9], double r1, double r2);

/// The index i with cumulative[i − 1] ≤ r · total < cumulative[i] (the
/// running sums of weights ≥ 0, total their last), never one of weight 0;
/// cumulative.size() when total is not above 0.
std::size_t pickWeighted(const std::vector<double>& cumulative, double r);

/**
 * `count` points (3 doubles each) over the triangles, point i in the
 * triangle picked by draw 0 of point i in proportion to its weight (weights
 * below 0 count as 0), uniform in it by draws 1 and 2, then moved by
 * shifts[i] along the triangle's normal n (`shifts`: one per triangle,
 * sideShift of where its velocity was sampled, so the point starts in the
 * flow; empty: none). None where no weight is above 0.
 */
std::vector<double> drawSurfacePoints(const std::vector<double>& triangles,
  const std::vector<double>& weights, std::uint32_t seed, std::size_t count,
  const std::vector<double>& shifts = {});

} // namespace bp

#endif
