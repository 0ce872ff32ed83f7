// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Pose.h
 * @brief An element's pose and spin: its rotation from the template by the
 * best rigid fit of its particles, and its angular velocity over a step.
 *
 * Shared operation for operation by the CPU engine (Engine::settle) and the
 * GPU engine's pose pass (Shaders/bp_pose.glsl). Every restoration method
 * gets a pose this way, not only shape matching: at the end of every step the
 * fit (fitRotation in ShapeMatching.h, the extraction shape matching uses,
 * warm-started from the pose of the step before) gives the new pose, and the
 * rotation from the old pose to the new one, divided by the step, gives the
 * spin. An element of one particle has no orientation: its pose stays the
 * identity and its spin zero.
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

/// Iterations of the pose fit per step (fitRotation): warm-started from
/// the pose one step before, two fit to float precision.
constexpr int PoseIterations = 2;

/// Turns `pose` (warm start: the pose before) to the best rigid fit of the
/// n particles `p` to the scaled rest shape (momentOf); writes their centre.
inline void fitPose(const float* p, std::size_t n, const std::vector<std::array<float, 3>>& rest,
  float size, float pose[4], float c[3])
{
  float A[9];
  momentOf(p, n, rest, size, c, A);
  fitRotation(A, pose, PoseIterations);
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
