// SPDX-License-Identifier: BSD-3-Clause
// The boundary (Parameters::boundary, engine specification "Boundaries") on
// both engines: with Terminate, elements the flow carries out through the
// grid's sides are hidden until their lifetime runs out, then placed again;
// the GPU engine's positions, hidden elements and generations against the
// CPU engine's, on the fragment path, the compute path and its fused step.
#include "AnalyticFlows.h"
#include "Engine.h"
#include "GpuStepper.h"
#include "SharedContext.h"
#include "Stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace
{
struct BoundaryCase
{
  bp::BuiltinShape shape;
  bp::Integrator integrator;
  bp::Restoration restoration;
  bp::ResetWhen resetWhen;
  bp::Boundary boundary = bp::Boundary::Terminate;
};

struct Counts
{
  int terminated = 0; ///< terminated elements seen, summed over the checks
  int replaced = 0;   ///< of those, placed again by the end
};

Counts compareEngines(const BoundaryCase& c)
{
  Counts counts;
  bp::GridGeometry g;
  g.dims = { 24, 24, 24 };
  g.origin = { -1.0, -1.0, -1.0 };
  g.spacing = { 2.0 / 23, 2.0 / 23, 2.0 / 23 };
  bp::FieldSlice s;
  s.velocity =
    std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(bp::AnalyticFlow::ABC, g, 0.0));
  const bp::VectorField field(g, s);
  bp::Parameters p;
  p.numberOfElements = 300;
  p.elementSize = 0.1f;
  p.emitterMin = { -0.9f, -0.9f, -0.9f };
  p.emitterMax = { 0.9f, 0.9f, 0.9f };
  p.lifetimeMin = 0.4f;
  p.lifetimeMax = 1.0f;
  p.integrator = c.integrator;
  p.restoration = c.restoration;
  p.iterations = 2;
  p.resetWhen = c.resetWhen;
  p.boundary = c.boundary;
  p.seed = 5;
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  bp::CpuStepper cpu(bp::serialRunner());
  bp::GpuStepper gpu;
  EXPECT_EQ(cpu.configure(shape, p), "");
  EXPECT_EQ(gpu.configure(shape, p), "");
  EXPECT_EQ(cpu.setField(field), "");
  EXPECT_EQ(gpu.setField(field), "");
  cpu.initialize(0.0);
  gpu.initialize(0.0);
  const double dt = 0.01;
  const std::size_t elements = p.numberOfElements;
  std::vector<std::uint32_t> terminatedAt(elements, 0); // a generation + 1; 0: none
  double worst = 0.0;
  int hiddenApart = 0, generationsApart = 0;
  for (int k = 0; k < 150; ++k)
  {
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
    if (k % 10 != 9)
      continue;
    const bp::Engine& E = cpu.engine();
    std::vector<float> x, generations, flags, hidden;
    gpu.engine().read(&x, nullptr, nullptr);
    gpu.engine().readElements(nullptr, &generations, nullptr, nullptr, &flags, &hidden);
    for (std::size_t q = 0; q < x.size(); ++q)
      worst = std::max(worst, double(std::abs(x[q] - E.positions()[q])));
    for (std::size_t e = 0; e < elements; ++e)
    {
      // The GPU's hidden: centre .w 1 (release window) or 2 (terminated),
      // or a test's flag of 2 (terminated in the last step).
      const bool gpuHidden = hidden[e] > 0.5f || flags[e] > 1.5f;
      const bool cpuHidden = (E.resetFlags()[e] & bp::HiddenFlags) != 0;
      hiddenApart += gpuHidden != cpuHidden;
      generationsApart += generations[e] != float(E.generations()[e]);
      if (E.resetFlags()[e] & bp::Terminated)
      {
        counts.terminated += terminatedAt[e] == 0;
        terminatedAt[e] = E.generations()[e] + 1;
      }
    }
  }
  for (std::size_t e = 0; e < elements; ++e)
    counts.replaced += terminatedAt[e] != 0 && cpu.engine().generations()[e] >= terminatedAt[e];
  std::printf("%s, integrator %d, restoration %d, reset when %d, boundary %d: positions within "
              "%.3g; %d terminated, %d placed again; %d hidden and %d generations apart\n",
    shape.name.c_str(), int(c.integrator), int(c.restoration), int(c.resetWhen), int(c.boundary),
    worst, counts.terminated, counts.replaced, hiddenApart, generationsApart);
  EXPECT_LT(worst, 1e-4 * g.diagonal());
  // An element on the edge of the field may leave on one engine only (the
  // engine specification's counted edge exception): at most 1%.
  EXPECT_LE(hiddenApart, int(elements / 100));
  EXPECT_EQ(generationsApart, 0);
  return counts;
}
} // namespace

TEST(GpuBoundary, TerminateMatchesTheCpuEngine)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using W = bp::ResetWhen;
  const BoundaryCase cases[] = {
    { bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, W::CenterLeaves },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, W::CenterLeaves },
    { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, W::AnyParticleLeaves },
    { bp::BuiltinShape::Paddlewheel, I::RK2, R::GaussSeidel, W::AnyParticleLeaves },
  };
  for (BoundaryCase c : cases)
  {
    c.boundary = bp::Boundary::Terminate;
    const Counts terminate = compareEngines(c);
    EXPECT_GT(terminate.terminated, 20);
    EXPECT_GT(terminate.replaced, 5);
    c.boundary = bp::Boundary::ReleaseAgain;
    EXPECT_EQ(compareEngines(c).terminated, 0);
  }
}
