// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Quaternion.h
 * @brief Unit quaternions (x, y, z, w) and rotations: the one place the C++
 * code writes their maths (the engine's placement, shape matching, the pose
 * fit and spin). Shaders/bp_common.glsl repeats the product and the matrix
 * (bpQuaternionProduct, bpQuaternionRows) operation for operation.
 *
 * The inline functions fix the order of every float operation: both engines
 * and the parity tests depend on their bits, so rewrite them only together
 * with the shaders.
 */
#ifndef BoundParticles_Quaternion_h
#define BoundParticles_Quaternion_h

#include <array>
#include <cmath>

namespace bp
{

/// pi, for the rotations here and, as a float, the kernels' (BP_PI).
constexpr double Pi = 3.14159265358979323846;

/// alongFlowQuaternion's "against the flow": 1 + cos(angle) below this (within
/// 0.08 degrees of opposite), where a x d carries no direction. The kernels
/// get it as BP_ANTIPARALLEL_TOLERANCE (bp_reset.glsl).
constexpr float AntiparallelTolerance = 1e-6f;

/// out = r * q, the Hamilton product of (x, y, z, w) quaternions: q, then r.
/// `out` may not alias r or q.
inline void quaternionProduct(const float r[4], const float q[4], float out[4])
{
  out[0] = r[3] * q[0] + r[0] * q[3] + r[1] * q[2] - r[2] * q[1];
  out[1] = r[3] * q[1] - r[0] * q[2] + r[1] * q[3] + r[2] * q[0];
  out[2] = r[3] * q[2] + r[0] * q[1] - r[1] * q[0] + r[2] * q[3];
  out[3] = r[3] * q[3] - r[0] * q[0] - r[1] * q[1] - r[2] * q[2];
}

/// The product r * q of unit quaternions (x, y, z, w): q, then r.
inline std::array<float, 4> multiplyQuaternions(const float r[4], const std::array<float, 4>& q)
{
  std::array<float, 4> out;
  quaternionProduct(r, q.data(), out.data());
  return out;
}

/// q = d * q (Hamilton product), then normalised: q turned by d.
inline void turnQuaternion(const float d[4], float q[4])
{
  float n[4];
  quaternionProduct(d, q, n);
  const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
  for (int k = 0; k < 4; ++k)
  {
    q[k] = n[k] / length;
  }
}

/// Row-major rotation matrix of the unit quaternion (x, y, z, w).
inline void quaternionToMatrix(const float q[4], float R[9])
{
  const float x = q[0], y = q[1], z = q[2], w = q[3];
  R[0] = 1 - 2 * (y * y + z * z);
  R[1] = 2 * (x * y - w * z);
  R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);
  R[4] = 1 - 2 * (x * x + z * z);
  R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);
  R[7] = 2 * (y * z + w * x);
  R[8] = 1 - 2 * (x * x + y * y);
}

/// Row-major rotation R = Rz * Ry * Rx from angles in degrees about X, then Y, then Z.
std::array<float, 9> rotationFromDegrees(double x, double y, double z);

/// Shoemake's uniform random rotation from three uniforms in [0, 1), as the
/// unit quaternion (x, y, z, w).
std::array<float, 4> quaternionFromUniforms(float u1, float u2, float u3);

/// The unit quaternion (x, y, z, w) of a row-major rotation matrix.
std::array<float, 4> quaternionFromRotation(const std::array<float, 9>& R);

/// The rotation by 2 pi u about axis `axis` (0-2) after the rotation `first`,
/// as a unit quaternion: an in-plane orientation (Parameters::planeAxis).
std::array<float, 4> inPlaneQuaternion(int axis, float u, const std::array<float, 4>& first);

/**
 * Along Flow's orientation for a flow `v` at the release centre: the shortest
 * turn of the template's long axis (`axis`, longAxis() in ElementTemplate.h:
 * the x axis for the built-in shapes) as the frame leaves it onto v, after
 * the frame (row-major `frame`, as the quaternion `first`). On a flat field
 * (`planeAxis` >= 0) v's component along that axis is dropped, so the turn is
 * about it. Opposite directions turn by a half turn about the frame's z axis;
 * a zero or non-finite v keeps `first`.
 */
std::array<float, 4> alongFlowQuaternion(const float v[3], int planeAxis,
  const std::array<float, 9>& frame, const std::array<float, 3>& axis,
  const std::array<float, 4>& first);

} // namespace bp

#endif
