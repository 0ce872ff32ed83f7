// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ShapeMatching.h
 * @brief The rotation of an element's best rigid fit to its rest shape: the
 * one extraction that shape matching (Müller et al. 2005, Engine::matchShape)
 * and the pose fit (Pose.h) share, operation for operation the same in
 * Shaders/bp_common.glsl (bpFitRotation).
 *
 * Both want the rotation R that maximises tr(R^T A) for the moment matrix A =
 * sum (x_i - c)(q_i)^T (momentOf, Pose.h), warm-started from the element's
 * quaternion (x, y, z, w) of the iteration or step before. Damped Newton
 * steps turn a flat or long element about each axis by its own moment, so a
 * strip's roll about its long axis converges in a few steps, as its yaw
 * does. The fixed-point iteration of Müller, Bender, Chentanez and Macklin,
 * "A Robust Method to Extract the Rotational Part of Deformations" (2016),
 * which shape matching used before, turned it per step by its moment about
 * that axis over its whole moment: a Strip16 rolled late. Neither needs an
 * inverse of A, so flat elements (strips, crosses: A of rank 2) work. Far
 * from the fit (an element flipped by a strong shear) Newton's step would
 * climb to a saddle: there a turn about the gradient (the fixed-point
 * iteration's direction) by the angle that fits best about it takes its
 * place until Newton's step applies again, so the fit does not stall. Only
 * a start near a saddle itself, such as a strip turned half round its long
 * axis, leaves it slowly (as the fixed-point iteration did).
 */
#ifndef BoundParticles_ShapeMatching_h
#define BoundParticles_ShapeMatching_h

#include "Quaternion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bp
{

/// Iterations of the rotation fit per shape-matching iteration: from the fit
/// of the iteration before Newton's steps converge in one or two; the others
/// bring a cross or a paddlewheel started up to 170 degrees off closer than
/// the 8 fixed-point steps used before did (docs/engine-specification.md).
constexpr int MatchIterations = 4;

/// How far a Newton step of fitRotation is damped, as a fraction of the
/// element's whole moment: a turn about the axis of a line-like element
/// (whose moment about it is 0) is left alone rather than divided by 0.
constexpr float RotationDamping = 1.0e-3f;

/// The longest Newton step |w| (radians) fitRotation takes: a longer one
/// (H nearly singular, far from the fit) is cut to this length.
constexpr float MaxNewtonStep = 1.0f;

/// P = sum_c r_c a_c^T and g = sum_c r_c x a_c over the columns of R and A
/// (row-major): the fit's moment seen from R and its gradient.
inline void fitTerms(const float R[9], const float A[9], float P[9], float g[3])
{
  std::fill_n(P, 9, 0.0f);
  std::fill_n(g, 3, 0.0f);
  for (int c = 0; c < 3; ++c)
  {
    const float r[3] = { R[c], R[3 + c], R[6 + c] };
    const float a[3] = { A[c], A[3 + c], A[6 + c] };
    g[0] += r[1] * a[2] - r[2] * a[1];
    g[1] += r[2] * a[0] - r[0] * a[2];
    g[2] += r[0] * a[1] - r[1] * a[0];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        P[3 * i + j] += r[i] * a[j];
      }
    }
  }
}

/**
 * Newton's turn as the quaternion (w / 2, 1): w = H^-1 g with H = tr(P) I -
 * sym(P) (+ damping), solved by H's cofactors, cut to MaxNewtonStep. False
 * where H is not positive definite (the fit is more than about 90 degrees
 * away: Newton's step would climb to a saddle) or w is not finite.
 */
inline bool newtonTurn(const float P[9], const float g[3], float turn[4])
{
  const float trace = P[0] + P[4] + P[8];
  const float d = trace + RotationDamping * std::abs(trace);
  // H = d I - sym(P), symmetric.
  const float h00 = d - P[0], h11 = d - P[4], h22 = d - P[8];
  const float h01 = -0.5f * (P[1] + P[3]), h02 = -0.5f * (P[2] + P[6]), h12 = -0.5f * (P[5] + P[7]);
  const float c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
  const float c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
  const float det = h00 * c00 + h01 * c01 + h02 * c02;
  if (!(det > 0.0f && h00 > 0.0f && c22 > 0.0f)) // Sylvester's criterion
  {
    return false;
  }
  const float half = 0.5f / det;
  turn[0] = (c00 * g[0] + c01 * g[1] + c02 * g[2]) * half;
  turn[1] = (c01 * g[0] + c11 * g[1] + c12 * g[2]) * half;
  turn[2] = (c02 * g[0] + c12 * g[1] + c22 * g[2]) * half;
  turn[3] = 1.0f;
  const float w2 = turn[0] * turn[0] + turn[1] * turn[1] + turn[2] * turn[2];
  const float longest = 0.5f * MaxNewtonStep;
  if (!(w2 <= longest * longest))
  {
    if (!(w2 <= std::numeric_limits<float>::max()))
    {
      return false;
    }
    const float cut = longest / std::sqrt(w2);
    for (int k = 0; k < 3; ++k)
    {
      turn[k] = turn[k] * cut;
    }
  }
  return true;
}

/**
 * The turn about g by the angle that fits best about that axis, exactly: with
 * n = g / |g| the fit turned by t about n is tr(P) - n.Pn times cos t plus
 * |g| sin t plus n.Pn, whose maximum is at t = atan2(|g|, tr(P) - n.Pn). The
 * direction of Müller et al.'s fixed-point step (2016), which converges from
 * anywhere, with the step length that does not undershoot. False where g is 0
 * (or not finite): q is then a fit, or A is 0.
 */
inline bool axisTurn(const float P[9], const float g[3], float turn[4])
{
  const float g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  if (!(g2 > 0.0f && g2 <= std::numeric_limits<float>::max()))
  {
    return false;
  }
  const float length = std::sqrt(g2);
  float gPg = 0.0f;
  for (int i = 0; i < 3; ++i)
  {
    gPg += g[i] * (P[3 * i] * g[0] + P[3 * i + 1] * g[1] + P[3 * i + 2] * g[2]);
  }
  // Both arguments times |g|^2 > 0, which leaves the angle as it is.
  const float angle = std::atan2(length * g2, (P[0] + P[4] + P[8]) * g2 - gPg);
  const float s = std::sin(0.5f * angle) / length;
  turn[0] = g[0] * s;
  turn[1] = g[1] * s;
  turn[2] = g[2] * s;
  turn[3] = std::cos(0.5f * angle);
  return true;
}

/**
 * Turns q towards the rotation R closest to the row-major A (the maximum of
 * tr(R^T A)) by `iterations` steps, each Newton's (newtonTurn) where it
 * applies, else the best turn about the gradient (axisTurn). A zero (or
 * non-finite) A keeps q.
 */
inline void fitRotation(const float A[9], float q[4], int iterations)
{
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    float R[9], P[9], g[3], turn[4];
    quaternionToMatrix(q, R);
    fitTerms(R, A, P, g);
    if (!newtonTurn(P, g, turn) && !axisTurn(P, g, turn))
    {
      break;
    }
    turnQuaternion(turn, q);
  }
}

} // namespace bp

#endif
