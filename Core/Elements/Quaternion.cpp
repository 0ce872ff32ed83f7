// SPDX-License-Identifier: BSD-3-Clause
// Rotations built from angles, uniforms, matrices and the flow: how the engine
// turns an element when it places it (Quaternion.h).
#include "Quaternion.h"
#include "EigenRows.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bp
{
std::array<float, 9> rotationFromDegrees(double x, double y, double z)
{
  const double d = Pi / 180.0;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(z * d, Eigen::Vector3d::UnitZ()) *
    Eigen::AngleAxisd(y * d, Eigen::Vector3d::UnitY()) *
    Eigen::AngleAxisd(x * d, Eigen::Vector3d::UnitX()))
                              .toRotationMatrix();
  return toRowMajor(r);
}

std::array<float, 4> quaternionFromUniforms(float u1, float u2, float u3)
{
  // Shoemake, "Uniform random rotations", Graphics Gems III (1992).
  const float s1 = std::sqrt(1.0f - u1), s2 = std::sqrt(u1);
  const float a = float(2.0 * Pi) * u2, b = float(2.0 * Pi) * u3;
  return { s1 * std::sin(a), s1 * std::cos(a), s2 * std::sin(b), s2 * std::cos(b) };
}

std::array<float, 4> inPlaneQuaternion(int axis, float u, const std::array<float, 4>& first)
{
  // r = (sin(a/2) e_axis, cos(a/2)), then the product r * first.
  const float half = float(Pi) * u;
  float r[4] = { 0, 0, 0, std::cos(half) };
  r[axis] = std::sin(half);
  return multiplyQuaternions(r, first);
}

std::array<float, 4> alongFlowQuaternion(const float v[3], int planeAxis,
  const std::array<float, 9>& frame, const std::array<float, 3>& axis,
  const std::array<float, 4>& first)
{
  float d[3] = { v[0], v[1], v[2] };
  if (planeAxis >= 0)
  {
    d[planeAxis] = 0.0f;
  }
  // Scaled by the largest component first, so that any unit of speed, however
  // small or large, normalises without underflow or overflow.
  const float m = std::max(std::max(std::abs(d[0]), std::abs(d[1])), std::abs(d[2]));
  if (!(m > 0.0f) || !(m <= std::numeric_limits<float>::max()))
  {
    return first;
  }
  d[0] = d[0] / m;
  d[1] = d[1] / m;
  d[2] = d[2] / m;
  const float inverse = 1.0f / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  d[0] = d[0] * inverse;
  d[1] = d[1] * inverse;
  d[2] = d[2] * inverse;
  // a = frame * axis, the long axis as the frame leaves it (exactly the
  // frame's first column for the x axis).
  float a[3];
  for (int k = 0; k < 3; ++k)
  {
    a[k] = frame[3 * k] * axis[0] + frame[3 * k + 1] * axis[1] + frame[3 * k + 2] * axis[2];
  }
  const float c = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
  float r[4];
  if (1.0f + c < AntiparallelTolerance)
  {
    // Against the flow (AntiparallelTolerance): a half turn about the frame's z axis (the plane's
    // normal on a flat field), which keeps a flat element in its plane.
    r[0] = frame[2];
    r[1] = frame[5];
    r[2] = frame[8];
    r[3] = 0.0f;
  }
  else
  {
    // (a x d, 1 + a.d), normalised: half the angle between a and d.
    r[0] = a[1] * d[2] - a[2] * d[1];
    r[1] = a[2] * d[0] - a[0] * d[2];
    r[2] = a[0] * d[1] - a[1] * d[0];
    r[3] = 1.0f + c;
    const float n = 1.0f / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    r[0] = r[0] * n;
    r[1] = r[1] * n;
    r[2] = r[2] * n;
    r[3] = r[3] * n;
  }
  return multiplyQuaternions(r, first);
}

std::array<float, 4> quaternionFromRotation(const std::array<float, 9>& R)
{
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m(i, j) = R[3 * i + j];
  const Eigen::Quaterniond q(m);
  return { float(q.x()), float(q.y()), float(q.z()), float(q.w()) };
}

} // namespace bp
