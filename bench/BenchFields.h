// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BenchFields.h
 * @brief The fields and parameters the engine benchmarks share
 * (bench_engine.cpp, bench_threads.cpp): a res³ grid over [-1, 1]³ with the
 * steady shear layer and the unsteady double gyre (two time steps 100 apart).
 */
#ifndef BoundParticles_BenchFields_h
#define BoundParticles_BenchFields_h

#include "AnalyticFlows.h"
#include "EngineParameters.h"
#include "VectorField.h"

#include <memory>
#include <vector>

namespace bench
{
struct Fields
{
  double spacing;
  bp::VectorField steady, unsteady;
};

inline Fields benchFields(int resolution)
{
  bp::GridGeometry g;
  g.dims = { resolution, resolution, resolution };
  g.origin = { -1, -1, -1 };
  const double h = 2.0 / (resolution - 1);
  g.spacing = { h, h, h };
  auto slice = [&](bp::AnalyticFlow flow, double t)
  {
    bp::FieldSlice s;
    s.time = t;
    s.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, t));
    return s;
  };
  return { h, bp::VectorField(g, slice(bp::AnalyticFlow::ShearLayer, 0.0)),
    bp::VectorField(
      g, slice(bp::AnalyticFlow::DoubleGyre, 0.0), slice(bp::AnalyticFlow::DoubleGyre, 100.0)) };
}
/// The benchmarks' parameters: `elements` released over the whole field,
/// 0.05 in size, living 2 to 4 time units.
inline bp::Parameters parametersFor(const bp::VectorField& field, std::size_t elements)
{
  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = 0.05f;
  const auto b = field.grid().bounds();
  for (int a = 0; a < 3; ++a)
  {
    p.emitterMin[a] = float(b[2 * a]);
    p.emitterMax[a] = float(b[2 * a + 1]);
  }
  p.lifetimeMin = 2.0f;
  p.lifetimeMax = 4.0f;
  return p;
}
} // namespace bench

#endif
