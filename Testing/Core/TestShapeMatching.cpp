// SPDX-License-Identifier: BSD-3-Clause
// Tests of Core/Elements/ShapeMatching.h: fitRotation, the one rotation extraction of
// shape matching and the pose fit (both engines; the GPU twin's parity is in
// Testing/Gpu/TestGpuEngine.cpp).
#include "ElementTemplate.h"
#include "Pose.h"
#include "ShapeMatching.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// The quaternion of the rotation by `degrees` about the unit `axis`, then q.
std::array<float, 4> turned(const std::array<float, 4>& q, const double axis[3], double degrees)
{
  const double half = 0.5 * degrees * Pi / 180.0;
  const float r[4] = { float(axis[0] * std::sin(half)), float(axis[1] * std::sin(half)),
    float(axis[2] * std::sin(half)), float(std::cos(half)) };
  return bp::multiplyQuaternions(r, q);
}

/// The angle in degrees between the rotations q and r, from their quotient
/// in double (an arc cosine of q . r would lose the last bits of a float).
double degreesBetween(const float* q, const std::array<float, 4>& r)
{
  const double a[4] = { q[0], q[1], q[2], q[3] }, b[4] = { -r[0], -r[1], -r[2], r[3] };
  const double d[4] = { b[3] * a[0] + b[0] * a[3] + b[1] * a[2] - b[2] * a[1],
    b[3] * a[1] - b[0] * a[2] + b[1] * a[3] + b[2] * a[0],
    b[3] * a[2] + b[0] * a[1] - b[1] * a[0] + b[2] * a[3],
    b[3] * a[3] - b[0] * a[0] - b[1] * a[1] - b[2] * a[2] };
  return 2.0 * std::atan2(std::hypot(d[0], d[1], d[2]), std::abs(d[3])) * 180.0 / Pi;
}

/// The moment A of the shape's rest positions turned by `fit` (its exact fit).
void momentTurnedBy(const bp::ElementTemplate& shape, const std::array<float, 4>& fit, float A[9])
{
  float R[9];
  bp::quaternionToMatrix(fit.data(), R);
  std::vector<float> p;
  for (const auto& r : shape.rest)
  {
    for (int row = 0; row < 3; ++row)
    {
      p.push_back(R[3 * row] * r[0] + R[3 * row + 1] * r[1] + R[3 * row + 2] * r[2]);
    }
  }
  float c[3];
  bp::momentOf(p.data(), shape.particleCount(), shape.rest, 1.0f, c, A);
}

/// Iterations of fitRotation from `start` until within `degrees` of `fit` (at most 50).
int iterationsToFit(
  const float A[9], std::array<float, 4> start, const std::array<float, 4>& fit, double degrees)
{
  for (int k = 0; k < 50; ++k)
  {
    if (degreesBetween(start.data(), fit) < degrees)
    {
      return k;
    }
    bp::fitRotation(A, start.data(), 1);
  }
  return 50;
}

const double Oblique[3] = { 0.267261, 0.534522, 0.801784 }; // (1, 2, 3) / |(1, 2, 3)|
} // namespace

TEST(ShapeMatching, FitRotationConvergesFromFarAway)
{
  // Newton's step is refused this far off (its H is not positive definite):
  // the turns about the gradient bring the element within its reach. A long
  // element started far off about an oblique axis may instead come to rest
  // near its fit turned half round its long axis, a saddle of the fit that
  // holds every gradient method (the fixed-point iteration too), so it is
  // started at most 100 degrees off here.
  const std::array<float, 4> fit = bp::quaternionFromUniforms(0.3f, 0.6f, 0.8f);
  for (auto s : { bp::BuiltinShape::Cross, bp::BuiltinShape::Paddlewheel, bp::BuiltinShape::Strip16,
         bp::BuiltinShape::Fish })
  {
    const bp::ElementTemplate shape = bp::builtinTemplate(s);
    SCOPED_TRACE(shape.name);
    float A[9];
    momentTurnedBy(shape, fit, A);
    const bool compact = s == bp::BuiltinShape::Cross || s == bp::BuiltinShape::Paddlewheel;
    for (double degrees : { 60.0, 100.0, 140.0, 170.0 })
    {
      if (!compact && degrees > 100.0)
      {
        continue;
      }
      SCOPED_TRACE(degrees);
      std::array<float, 4> q = turned(fit, Oblique, degrees);
      bp::fitRotation(A, q.data(), 3 * bp::MatchIterations);
      EXPECT_LT(degreesBetween(q.data(), fit), 1e-3);
    }
  }
}

TEST(ShapeMatching, ALongElementRollsIntoItsFitNearlyAsFastAsItYaws)
{
  // Strip16's moment about its long axis (x) is a sixtieth of that about the
  // others. The fixed-point iteration shape matching used before turned it
  // by about that fraction of the way per step: from 20 degrees of roll it
  // took 584 steps to 0.001 degrees (3 from 20 degrees of yaw). Newton's
  // steps take 4 (1 for the yaw): each leaves about 6% of the roll, the
  // damping's share (RotationDamping) of the moment about the long axis.
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip16);
  const std::array<float, 4> fit = bp::quaternionFromUniforms(0.3f, 0.6f, 0.8f);
  float A[9], R[9];
  momentTurnedBy(shape, fit, A);
  bp::quaternionToMatrix(fit.data(), R);
  const double roll[3] = { R[0], R[3], R[6] }; // the fit's x axis
  const double yaw[3] = { R[2], R[5], R[8] };  // its normal
  for (double degrees : { 2.0, 20.0, 60.0 })
  {
    SCOPED_TRACE(degrees);
    EXPECT_LE(iterationsToFit(A, turned(fit, roll, degrees), fit, 1e-3), bp::MatchIterations + 1);
    EXPECT_LE(iterationsToFit(A, turned(fit, yaw, degrees), fit, 1e-3), 2);
  }
}

TEST(ShapeMatching, FitRotationKeepsTheFitAndAZeroMoment)
{
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const std::array<float, 4> fit = bp::quaternionFromUniforms(0.1f, 0.2f, 0.9f);
  float A[9];
  momentTurnedBy(shape, fit, A);
  std::array<float, 4> q = fit;
  bp::fitRotation(A, q.data(), bp::MatchIterations);
  EXPECT_LT(degreesBetween(q.data(), fit), 1e-3);
  const float zero[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  q = turned(fit, Oblique, 30.0);
  const std::array<float, 4> before = q;
  bp::fitRotation(zero, q.data(), bp::MatchIterations);
  EXPECT_EQ(q, before);
}
