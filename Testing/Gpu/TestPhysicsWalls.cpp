// SPDX-License-Identifier: BSD-3-Clause
// The field's boundary as a wall (Boundary Stick, Slip, Bounce; engine
// specification 2.8, "Walls") against the physics, on both engines: a heavy
// element dropped onto a floor under gravity sticks there at the analytic
// settling time and place; one that bounces rises to e^2 of its drop
// height; a strip carried across a channel onto a Slip wall lies down on it
// and slides along it at the flow's speed there, and stops on a Stick wall.
// A periodic box (Periodic, 2.8 "Periodic domains") brings every element
// back to its start after one period, its shape unchanged.
#include "Engine.h"
#include "PhysicsSystem.h"
#include "SharedContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

namespace
{
using bptest::System;

/// A steady field on `g` from u(x).
bp::VectorField fieldOf(
  const bp::GridGeometry& g, const std::function<std::array<float, 3>(double, double)>& u)
{
  auto velocity = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        const std::array<float, 3> v = u(g.coordinate(0, i), g.coordinate(1, j));
        velocity->insert(velocity->end(), v.begin(), v.end());
      }
  bp::FieldSlice s;
  s.velocity = velocity;
  return bp::VectorField(g, s);
}

bp::GridGeometry grid(std::array<int, 3> dims, std::array<double, 3> lo, std::array<double, 3> hi)
{
  bp::GridGeometry g;
  g.dims = dims;
  for (int a = 0; a < 3; ++a)
  {
    g.origin[a] = lo[a];
    g.spacing[a] = (hi[a] - lo[a]) / (dims[a] - 1);
  }
  return g;
}

/// Still fluid over [-1, 1]^3: the floor is z = -1.
bp::VectorField still()
{
  return fieldOf(grid({ 9, 9, 9 }, { -1, -1, -1 }, { 1, 1, 1 }),
    [](double, double) {
      return std::array<float, 3>{ 0, 0, 0 };
    });
}

bp::Parameters dropped(bp::Boundary boundary, float tau, std::array<float, 3> at)
{
  bp::Parameters p;
  p.numberOfElements = 1;
  p.elementSize = 0.05f;
  p.emitterMin = p.emitterMax = at;
  p.lifetimeMin = p.lifetimeMax = 1e6f;
  p.integrator = bp::Integrator::RK4;
  p.orientation = bp::Orientation::Fixed;
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = tau;
  p.densityRatio = 1000.0f;
  p.gravity = { 0, 0, -9.81f };
  p.boundary = boundary;
  return p;
}

class WallPhysics : public bptest::OnEachEngine
{
};
} // namespace

TEST_P(WallPhysics, AHeavyElementSticksToTheFloorAtTheSettlingTime)
{
  // A Square (in the x-y plane) released at rest at z = 0.5 settles 1.5 to
  // the floor in settlingTime (Inertia.h's analytic settling), lands there
  // with its x and y unchanged, and stays.
  const bp::VectorField field = still();
  const bp::Parameters p = dropped(bp::Boundary::Stick, 0.1f, { 0.25f, -0.25f, 0.5f });
  System s(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Square), p, field);
  const std::vector<float> start = s.positions();
  const double h = 0.002, arrival = bp::settlingTime(p, 1.5);
  int k = 0;
  std::vector<float> x = start;
  const auto allDown = [&x]()
  {
    for (std::size_t q = 2; q < x.size(); q += 3)
      if (x[q] != -1.0f)
        return false;
    return true;
  };
  for (; k < 5000 && !allDown(); ++k)
  {
    s.step(k * h, h);
    x = s.positions();
  }
  std::printf("%s: on the floor after %.4f, analytic %.4f\n", engine(), k * h, arrival);
  EXPECT_NEAR(k * h, arrival, h);
  for (std::size_t q = 0; q < x.size(); q += 3)
  {
    EXPECT_FLOAT_EQ(x[q], start[q]);
    EXPECT_FLOAT_EQ(x[q + 1], start[q + 1]);
  }
  for (int more = 0; more < 100; ++more)
    s.step((k + more) * h, h);
  EXPECT_EQ(s.positions(), x) << "held where it landed";
}

TEST_P(WallPhysics, ABounceRisesToTheSquareOfTheRestitution)
{
  // Nearly free fall (tau far above the flight): a particle dropped 1.5 onto
  // the floor leaves it with e times its speed and rises to e^2 of 1.5,
  // within a step's travel at the impact speed.
  const bp::VectorField field = still();
  for (float e : { 1.0f, 0.7f, 0.4f })
  {
    bp::Parameters p = dropped(bp::Boundary::Bounce, 1e4f, { 0, 0, 0.5f });
    p.restitution = e;
    System s(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Point), p, field);
    const double h = 0.001;
    bool bounced = false, rising = false;
    float apex = -1.0f, z = 0.5f;
    for (int k = 0; k < 3000; ++k)
    {
      s.step(k * h, h);
      const float now = s.positions()[2];
      bounced = bounced || s.slips()[2] > 0.0f;
      if (bounced)
      {
        if (rising && now < z)
          break; // past the apex
        rising = rising || now > z;
        apex = std::max(apex, now);
      }
      z = now;
    }
    const double speed = std::sqrt(2 * 9.81 * 1.5);
    std::printf("%s, restitution %.1f: rose to %.4f, e^2 of the drop %.4f\n", engine(), double(e),
      double(apex) + 1.0, double(e * e) * 1.5);
    EXPECT_TRUE(bounced);
    EXPECT_NEAR(apex + 1.0, e * e * 1.5, 2 * speed * h) << "restitution " << e;
  }
}

TEST_P(WallPhysics, AStripInAChannelSlidesAlongASlipWall)
{
  // A channel x in [-4, 4], y in [-1, 1]: u = 1.25 - y^2 / 4 along x (1 at
  // the walls), and a cross flow of -0.5 that carries a strip onto the wall
  // y = -1. With Slip the strip lies down on the wall, stays on its side
  // (every particle on y = -1) and slides along it at the flow's speed
  // there, 1; with Stick it stops.
  const bp::VectorField field = fieldOf(grid({ 33, 9, 3 }, { -4, -1, -0.5 }, { 4, 1, 0.5 }),
    [](double, double y) {
      return std::array<float, 3>{ float(1.25 - 0.25 * y * y), -0.5f, 0.0f };
    });
  for (bp::Boundary wall : { bp::Boundary::Slip, bp::Boundary::Stick })
  {
    bp::Parameters p;
    p.numberOfElements = 1;
    p.elementSize = 0.4f;
    p.emitterMin = p.emitterMax = { -3.5f, 0.0f, 0.0f };
    p.orientation = bp::Orientation::Fixed;
    // The strip's plane holds z and its length points at 45 degrees into
    // the wall: it meets the wall end first and turns to lie flat on it.
    const float c = std::sqrt(0.5f);
    p.frame = { c, 0, c, c, 0, -c, 0, 1, 0 };
    p.lifetimeMin = p.lifetimeMax = 1e6f;
    p.integrator = bp::Integrator::RK4;
    p.iterations = 4;
    p.boundary = wall;
    System s(GetParam(), bp::builtinTemplate(bp::BuiltinShape::Strip8), p, field);
    const double h = 0.01;
    const auto meanX = [](const std::vector<float>& x)
    {
      double m = 0;
      for (std::size_t q = 0; q < x.size(); q += 3)
        m += x[q];
      return m / double(x.size() / 3);
    };
    for (int k = 0; k < 300; ++k)
      s.step(k * h, h);
    const std::vector<float> first = s.positions();
    for (int k = 300; k < 500; ++k)
      s.step(k * h, h);
    const std::vector<float> last = s.positions();
    double highest = -1.0;
    for (std::size_t q = 1; q < last.size(); q += 3)
      highest = std::max(highest, double(last[q]));
    const double slid = meanX(last) - meanX(first);
    std::printf("%s, %s: particles up to y = %.5f, slid %.4f along the wall in 2\n", engine(),
      bp::enumName(wall), highest, slid);
    EXPECT_EQ(highest, -1.0) << "every particle on the wall's side, lying on it";
    if (wall == bp::Boundary::Slip)
      EXPECT_NEAR(slid, 2.0, 0.02);
    else
      EXPECT_EQ(slid, 0.0);
  }
}

TEST_P(WallPhysics, APeriodicBoxBringsEveryElementBackAfterOnePeriod)
{
  // A box [-1, 1]^3 periodic along every axis (period 2, its last planes
  // standing for its first) in the uniform flow (1, -0.5, 0.25): after
  // t = 8, one period along z, two along y and four along x, every particle
  // is back where it started (within the float steps' rounding), never
  // released, and the springs stayed at rest all the way across the seams.
  bp::GridGeometry g = grid({ 9, 9, 9 }, { -1, -1, -1 }, { 1, 1, 1 });
  g.periodic = { true, true, true };
  const bp::VectorField field = fieldOf(g,
    [](double, double) {
      return std::array<float, 3>{ 1.0f, -0.5f, 0.25f };
    });
  for (bp::BuiltinShape shape : { bp::BuiltinShape::Cross, bp::BuiltinShape::Strip8 })
  {
    bp::Parameters p;
    p.numberOfElements = 20;
    p.elementSize = 0.4f;
    p.emitterMin = { -0.9f, -0.9f, -0.9f };
    p.emitterMax = { 0.9f, 0.9f, 0.9f };
    p.lifetimeMin = p.lifetimeMax = 1e6f;
    p.integrator = bp::Integrator::RK4;
    p.iterations = 4;
    p.seed = 3;
    const bp::ElementTemplate t = bp::builtinTemplate(shape);
    System s(GetParam(), t, p, field);
    const double h = 0.02;
    s.step(0.0, h);
    const std::vector<float> start = s.positions();
    const std::size_t n = t.particleCount();
    // The largest change of any particle's offset from its element's first
    // particle: 0 for an element moved whole.
    double worstShape = 0.0, worstReturn = 0.0;
    int jumps = 0;
    std::vector<float> last = start;
    for (int k = 1; k <= 400; ++k)
    {
      s.step(k * h, h);
      const std::vector<float> x = s.positions();
      for (std::size_t e = 0; e < p.numberOfElements; ++e)
        for (std::size_t i = 0; i < n; ++i)
          for (int a = 0; a < 3; ++a)
          {
            const std::size_t q = 3 * (e * n + i) + a, o = 3 * e * n + a;
            worstShape =
              std::max(worstShape, double(std::abs((x[q] - x[o]) - (start[q] - start[o]))));
            jumps += i == 0 && std::abs(x[q] - last[q]) > 1.0f;
          }
      last = x;
    }
    for (std::size_t q = 0; q < start.size(); ++q)
      worstReturn = std::max(worstReturn, double(std::abs(last[q] - start[q])));
    const std::vector<float> flags = s.flags();
    std::printf("%s, %s: back within %.3g after one period, shape within %.3g, %d seam jumps\n",
      engine(), t.name.c_str(), worstReturn, worstShape, jumps);
    EXPECT_LT(worstReturn, 1e-3);
    EXPECT_LT(worstShape, 1e-3);
    EXPECT_GE(jumps, int(p.numberOfElements) * 7); // 4 + 2 + 1 seams each
    for (float f : flags)
      EXPECT_EQ(f, 0.0f) << "never released for leaving";
  }
}

INSTANTIATE_TEST_SUITE_P(Engines, WallPhysics, ::testing::Values(false, true), bptest::engineName);
