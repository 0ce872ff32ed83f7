// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Periodic.h
 * @brief Periodic axes (Periodic; engine specification 2.8, "Periodic
 * domains"): the period of a grid axis and the two rules both engines follow
 * (the GPU engine in Shaders/bp_common.glsl, bpWrapPeriodic and
 * bpPeriodicShift, with the same float operations).
 *
 * The period of a periodic axis is the grid's extent along it, upper - lower:
 * its last plane stands for its first (a copy of it), so the same rule holds
 * on uniform and rectilinear axes alike and the field needs no extra cell.
 *
 *  - Sampling (VectorField): a coordinate along a periodic axis is moved by
 *    whole periods into [lower, upper) before its cell is found, so a sample
 *    beyond a side (an integrator's stage, a particle of an element whose
 *    centre is still inside) reads the field across the seam.
 *  - Elements (the engines' settle): an element whose centre lies beyond a
 *    periodic side after a step moves whole by whole periods (periodicShift),
 *    every particle by the same shift, so its springs and shape are untouched.
 */
#ifndef BoundParticles_Periodic_h
#define BoundParticles_Periodic_h

#include <cmath>
#include <vector>

namespace bp
{

/// x moved by whole periods (upper - lower > 0) into [lower, upper). A
/// coordinate already in [lower, upper] is returned as it is (the upper side
/// is the lower one); NaN and infinities are returned as they are.
inline float wrapPeriodic(float x, float lower, float upper)
{
  if (!(x < lower || x > upper) || !std::isfinite(x))
  {
    return x;
  }
  const float period = upper - lower;
  float w = x - period * std::floor((x - lower) / period);
  // Rounding may leave w a hair outside: the two sides are one point.
  if (!(w >= lower) || !(w < upper))
  {
    w = lower;
  }
  return w;
}

/// The shift that moves an element whose centre is at c back into [lower,
/// upper] by whole periods: 0 while c is in it, otherwise -n (upper - lower)
/// with n = floor((c - lower) / (upper - lower)). 0 for NaN or infinite c.
inline float periodicShift(float c, float lower, float upper)
{
  if (!(c < lower || c > upper) || !std::isfinite(c))
  {
    return 0.0f;
  }
  const float period = upper - lower;
  return -std::floor((c - lower) / period) * period;
}

struct GridGeometry;

/**
 * How far the last plane of `velocity` (3 floats per grid point, x fastest)
 * along axis `a` lies from its first: the largest difference of a component
 * between matching points, as a share of the largest speed over the grid.
 * 0 where the last plane is a copy of the first, as the period rule above
 * assumes; 0 for a field at rest or an axis of one point. Data whose last
 * plane is one spacing short of the period (points at 0, h, ..., L - h)
 * shows here as the difference of two neighbouring planes.
 */
double periodicSeamMismatch(const GridGeometry& grid, const std::vector<float>& velocity, int a);

/// The same difference, not divided by the largest speed: a distributed run
/// takes the largest over its pieces (each holds the whole periodic axis)
/// and divides it by the whole field's largest speed.
double periodicSeamDifference(const GridGeometry& grid, const std::vector<float>& velocity, int a);

/// The largest finite speed of `velocity` (3 floats per point), as
/// periodicSeamMismatch divides by it.
double largestFiniteSpeed(const std::vector<float>& velocity);

} // namespace bp

#endif
