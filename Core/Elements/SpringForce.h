// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SpringForce.h
 * @brief The force of one spring, the one C++ definition (thesis eqs. 2.3-2.5).
 *
 * Every spring the engine restores goes through springForce(): an element's
 * own springs (Engine::restore: Jacobi, averaged Jacobi, Gauss-Seidel) and a
 * super set's links (Engine::restoreLinks). Its GLSL twin, bpSpringForce in
 * Shaders/bp_common.glsl, is the one the GPU engine's kernels use, operation
 * for operation the same.
 */
#ifndef BoundParticles_SpringForce_h
#define BoundParticles_SpringForce_h

#include <cmath>

namespace bp
{

/**
 * The force term of a spring of working rest length `rest` and stiffness
 * `stiffness` between the particles at pa and pb: f (pa - pb) with f =
 * stiffness (rest - |pa - pb|) / |pa - pb|, the whole correction that moves
 * end a away from end b (each end then takes its share). False, with `force`
 * untouched, where the ends coincide (or a length is not a number): the
 * spring has no direction to restore along.
 */
inline bool springForce(
  const float* pa, const float* pb, float rest, float stiffness, float force[3])
{
  const float d[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(len > 0.0f))
  {
    return false;
  }
  const float f = stiffness * (rest - len) / len;
  force[0] = f * d[0];
  force[1] = f * d[1];
  force[2] = f * d[2];
  return true;
}

} // namespace bp

#endif
