// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Pose.h
 * @brief An element's pose and spin: its rotation from the template by the
 * best rigid fit of its particles, and its angular velocity over a step.
 *
 * Shared operation for operation by the CPU engine (Engine::settle) and the
 * GPU engine's pose pass (Shaders/bp_pose.frag). Every restoration method
 * gets a pose this way, not only shape matching: at the end of every step the
 * fit (trackRotation's Newton steps, warm-started from the pose of the step
 * before) gives the new pose, and the rotation from the old pose to the
 * new one, divided by the step, gives the spin. An element of one particle
 * has no orientation: its pose stays the identity and its spin zero.
 */
#ifndef BoundParticles_Pose_h
#define BoundParticles_Pose_h

#include "Quaternion.h"
#include "ShapeMatching.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace bp
{

/// The clamp of SpinVorticityRatio: beyond it a reading says "much faster,
/// or against the flow" and no more (near-irrotational flow divides by little).
constexpr float MaxSpinVorticityRatio = 2.0f;

/// Below this |curl v| * h (radians of fluid rotation per step, twice the
/// parcel's) the fit cannot resolve a reading: the ratio there is 0.
constexpr float MinVorticityStep = 1.0e-4f;

/**
 * The centre c of n particles `p` (3 floats each), the float mean summed in
 * particle order, and their moment A = sum (x_i - c)(s r_i)^T against the
 * template's rest positions `rest` scaled by s = `size`, row-major: what
 * shape matching and the pose fit take the rotation of.
 */
inline void momentOf(const float* p, std::size_t n, const std::vector<std::array<float, 3>>& rest,
  float size, float c[3], float A[9])
{
  c[0] = c[1] = c[2] = 0.0f;
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[3 * i + k];
    }
  }
  const float count = float(n);
  for (int k = 0; k < 3; ++k)
  {
    c[k] = c[k] / count;
  }
  std::fill_n(A, 9, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    const float q[3] = { size * rest[i][0], size * rest[i][1], size * rest[i][2] };
    for (int row = 0; row < 3; ++row)
    {
      const float d = p[3 * i + row] - c[row];
      for (int col = 0; col < 3; ++col)
      {
        A[3 * row + col] += d * q[col];
      }
    }
  }
}

/// Iterations of the pose fit per step (trackRotation).
constexpr int PoseIterations = 2;

/// How far trackRotation's Newton step is damped, as a fraction of the
/// element's whole moment: a turn about the axis of a line-like element
/// (whose moment about it is 0) is left alone rather than divided by 0.
constexpr float PoseDamping = 1.0e-3f;

/**
 * Turns q towards the rotation R closest to A (the maximum of tr(R^T A)) by
 * Newton steps: with P = sum_c r_c a_c^T over the columns of R and A, the
 * turn w = H^-1 g, g = sum_c r_c x a_c, H = tr(P) I - sym(P) (+ damping),
 * applied as the quaternion (w / 2, 1), normalised. Unlike the fixed-point
 * step of extractRotation (g / tr(P)), it turns a flat or long element about
 * each axis by its own moment, so a strip's roll converges as fast as its
 * yaw; warm-started from the pose one step before, two steps fit to float
 * precision.
 */
inline void trackRotation(const float A[9], float q[4])
{
  for (int iteration = 0; iteration < PoseIterations; ++iteration)
  {
    float R[9];
    quaternionToMatrix(q, R);
    float g[3] = { 0, 0, 0 };
    float P[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
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
    const float trace = P[0] + P[4] + P[8];
    const float d = trace + PoseDamping * std::abs(trace);
    // H = d I - sym(P), symmetric: its cofactors solve H w = g.
    const float h00 = d - P[0], h11 = d - P[4], h22 = d - P[8];
    const float h01 = -0.5f * (P[1] + P[3]), h02 = -0.5f * (P[2] + P[6]),
                h12 = -0.5f * (P[5] + P[7]);
    const float c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22,
                c02 = h01 * h12 - h02 * h11;
    const float c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12,
                c22 = h00 * h11 - h01 * h01;
    const float det = h00 * c00 + h01 * c01 + h02 * c02;
    if (!(det > 0.0f))
    {
      break; // A is zero or far from q: keep the pose
    }
    const float half = 0.5f / det;
    const float w[3] = { (c00 * g[0] + c01 * g[1] + c02 * g[2]) * half,
      (c01 * g[0] + c11 * g[1] + c12 * g[2]) * half,
      (c02 * g[0] + c12 * g[1] + c22 * g[2]) * half };
    const float turn[4] = { w[0], w[1], w[2], 1.0f };
    turnQuaternion(turn, q);
  }
}

/// Turns `pose` (warm start: the pose before) to the best rigid fit of the
/// n particles `p` to the scaled rest shape (momentOf); writes their centre.
inline void fitPose(const float* p, std::size_t n, const std::vector<std::array<float, 3>>& rest,
  float size, float pose[4], float c[3])
{
  float A[9];
  momentOf(p, n, rest, size, c, A);
  trackRotation(A, pose);
}

/**
 * The angular velocity (world frame, radians per time unit) that turns
 * `before` into `after` in time h: the rotation d = after * conj(before),
 * taken the short way round (w >= 0), is angle 2 atan2(|d.xyz|, d.w) about
 * d.xyz / |d.xyz|.
 */
inline void spinBetween(const float before[4], const float after[4], float h, float spin[3])
{
  const float a[4] = { after[0], after[1], after[2], after[3] };
  const float b[4] = { -before[0], -before[1], -before[2], before[3] }; // conjugate
  float d[4];
  quaternionProduct(a, b, d);
  if (d[3] < 0.0f)
  {
    for (float& x : d)
    {
      x = -x;
    }
  }
  const float s = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const float rate = s > 0.0f ? 2.0f * std::atan2(s, d[3]) / (s * h) : 0.0f;
  for (int k = 0; k < 3; ++k)
  {
    spin[k] = d[k] * rate;
  }
}

/**
 * The "vorticity meter" reading: the spin's component along the vorticity
 * `curl` against half its magnitude, 2 (spin . curl) / |curl|^2; 1 turns with
 * the fluid, 0 not at all, -1 against it. 0 where |curl| * h is below
 * MinVorticityStep (or not finite); clamped to +-MaxSpinVorticityRatio.
 */
inline float spinVorticityRatio(const float spin[3], const float curl[3], float h)
{
  const float c2 = curl[0] * curl[0] + curl[1] * curl[1] + curl[2] * curl[2];
  const float floor = MinVorticityStep / h;
  if (!(c2 >= floor * floor))
  {
    return 0.0f;
  }
  const float ratio = 2.0f * (spin[0] * curl[0] + spin[1] * curl[1] + spin[2] * curl[2]) / c2;
  return std::fmax(-MaxSpinVorticityRatio, std::fmin(MaxSpinVorticityRatio, ratio));
}

} // namespace bp

#endif
