// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ShapeMatching.h
 * @brief Best rigid fit of an element to its rest shape (Müller et al. 2005),
 * shared operation for operation by the CPU engine and Shaders/bp_match.frag.
 *
 * The rotation of the fit is extracted from the moment matrix A = sum (x_i -
 * c)(q_i)^T by the iteration of Müller, Bender, Chentanez and Macklin, "A
 * Robust Method to Extract the Rotational Part of Deformations" (2016). Unlike
 * a polar decomposition by Newton's method, it needs no inverse of A, so flat
 * elements (strips, crosses: A of rank 2) work. Each element keeps its
 * orientation as a quaternion (x, y, z, w) between steps as the warm start.
 * The goals, and the linear mode's blend, are Engine::matchShape's
 * (EngineStep.cpp); the pose fit (Pose.h) extracts its rotation by Newton
 * steps instead.
 */
#ifndef BoundParticles_ShapeMatching_h
#define BoundParticles_ShapeMatching_h

#include "Quaternion.h"

#include <cmath>

namespace bp
{

/// Iterations of the rotation extraction per restoration iteration.
constexpr int RotationIterations = 8;

/// Turns q towards the rotation closest to the row-major matrix A.
inline void extractRotation(const float A[9], float q[4])
{
  for (int iteration = 0; iteration < RotationIterations; ++iteration)
  {
    float R[9];
    quaternionToMatrix(q, R);
    // sum over columns c of R_c x A_c, and of R_c . A_c
    float num[3] = { 0, 0, 0 };
    float dot = 0;
    for (int c = 0; c < 3; ++c)
    {
      const float r[3] = { R[c], R[3 + c], R[6 + c] };
      const float a[3] = { A[c], A[3 + c], A[6 + c] };
      num[0] += r[1] * a[2] - r[2] * a[1];
      num[1] += r[2] * a[0] - r[0] * a[2];
      num[2] += r[0] * a[1] - r[1] * a[0];
      dot += r[0] * a[0] + r[1] * a[1] + r[2] * a[2];
    }
    const float den = std::abs(dot) + 1.0e-9f;
    const float omega[3] = { num[0] / den, num[1] / den, num[2] / den };
    const float angle = std::sqrt(omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]);
    if (!(angle >= 1.0e-9f))
    {
      break; // converged (or A is zero: keep the orientation)
    }
    const float s = std::sin(0.5f * angle) / angle, c = std::cos(0.5f * angle);
    const float d[4] = { omega[0] * s, omega[1] * s, omega[2] * s, c };
    turnQuaternion(d, q);
  }
}

} // namespace bp

#endif
