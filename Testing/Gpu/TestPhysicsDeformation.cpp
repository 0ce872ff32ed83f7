// SPDX-License-Identifier: BSD-3-Clause
// Physics checks of ElementStretch and ElementFTLE (Core/Elements/ElementStretch.h), on
// the CPU engine and on the GPU engine: each engine's positions, lifetimes
// and generations (read back from the GPU) go through the one Core fit the
// output uses. A spring-free cross of six particles in a steady linear strain
// u = (a x, -a y, 0) is stretched by exp(a t) along x and squeezed by
// exp(-a t) along y: its FTLE is a. In solid-body rotation nothing stretches.
#include "AnalyticFlows.h"
#include "ElementStretch.h"
#include "Engine.h"
#include "GpuStepper.h"
#include "PhysicsSystem.h"
#include "SharedContext.h"
#include "Stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

namespace
{
/// The field u = (a x, -a y, 0) on a grid over `box` (trilinear sampling of a
/// linear field is exact), or solid-body rotation when a is 0.
bp::VectorField linearField(double a, std::array<double, 6> box)
{
  bp::GridGeometry g;
  g.dims = { 33, 33, 5 };
  for (int k = 0; k < 3; ++k)
  {
    g.origin[k] = box[2 * k];
    g.spacing[k] = (box[2 * k + 1] - box[2 * k]) / (g.dims[k] - 1);
  }
  bp::FieldSlice s;
  if (a == 0.0)
  {
    s.velocity = std::make_shared<std::vector<float>>(
      bp::sampleAnalyticFlow(bp::AnalyticFlow::SolidBodyRotation, g, 0.0));
    return bp::VectorField(g, s);
  }
  auto v = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        const double x = g.origin[0] + i * g.spacing[0], y = g.origin[1] + j * g.spacing[1];
        v->insert(v->end(), { float(a * x), float(-a * y), 0.0f });
      }
  s.velocity = v;
  return bp::VectorField(g, s);
}

/// A cross of six particles on the axes, with no springs: free tracers.
bp::ElementTemplate freeCross()
{
  return bp::makeTemplate("Cross6",
    { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } }, {}, {});
}

/// Each element's (largest stretch, smallest stretch, FTLE) after `steps`
/// RK4 steps of h in `field`, from the CPU or the GPU engine's state.
std::vector<std::array<float, 3>> deformation(bool gpu, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, int steps, double h)
{
  std::unique_ptr<bp::Stepper> stepper;
  bp::GpuStepper* g = nullptr;
  bp::CpuStepper* c = nullptr;
  if (gpu)
    stepper.reset(g = new bp::GpuStepper);
  else
    stepper.reset(c = new bp::CpuStepper(bp::serialRunner()));
  EXPECT_EQ(stepper->configure(shape, p), "");
  EXPECT_EQ(stepper->setField(field), "");
  stepper->initialize(0.0);
  for (int s = 0; s < steps; ++s)
    stepper->step(s * h, h);
  std::vector<float> x, lifetimes, generations, hidden;
  if (g)
  {
    g->engine().read(&x, nullptr, nullptr);
    g->engine().readElements(&lifetimes, &generations, nullptr, nullptr, nullptr, &hidden);
  }
  else
  {
    const bp::Engine& e = c->engine();
    x = e.positions();
    lifetimes = e.lifetimes();
    generations.assign(e.generations().begin(), e.generations().end());
    for (std::uint8_t f : e.resetFlags())
      hidden.push_back((f & bp::ReleaseHidden) ? 1.0f : 0.0f);
  }
  const bp::StretchFit fit(shape.rest, p.elementSize);
  const std::size_t n = shape.particleCount();
  std::vector<std::array<float, 3>> out;
  for (std::size_t e = 0; e < p.numberOfElements; ++e)
  {
    // The GPU engine holds element e at index e, each drawing as itself.
    const double age =
      double(bp::lifetimeDraw(p, std::uint32_t(e), std::uint32_t(generations[e]))) -
      double(lifetimes[e]);
    out.push_back(bp::elementDeformation(fit, x.data() + 3 * e * n, age, hidden[e] > 0.5f));
  }
  if (g)
    g->engine().release();
  return out;
}

bp::Parameters placed(std::size_t elements, float size, float reach)
{
  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = size;
  p.emitterMin = { -reach, -reach, -0.1f };
  p.emitterMax = { reach, reach, 0.1f };
  p.lifetimeMin = p.lifetimeMax = 10.0f;
  p.seed = 5;
  p.integrator = bp::Integrator::RK4;
  return p;
}

class Deformation : public bptest::OnEachEngine
{
};
} // namespace

// Linear strain at rate a: every free cross is stretched by exp(a t) and
// squeezed by exp(-a t); its FTLE is a, within 1%. Random orientations: the
// fit measures the flow, not how the element lies.
TEST_P(Deformation, LinearStrainStretchesFreeCrossesAtItsRate)
{
  const double a = 0.5, T = 2.0, h = 0.01;
  const bp::VectorField field = linearField(a, { -2, 2, -2, 2, -0.5, 0.5 });
  const bp::Parameters p = placed(30, 0.1f, 0.4f);
  const auto d = deformation(GetParam(), freeCross(), p, field, int(std::lround(T / h)), h);
  double worstFtle = 0.0, worstLarge = 0.0, worstSmall = 0.0;
  for (const auto& e : d)
  {
    worstFtle = std::max(worstFtle, std::abs(e[2] / a - 1.0));
    worstLarge = std::max(worstLarge, std::abs(e[0] / std::exp(a * T) - 1.0));
    worstSmall = std::max(worstSmall, std::abs(e[1] / std::exp(-a * T) - 1.0));
  }
  std::printf("%s: ElementFTLE within %.2e of a, stretches within %.2e of exp(aT) and %.2e of "
              "exp(-aT)\n",
    GetParam() ? "GPU" : "CPU", worstFtle, worstLarge, worstSmall);
  EXPECT_LT(worstFtle, 0.01);
  EXPECT_LT(worstLarge, 0.01);
  EXPECT_LT(worstSmall, 0.01);
}

// The built-in Cross with Restoration Iterations 0 (the tracer's way to free
// any template of its springs) is stretched as the free one: flat, it is
// measured in its own plane, here the plane of the strain.
TEST_P(Deformation, NoRestorationFreesABuiltinCross)
{
  const double a = 0.5, T = 2.0, h = 0.01;
  const bp::VectorField field = linearField(a, { -2, 2, -2, 2, -0.5, 0.5 });
  bp::Parameters p = placed(20, 0.1f, 0.4f);
  p.iterations = 0;
  p.orientation = bp::Orientation::Fixed;
  const auto d = deformation(
    GetParam(), bp::builtinTemplate(bp::BuiltinShape::Cross), p, field, int(std::lround(T / h)), h);
  for (const auto& e : d)
  {
    EXPECT_NEAR(e[2], a, 0.01 * a);
    EXPECT_NEAR(e[0], std::exp(a * T), 0.01 * std::exp(a * T));
  }
  // With its springs (more iterations, stiffer) the same cross gives way far
  // less: its FTLE measures how much the flow strains against the springs.
  p.iterations = 8;
  const auto stiff = deformation(
    GetParam(), bp::builtinTemplate(bp::BuiltinShape::Cross), p, field, int(std::lround(T / h)), h);
  double most = 0.0;
  for (const auto& e : stiff)
    most = std::max(most, double(e[2]));
  std::printf("%s: a stiff Cross's ElementFTLE is at most %.3f against the flow's %.3f\n",
    GetParam() ? "GPU" : "CPU", most, a);
  EXPECT_LT(most, 0.5 * a);
}

// Solid-body rotation turns elements without stretching them: FTLE about 0.
TEST_P(Deformation, SolidBodyRotationStretchesNothing)
{
  const double h = 0.01;
  const bp::VectorField field = linearField(0.0, { -1, 1, -1, 1, -1, 1 });
  const bp::Parameters p = placed(30, 0.1f, 0.5f);
  const auto d = deformation(GetParam(), freeCross(), p, field, 300, h);
  double worstFtle = 0.0, worstStretch = 0.0;
  for (const auto& e : d)
  {
    worstFtle = std::max(worstFtle, double(std::abs(e[2])));
    worstStretch =
      std::max({ worstStretch, std::abs(double(e[0]) - 1.0), std::abs(double(e[1]) - 1.0) });
  }
  std::printf("%s: solid rotation, |ElementFTLE| <= %.2e, stretches within %.2e of 1\n",
    GetParam() ? "GPU" : "CPU", worstFtle, worstStretch);
  EXPECT_LT(worstFtle, 2e-3); // the strain test's rate is 0.5
  EXPECT_LT(worstStretch, 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Engines, Deformation, ::testing::Values(false, true), bptest::engineName);
