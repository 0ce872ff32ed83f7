// SPDX-License-Identifier: BSD-3-Clause
// Fields and systems that the core tests share.
#ifndef BoundParticles_TestHelpers_h
#define BoundParticles_TestHelpers_h

#include "AnalyticFlows.h"
#include "Engine.h"
#include "VectorField.h"

#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace bptest
{

inline bp::GridGeometry grid(int n, double lo = -1.0, double hi = 1.0, int nz = -1)
{
  bp::GridGeometry g;
  nz = nz < 0 ? n : nz;
  g.dims = { n, n, nz };
  g.origin = { lo, lo, nz > 1 ? lo : 0.0 };
  const double h = (hi - lo) / (n - 1);
  g.spacing = { h, h, nz > 1 ? (hi - lo) / (nz - 1) : 1.0 };
  return g;
}

inline bp::VectorField steadyFlow(bp::AnalyticFlow flow, const bp::GridGeometry& g)
{
  bp::FieldSlice s;
  s.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, 0.0));
  return bp::VectorField(g, s);
}

/// An unsteady field between the analytic flow sampled at t0 and at t1.
inline bp::VectorField unsteadyFlow(
  bp::AnalyticFlow flow, const bp::GridGeometry& g, double t0, double t1)
{
  bp::FieldSlice first, second;
  first.time = t0;
  first.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, t0));
  second.time = t1;
  second.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, t1));
  return bp::VectorField(g, first, second);
}

/// The uniform flow `u` on grid `g` (by default [-1, 1]^3, 9 points a side).
inline bp::VectorField uniformFlow(std::array<float, 3> u, const bp::GridGeometry& g = grid(9))
{
  auto velocity = std::make_shared<std::vector<float>>();
  for (std::size_t i = 0; i < g.pointCount(); ++i)
    velocity->insert(velocity->end(), u.begin(), u.end());
  bp::FieldSlice s;
  s.velocity = velocity;
  return bp::VectorField(g, s);
}

/// [-1, 1]^3 as a domain box, every axis with extent (grid(9)'s bounds).
inline bp::Domain cube()
{
  bp::Domain d;
  d.lower = { -1, -1, -1 };
  d.upper = { 1, 1, 1 };
  d.degenerate = { false, false, false };
  return d;
}

inline float distance(const float* a, const float* b)
{
  const float d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/// Largest |length / rest - 1| over every spring of every element.
inline double worstSpringStrain(const bp::Engine& engine)
{
  const std::size_t n = engine.particlesPerElement();
  const float size = engine.parameters().elementSize;
  double worst = 0.0;
  for (std::size_t e = 0; e < engine.elementCount(); ++e)
  {
    const float* p = engine.positions().data() + 3 * e * n;
    for (const bp::Spring& s : engine.shape().springs)
    {
      const double rest = s.restLength * size;
      worst = std::max(worst, std::abs(distance(p + 3 * s.a, p + 3 * s.b) / rest - 1.0));
    }
  }
  return worst;
}

} // namespace bptest

#endif
