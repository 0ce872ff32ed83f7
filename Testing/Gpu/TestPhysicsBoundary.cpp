// SPDX-License-Identifier: BSD-3-Clause
// The boundary (Parameters::boundary, engine specification "Boundaries") on
// both engines: with Terminate, elements the flow carries out through the
// grid's sides are hidden until their lifetime runs out, then placed again;
// the GPU engine's positions, hidden elements and generations against the
// CPU engine's, on the fragment path, the compute path and its fused step.
// The Surfaces' Outlets (engine specification 2.10) the same way: elements
// whose centres cross an outlet half-plane in solid-body rotation end there
// on both engines; gates, and an outlet no element reaches, change nothing
// on the GPU, bit for bit. Its Walls too: a uniform flow onto a tilted plane
// and solid-body rotation onto a half-plane, with Slip, Bounce (heavy
// particles too), Release Again and Terminate; a wall no particle reaches
// changes nothing, bit for bit.
// With Periodic and trails, the Bound Particles display's own test of which
// trail poses to draw (bp_draw_vs_dec.glsl: bpNotInTrail, run here alone)
// against the CPU output's (trailPoses: generation, hidden, trailAcrossSeam).
#include "AnalyticFlows.h"
#include "BoundParticlesShaders.h"
#include "DomainMask.h"
#include "Engine.h"
#include "GpuStepper.h"
#include "MaskWalls.h"
#include "OutputArrays.h"
#include "ParticleLayout.h"
#include "ShaderSource.h"
#include "SharedContext.h"
#include "Stepper.h"
#include "Surfaces.h"

#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

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

/// The grid over [-1, 1]^3 with `points` points a side, every field's here.
bp::GridGeometry cubeGrid(int points)
{
  bp::GridGeometry g;
  g.dims = { points, points, points };
  g.origin = { -1.0, -1.0, -1.0 };
  const double h = 2.0 / (points - 1);
  g.spacing = { h, h, h };
  return g;
}

/// The boundary tests' common trace: 300 elements of size 0.1 released in
/// [-0.9, 0.9]^3 with lifetimes in [lifetimeMin, lifetimeMax], two iterations,
/// the case's shape, integrator, restoration and boundary.
bp::Parameters boundaryTrace(bp::Integrator integrator, bp::Restoration restoration,
  bp::Boundary boundary, float lifetimeMin, float lifetimeMax, unsigned seed)
{
  bp::Parameters p;
  p.numberOfElements = 300;
  p.elementSize = 0.1f;
  p.emitterMin = { -0.9f, -0.9f, -0.9f };
  p.emitterMax = { 0.9f, 0.9f, 0.9f };
  p.lifetimeMin = lifetimeMin;
  p.lifetimeMax = lifetimeMax;
  p.integrator = integrator;
  p.restoration = restoration;
  p.iterations = 2;
  p.boundary = boundary;
  p.seed = seed;
  return p;
}

/// Both engines configured with the same trace and field, at t = 0.
struct EnginePair
{
  bp::CpuStepper cpu{ bp::serialRunner() };
  bp::GpuStepper gpu;
  EnginePair(
    const bp::ElementTemplate& shape, const bp::Parameters& p, const bp::VectorField& field)
  {
    EXPECT_EQ(this->cpu.configure(shape, p), "");
    EXPECT_EQ(this->gpu.configure(shape, p), "");
    EXPECT_EQ(this->cpu.setField(field), "");
    EXPECT_EQ(this->gpu.setField(field), "");
    this->cpu.initialize(0.0);
    this->gpu.initialize(0.0);
  }
};

/// The GPU engine's state read back: positions, generations, flags, hidden
/// elements and, where asked, slip velocities.
struct GpuReadback
{
  std::vector<float> x, generations, flags, hidden, slips;

  GpuReadback(const bp::GpuStepper& gpu, bool withSlips = false)
  {
    gpu.engine().read(&this->x, nullptr, nullptr);
    gpu.engine().readElements(
      nullptr, &this->generations, nullptr, nullptr, &this->flags, &this->hidden);
    if (withSlips)
      gpu.engine().readSlips(this->slips);
  }
  /// The GPU's hidden: centre .w 1 (release window) or 2 (terminated), or a
  /// test's flag of 2 (terminated in the last step).
  bool hiddenAt(std::size_t e) const { return this->hidden[e] > 0.5f || this->flags[e] > 1.5f; }
};

/// The GPU engine against the CPU engine over a run's checks: per element,
/// whether its positions (and heavy particles' slips, times the step) were
/// ever further apart than 1e-4 of the diagonal of [-1, 1]^3 (every field
/// here), the largest difference of those never apart, and the generations
/// and hidden elements apart, summed over the checks.
struct Parity
{
  std::size_t n; ///< particles per element
  std::vector<std::uint8_t> apart;
  int generationsApart = 0, hiddenApart = 0;
  double worstKept = 0.0;

  Parity(std::size_t elements, std::size_t particlesPerElement)
    : n(particlesPerElement)
    , apart(elements, 0)
  {
  }

  /// Reads the GPU engine back (its slips too where `slipStep` > 0, weighed
  /// by it) and compares it with `cpu`; returns what it read.
  GpuReadback check(const bp::GpuStepper& gpu, const bp::Engine& cpu, double slipStep = 0.0)
  {
    const double tolerance = 1e-4 * 2.0 * std::sqrt(3.0);
    GpuReadback r(gpu, slipStep > 0.0);
    for (std::size_t e = 0; e < this->apart.size(); ++e)
    {
      double worst = 0.0;
      for (std::size_t q = 3 * e * this->n; q < 3 * (e + 1) * this->n; ++q)
      {
        worst = std::max(worst, double(std::abs(r.x[q] - cpu.positions()[q])));
        if (slipStep > 0.0)
          worst = std::max(worst, slipStep * double(std::abs(r.slips[q] - cpu.slips()[q])));
      }
      this->apart[e] = this->apart[e] || !(worst < tolerance);
      if (!this->apart[e])
        this->worstKept = std::max(this->worstKept, worst);
      this->generationsApart += r.generations[e] != float(cpu.generations()[e]);
      this->hiddenApart += r.hiddenAt(e) != ((cpu.resetFlags()[e] & bp::HiddenFlags) != 0);
    }
    return r;
  }

  long elementsApart() const
  {
    return std::count(this->apart.begin(), this->apart.end(), std::uint8_t(1));
  }

  /// At most 1% of the elements apart (one that meets a side, a seam, a wall
  /// or an outlet within a rounding of it on one engine only: the edge
  /// exception); at most `allowed` hidden elements and generations apart.
  void expectAgree(int allowed) const
  {
    EXPECT_LE(this->elementsApart(), long(this->apart.size() / 100)) << "elements apart";
    EXPECT_LE(this->hiddenApart, allowed) << "hidden elements apart";
    EXPECT_LE(this->generationsApart, allowed) << "generations apart";
  }
};

Counts compareEngines(const BoundaryCase& c)
{
  Counts counts;
  bp::GridGeometry g = cubeGrid(24);
  bp::FieldSlice s;
  s.velocity =
    std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(bp::AnalyticFlow::ABC, g, 0.0));
  const bp::VectorField field(g, s);
  bp::Parameters p = boundaryTrace(c.integrator, c.restoration, c.boundary, 0.4f, 1.0f, 5);
  p.resetWhen = c.resetWhen;
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  EnginePair engines(shape, p, field);
  bp::CpuStepper& cpu = engines.cpu;
  bp::GpuStepper& gpu = engines.gpu;
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
    const GpuReadback r(gpu);
    for (std::size_t q = 0; q < r.x.size(); ++q)
      worst = std::max(worst, double(std::abs(r.x[q] - E.positions()[q])));
    for (std::size_t e = 0; e < elements; ++e)
    {
      hiddenApart += r.hiddenAt(e) != ((E.resetFlags()[e] & bp::HiddenFlags) != 0);
      generationsApart += r.generations[e] != float(E.generations()[e]);
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

namespace
{
struct WallCase
{
  bp::BuiltinShape shape;
  bp::Integrator integrator;
  bp::Restoration restoration;
  bp::Boundary boundary;
  bool heavy = false;  ///< Maxey-Riley with gravity
  bool masked = false; ///< a block of cells outside the flow
  bool staircase = false; ///< with `masked`: a diagonal staircase of them instead
};

/// The ABC flow on [-1, 1]^3 (24 points a side), carrying elements to every
/// side; `masked`: the points with x > 0.5 and y > 0.5 NaN (outside), or
/// with `staircase` those with x + y > 0.5 (a diagonal of cell faces).
bp::VectorField wallField(bool masked, bool staircase = false)
{
  bp::GridGeometry g = cubeGrid(24);
  bp::FieldSlice s;
  auto velocity =
    std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(bp::AnalyticFlow::ABC, g, 0.0));
  if (masked)
  {
    for (int k = 0; k < 24; ++k)
      for (int j = 0; j < 24; ++j)
        for (int i = 0; i < 24; ++i)
          if (staircase ? g.coordinate(0, i) + g.coordinate(1, j) > 0.5
                        : g.coordinate(0, i) > 0.5 && g.coordinate(1, j) > 0.5)
            (*velocity)[3 * (std::size_t(i) + 24 * (std::size_t(j) + 24 * std::size_t(k)))] = NAN;
    s.outsideCells = bp::maskOutsidePoints(g, *velocity, nullptr).outsideCells;
  }
  s.velocity = velocity;
  return bp::VectorField(g, s);
}

/// Steps both engines 150 steps; returns how many particles the CPU engine
/// had within 0.02 of a side, summed over every tenth step (the walls are met). Positions (and
/// heavy particles' slips) agree within 1e-4 of the diagonal but for at most 1% of the elements
/// (one that meets a wall on one engine only, by a rounding: the edge exception), generations and
/// hidden elements exactly.
int compareWalls(const WallCase& c)
{
  const bp::VectorField field = wallField(c.masked, c.staircase);
  bp::Parameters p = boundaryTrace(c.integrator, c.restoration, c.boundary, 0.8f, 1.6f, 7);
  p.restitution = 0.6f;
  if (c.heavy)
  {
    p.inertia = bp::Inertia::MaxeyRiley;
    p.responseTime = 0.2f;
    p.densityRatio = 1000.0f;
    p.gravity = { 0, 0, -4.0f };
  }
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  EnginePair engines(shape, p, field);
  bp::CpuStepper& cpu = engines.cpu;
  bp::GpuStepper& gpu = engines.gpu;
  const double dt = 0.01;
  const std::size_t elements = p.numberOfElements, n = shape.particleCount();
  Parity parity(elements, n);
  int nearWall = 0, inCellOutside = 0, onFace = 0;
  for (int k = 0; k < 150; ++k)
  {
    const std::vector<float> last = cpu.engine().positions();
    const std::vector<std::uint32_t> lastGenerations = cpu.engine().generations();
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
    {
      // No step takes a particle into a cell outside the flow (MaskWalls.h;
      // one released into one, which the release test of the centre's cell
      // does not see, stays there: 2.8); the GPU engine's positions agree.
      const bp::Engine& E = cpu.engine();
      for (std::size_t q = 0; q < E.positions().size(); q += 3)
        inCellOutside += E.generations()[q / (3 * n)] == lastGenerations[q / (3 * n)] &&
            field.outsideCellAt(E.positions().data() + q, 0.0f) &&
            !field.outsideCellAt(last.data() + q, 0.0f)
          ? 1
          : 0;
    }
    if (k % 10 != 9)
      continue;
    const bp::Engine& E = cpu.engine();
    parity.check(gpu, E, c.heavy ? dt : 0.0);
    const bp::Domain& box = field.domain();
    for (std::size_t q = 0; q < E.positions().size(); q += 3)
      onFace +=
        bp::onOutsideFace(field, 0.0f, bp::surfaceWallOffset(box), E.positions().data() + q);
    for (std::size_t q = 0; q < E.positions().size(); ++q)
    {
      const float x = E.positions()[q];
      nearWall += std::min(x - box.lower[q % 3], box.upper[q % 3] - x) < 0.02f ? 1 : 0;
    }
  }
  const bp::Engine& E = cpu.engine();
  int onWall = 0, outside = 0;
  for (std::size_t q = 0; q < E.positions().size(); q += 3)
  {
    onWall += bp::onWall(field.domain(), E.positions().data() + q) ? 1 : 0;
    outside += field.domain().contains(E.positions().data() + q) ? 0 : 1;
  }
  std::printf("%s, integrator %d, restoration %d, boundary %d%s%s: positions within %.3g but for "
              "%ld elements; %d particles on a wall at the end, %d near one; %d hidden, %d "
              "generations apart; %d on a face of the cells outside the flow, %d in one\n",
    shape.name.c_str(), int(c.integrator), int(c.restoration), int(c.boundary),
    c.heavy ? ", heavy" : "", c.masked ? (c.staircase ? ", staircase" : ", masked") : "",
    parity.worstKept, parity.elementsApart(), onWall, nearWall, parity.hiddenApart,
    parity.generationsApart, onFace, inCellOutside);
  parity.expectAgree(0);
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(inCellOutside, 0);
  if (c.masked && c.boundary == bp::Boundary::Stick)
    EXPECT_GT(onFace, 20) << "Stick holds particles on the faces of the cells outside the flow";
  if (c.boundary == bp::Boundary::Stick)
    EXPECT_GT(onWall, 20) << "Stick holds particles on the walls";
  return nearWall;
}
} // namespace

TEST(GpuBoundary, WallsMatchTheCpuEngine)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using B = bp::Boundary;
  const WallCase cases[] = {
    { bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, B::Stick },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, B::Stick },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, B::Slip },
    { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, B::Bounce },
    { bp::BuiltinShape::Paddlewheel, I::RK2, R::GaussSeidel, B::Slip },
    { bp::BuiltinShape::Strip4, I::Euler, R::Jacobi, B::Bounce },
  };
  for (const WallCase& c : cases)
    EXPECT_GT(compareWalls(c), 100) << "the walls are met";
}

TEST(GpuBoundary, WallsMatchWithInertiaAndCellsOutsideTheFlow)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using B = bp::Boundary;
  const WallCase cases[] = {
    { bp::BuiltinShape::Point, I::RK4, R::AveragedJacobi, B::Stick, true },
    { bp::BuiltinShape::Strip8, I::RK2, R::AveragedJacobi, B::Slip, true },
    { bp::BuiltinShape::Cross, I::Euler, R::ShapeMatching, B::Bounce, true },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, B::Stick, false, true },
    { bp::BuiltinShape::Cross, I::RK2, R::GaussSeidel, B::Bounce, true, true },
  };
  for (const WallCase& c : cases)
    EXPECT_GT(compareWalls(c), 100) << "the walls are met";
}

TEST(GpuBoundary, WallsOfCellsOutsideTheFlowMatchTheCpuEngine)
{
  // A staircase of cells outside the flow: the particles meet its faces,
  // slide along them, bounce off them and are held on them on both engines
  // alike (MaskWalls.h, bp_common.glsl's bpWallOnOutsideCells).
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using B = bp::Boundary;
  const WallCase cases[] = {
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, B::Slip, false, true, true },
    { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, B::Bounce, false, true, true },
    { bp::BuiltinShape::Strip4, I::Euler, R::Jacobi, B::Stick, false, true, true },
    { bp::BuiltinShape::Paddlewheel, I::RK2, R::GaussSeidel, B::Slip, true, true, true },
  };
  for (const WallCase& c : cases)
    EXPECT_GT(compareWalls(c), 100) << "the walls are met";
}

namespace
{
/// A flow periodic in x and y over [-1, 1]^3 (24 points a side; its last x
/// and y planes repeat its first): elements cross the x and y seams again
/// and again and meet the z sides.
bp::VectorField periodicField()
{
  bp::GridGeometry g = cubeGrid(24);
  g.periodic = { true, true, false };
  auto velocity = std::make_shared<std::vector<float>>();
  for (int k = 0; k < 24; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i)
      {
        // cos(pi x) at x = -1 and x = 1 is the same value written twice.
        const double x = i == 23 ? -1.0 : g.coordinate(0, i);
        const double y = j == 23 ? -1.0 : g.coordinate(1, j), z = g.coordinate(2, k);
        velocity->insert(velocity->end(),
          { float(1.5 + 0.5 * std::sin(M_PI * y)), float(-1.0 + 0.6 * std::cos(M_PI * x)),
            float(0.4 * std::sin(M_PI * x) * std::cos(0.5 * M_PI * z)) });
      }
  bp::FieldSlice s;
  s.velocity = velocity;
  return bp::VectorField(g, s);
}

/// Both engines 150 steps on periodicField(); positions agree within 1e-4 of
/// the diagonal but for at most 1% of the elements (a centre on a seam may
/// cross it on one engine only: the edge exception), generations and hidden
/// elements exactly. Returns how many times the CPU engine's elements moved
/// across a seam (a centre that jumped by more than half a period).
int comparePeriodic(const BoundaryCase& c)
{
  const bp::VectorField field = periodicField();
  bp::Parameters p = boundaryTrace(c.integrator, c.restoration, c.boundary, 0.8f, 1.6f, 11);
  p.resetWhen = c.resetWhen;
  p.restitution = 0.6f;
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  EnginePair engines(shape, p, field);
  bp::CpuStepper& cpu = engines.cpu;
  bp::GpuStepper& gpu = engines.gpu;
  const double dt = 0.01;
  const std::size_t elements = p.numberOfElements, n = shape.particleCount();
  Parity parity(elements, n);
  std::vector<float> centres(3 * elements, 0.0f);
  int crossings = 0;
  for (int k = 0; k < 150; ++k)
  {
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
    const bp::Engine& E = cpu.engine();
    for (std::size_t e = 0; e < elements; ++e)
    {
      float centre[3] = { 0, 0, 0 };
      for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a)
          centre[a] += E.positions()[3 * (e * n + i) + a] / float(n);
      for (int a = 0; a < 2; ++a)
      {
        crossings += k > 0 && std::abs(centre[a] - centres[3 * e + a]) > 1.0f;
        centres[3 * e + a] = centre[a];
      }
    }
    if (k % 10 == 9)
      parity.check(gpu, E);
  }
  std::printf("%s, integrator %d, restoration %d, reset when %d, boundary %d, periodic x and y: "
              "positions within %.3g but for %ld elements; %d seam crossings; %d hidden, %d "
              "generations apart\n",
    shape.name.c_str(), int(c.integrator), int(c.restoration), int(c.resetWhen), int(c.boundary),
    parity.worstKept, parity.elementsApart(), crossings, parity.hiddenApart,
    parity.generationsApart);
  parity.expectAgree(0);
  return crossings;
}
} // namespace

TEST(GpuBoundary, PeriodicMatchesTheCpuEngine)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using W = bp::ResetWhen;
  using B = bp::Boundary;
  const BoundaryCase cases[] = {
    { bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, W::CenterLeaves, B::ReleaseAgain },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, W::AnyParticleLeaves, B::ReleaseAgain },
    { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, W::CenterLeaves, B::Bounce },
    { bp::BuiltinShape::Paddlewheel, I::RK2, R::GaussSeidel, W::CenterLeaves, B::Slip },
    { bp::BuiltinShape::Strip4, I::RK4, R::Jacobi, W::AnyParticleLeaves, B::Terminate },
  };
  for (const BoundaryCase& c : cases)
    EXPECT_GT(comparePeriodic(c), 100) << "the seams are crossed";
}

namespace
{
/// Solid-body rotation about z (unit angular velocity) on [-1, 1]^3, 24
/// points a side.
bp::VectorField rotationField()
{
  bp::GridGeometry g = cubeGrid(24);
  bp::FieldSlice s;
  s.velocity = std::make_shared<std::vector<float>>(
    bp::sampleAnalyticFlow(bp::AnalyticFlow::SolidBodyRotation, g, 0.0));
  return bp::VectorField(g, s);
}

/// The half-plane y = 0, x in [0, 1], z in [-1, 1] cut into 16 x 12
/// squares, two triangles each (384: two rows of the GPU's outlet texture),
/// as an Outlet; with `gate` also the half-plane x = 0, y in [0, 1] as a
/// Gate. `shift` moves the outlet along z (out of every element's way).
std::shared_ptr<const bp::SurfaceSet> outletHalfPlane(bool gate, float shift = 0.0f)
{
  bp::SurfaceTriangles t;
  auto add = [&](const float* corners, bp::SurfaceInteraction kind, int surface)
  {
    t.corners.insert(t.corners.end(), corners, corners + 9);
    t.surfaces.push_back(surface);
    t.interaction.push_back(kind);
    t.cells.push_back(std::int32_t(t.cells.size()));
  };
  const int nx = 16, nz = 12;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i)
    {
      const float x0 = float(i) / nx, x1 = float(i + 1) / nx;
      const float z0 = shift - 1.0f + 2.0f * float(k) / nz;
      const float z1 = shift - 1.0f + 2.0f * float(k + 1) / nz;
      const float a[9] = { x0, 0, z0, x1, 0, z0, x1, 0, z1 };
      const float b[9] = { x0, 0, z0, x1, 0, z1, x0, 0, z1 };
      add(a, bp::SurfaceInteraction::Outlet, 0);
      add(b, bp::SurfaceInteraction::Outlet, 0);
    }
  if (gate)
  {
    const float a[9] = { 0, 0, -1, 0, 1, -1, 0, 1, 1 };
    const float b[9] = { 0, 0, -1, 0, 1, 1, 0, 0, 1 };
    add(a, bp::SurfaceInteraction::Gate, 1);
    add(b, bp::SurfaceInteraction::Gate, 1);
  }
  return std::make_shared<const bp::SurfaceSet>(t);
}

/// Both engines 150 steps in rotationField() through outletHalfPlane(true):
/// positions agree within 1e-4 of the diagonal but for at most 1% of the
/// elements, hidden elements and generations but for at most 1% (a centre
/// that crosses an outlet's plane within a rounding of it, or of a side, on
/// one engine only: the edge exception). Returns how many elements the CPU
/// engine terminated at the outlet.
int compareOutlets(const BoundaryCase& c)
{
  const bp::VectorField field = rotationField();
  bp::Parameters p = boundaryTrace(c.integrator, c.restoration, c.boundary, 0.4f, 1.0f, 13);
  p.resetWhen = c.resetWhen;
  p.restitution = 0.6f;
  p.surfaces = outletHalfPlane(true);
  EXPECT_EQ(p.surfaces->outletCorners().size(), 9u * 384u);
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  EnginePair engines(shape, p, field);
  bp::CpuStepper& cpu = engines.cpu;
  bp::GpuStepper& gpu = engines.gpu;
  const double dt = 0.01;
  const std::size_t elements = p.numberOfElements;
  Parity parity(elements, shape.particleCount());
  int terminated = 0;
  for (int k = 0; k < 150; ++k)
  {
    const std::vector<std::uint8_t> flagsBefore = cpu.engine().resetFlags();
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
    const bp::Engine& E = cpu.engine();
    for (std::size_t e = 0; e < elements; ++e)
    {
      // Terminated in this step: at the outlet where the boundary is not
      // Terminate (a wall, or Release Again); counted at once for Terminate.
      terminated += (E.resetFlags()[e] & bp::Terminated) && !(flagsBefore[e] & bp::Terminated);
    }
    if (k % 10 == 9)
      parity.check(gpu, E);
  }
  std::printf("%s, integrator %d, restoration %d, reset when %d, boundary %d, an outlet: "
              "positions within %.3g but for %ld elements; %d terminated; %d hidden, %d "
              "generations apart\n",
    shape.name.c_str(), int(c.integrator), int(c.restoration), int(c.resetWhen), int(c.boundary),
    parity.worstKept, parity.elementsApart(), terminated, parity.hiddenApart,
    parity.generationsApart);
  parity.expectAgree(int(elements / 100));
  return terminated;
}

/// The GPU engine's positions, generations, flags and hidden elements after
/// 60 steps in rotationField() with `surfaces` and the boundary `boundary`.
std::vector<float> gpuTrace(const bp::ElementTemplate& shape,
  std::shared_ptr<const bp::SurfaceSet> surfaces, bp::Boundary boundary = bp::Boundary::Terminate)
{
  bp::Parameters p =
    boundaryTrace(bp::Integrator::RK4, bp::Restoration::AveragedJacobi, boundary, 0.2f, 0.5f, 13);
  p.surfaces = std::move(surfaces);
  bp::GpuStepper gpu;
  EXPECT_EQ(gpu.configure(shape, p), "");
  EXPECT_EQ(gpu.setField(rotationField()), "");
  gpu.initialize(0.0);
  for (int k = 0; k < 60; ++k)
    gpu.step(k * 0.01, 0.01);
  GpuReadback r(gpu);
  for (const std::vector<float>* v : { &r.generations, &r.flags, &r.hidden })
    r.x.insert(r.x.end(), v->begin(), v->end());
  return r.x;
}
} // namespace

TEST(GpuBoundary, OutletsMatchTheCpuEngine)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using W = bp::ResetWhen;
  using B = bp::Boundary;
  const BoundaryCase cases[] = {
    { bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, W::CenterLeaves, B::ReleaseAgain },
    { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, W::CenterLeaves, B::Terminate },
    { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, W::AnyParticleLeaves, B::Slip },
    { bp::BuiltinShape::Paddlewheel, I::RK2, R::GaussSeidel, W::AnyParticleLeaves,
      B::ReleaseAgain },
  };
  for (const BoundaryCase& c : cases)
    EXPECT_GT(compareOutlets(c), 20) << "elements end at the outlet";
}

TEST(GpuBoundary, GatesAndAnOutletOutOfTheWayChangeNothing)
{
  // Gates are not on the GPU at all; an outlet that no element reaches (the
  // half-plane moved 10 along z) runs the outlet test and changes no bit.
  ASSERT_TRUE(bp::haveSharedContext());
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip8);
  const std::vector<float> none = gpuTrace(shape, nullptr);
  bp::SurfaceTriangles gates;
  gates.corners = { 0, 0, -1, 1, 0, -1, 1, 0, 1 };
  gates.interaction = { bp::SurfaceInteraction::Gate };
  const std::vector<float> withGates = gpuTrace(shape, std::make_shared<bp::SurfaceSet>(gates));
  const std::vector<float> outOfTheWay = gpuTrace(shape, outletHalfPlane(false, 10.0f));
  ASSERT_EQ(withGates.size(), none.size());
  ASSERT_EQ(outOfTheWay.size(), none.size());
  long differ = 0;
  for (std::size_t k = 0; k < none.size(); ++k)
    differ += (withGates[k] != none[k]) + (outOfTheWay[k] != none[k]);
  EXPECT_EQ(differ, 0);
  // Some left the field meanwhile (Terminate): the flags are compared too.
  long hidden = 0;
  for (std::size_t k = none.size() - 300; k < none.size(); ++k)
    hidden += none[k] > 0.5f;
  std::printf(
    "surfaces that end nothing: %ld values apart; %ld of 300 elements hidden\n", differ, hidden);
}

namespace
{
/// What the GPU engine's configure says to `limit` + 1 triangles of `kind`
/// under the boundary `boundary`.
std::string configureMoreThan(std::size_t limit, bp::SurfaceInteraction kind, bp::Boundary boundary)
{
  bp::SurfaceTriangles t;
  for (std::size_t k = 0; k <= limit; ++k)
  {
    const float x = float(k) / float(limit);
    t.corners.insert(t.corners.end(), { x, 0, 0, x, 1, 0, x, 0, 1 });
  }
  t.interaction.assign(limit + 1, kind);
  bp::Parameters p =
    boundaryTrace(bp::Integrator::Euler, bp::Restoration::AveragedJacobi, boundary, 1, 1, 1);
  p.surfaces = std::make_shared<bp::SurfaceSet>(t);
  bp::GpuStepper gpu;
  return gpu.configure(bp::builtinTemplate(bp::BuiltinShape::Point), p);
}
} // namespace

TEST(GpuBoundary, RefusesMoreOutletTrianglesThanItTests)
{
  ASSERT_TRUE(bp::haveSharedContext());
  const std::string error = configureMoreThan(
    bp::GpuMaxOutletTriangles, bp::SurfaceInteraction::Outlet, bp::Boundary::ReleaseAgain);
  EXPECT_NE(error.find("4097 Outlet triangles"), std::string::npos) << error;
  EXPECT_EQ(bp::gpuOutletError(bp::GpuMaxOutletTriangles), "");
}

namespace
{
/// The draw shader's declarations (bp_draw_vs_dec.glsl, as the display
/// compiles them) under a vertex shader of their own: vertex e writes 1
/// where the display draws element e's pose in the trail slot bound, else 0
/// (bpHiddenElement or bpNotInTrail, as bp_draw_vs_impl.glsl clips it), by
/// transform feedback.
class TrailPoseProbe
{
public:
  TrailPoseProbe()
  {
    const std::string vs = "#version 330 core\n" + bp::colorSourceDefinitions() +
      bp::engineConstantDefinitions() + bpShaderDrawVSDec +
      "\nout float bpShown;\nvoid main()\n{\n  bpShown = bpHiddenElement(gl_VertexID) || "
      "bpNotInTrail(gl_VertexID) ? 0.0 : 1.0;\n  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);\n}\n";
    const char* source = vs.c_str();
    const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    char log[4096] = "";
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    EXPECT_TRUE(ok) << log;
    this->Program = glCreateProgram();
    glAttachShader(this->Program, shader);
    const char* varying = "bpShown";
    glTransformFeedbackVaryings(this->Program, 1, &varying, GL_INTERLEAVED_ATTRIBS);
    glLinkProgram(this->Program);
    glGetProgramiv(this->Program, GL_LINK_STATUS, &ok);
    glGetProgramInfoLog(this->Program, sizeof(log), nullptr, log);
    EXPECT_TRUE(ok) << log;
    glDeleteShader(shader);
    glGenVertexArrays(1, &this->Array);
    glGenBuffers(1, &this->Buffer);
  }
  ~TrailPoseProbe()
  {
    glDeleteBuffers(1, &this->Buffer);
    glDeleteVertexArrays(1, &this->Array);
    glDeleteProgram(this->Program);
  }

  /// Per element, whether the display draws its pose in `slot`.
  std::vector<float> shown(
    const bp::GpuEngine::DrawInputs& d, const bp::GpuEngine::DrawInputs::TrailSlot& slot)
  {
    glUseProgram(this->Program);
    const std::pair<const char*, GLuint> textures[] = { { "bpPositions", d.positions },
      { "bpElements", d.elements }, { "bpCenters", d.centers },
      { "bpTrailPositions", slot.positions }, { "bpTrailElements", slot.elements } };
    for (GLint unit = 0; unit < 5; ++unit)
    {
      glActiveTexture(GLenum(GL_TEXTURE0 + unit));
      glBindTexture(GL_TEXTURE_2D, textures[unit].second);
      glUniform1i(glGetUniformLocation(this->Program, textures[unit].first), unit);
    }
    glActiveTexture(GL_TEXTURE0);
    glUniform2i(
      glGetUniformLocation(this->Program, "bpElementGrid"), d.elementGrid[0], d.elementGrid[1]);
    glUniform1i(glGetUniformLocation(this->Program, "bpBlocksPerRow"), d.blocksPerRow);
    glUniform3fv(glGetUniformLocation(this->Program, "bpTrailHalfPeriods"), 1, d.trailHalfPeriods);
    glUniform1i(glGetUniformLocation(this->Program, "bpTrail"), 1);
    const GLsizeiptr bytes = GLsizeiptr(sizeof(float)) * d.elementCount;
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, this->Buffer);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, this->Buffer);
    glBindVertexArray(this->Array);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, d.elementCount);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    std::vector<float> out(std::size_t(d.elementCount), -1.0f);
    glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, bytes, out.data());
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindVertexArray(0);
    glUseProgram(0);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return out;
  }

private:
  GLuint Program = 0, Array = 0, Buffer = 0;
};
} // namespace

TEST(GpuBoundary, PeriodicTrailsBreakAtTheSeamAsOnTheCpu)
{
  // periodicField() (x and y periodic, period 2), a trail of 6 poses every
  // 4 steps: after each step from the trail's fill on, every slot's poses
  // the display draws against those the CPU output shows, for every element
  // whose positions agree on both engines (a centre on a seam may cross it
  // on one engine only: comparePeriodic's edge exception).
  ASSERT_TRUE(bp::haveSharedContext());
  const bp::VectorField field = periodicField();
  bp::Parameters p = boundaryTrace(
    bp::Integrator::RK4, bp::Restoration::Jacobi, bp::Boundary::ReleaseAgain, 0.8f, 1.6f, 11);
  p.trailLength = 6;
  p.trailInterval = 0.04;
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip4);
  EnginePair engines(shape, p, field);
  TrailPoseProbe probe;
  const double dt = 0.01;
  const std::size_t E = p.numberOfElements, n = shape.particleCount();
  const double tolerance = 1e-4 * 2.0 * std::sqrt(3.0);
  int shown = 0, across = 0, apart = 0, skipped = 0;
  for (int k = 0; k < 120; ++k)
  {
    engines.cpu.step(k * dt, dt);
    engines.gpu.step(k * dt, dt);
    if (k < 24 || k % 3 != 0)
      continue;
    const bp::Engine& cpu = engines.cpu.engine();
    const bp::GpuEngine::DrawInputs d = engines.gpu.engine().drawInputs();
    ASSERT_EQ(d.trail.size(), std::size_t(p.trailLength));
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(d.trailHalfPeriods[a], a < 2 ? 1.0f : 0.0f) << "axis " << a;
    std::vector<float> x;
    engines.gpu.engine().read(&x, nullptr, nullptr);
    std::vector<std::uint8_t> agree(E, 1);
    for (std::size_t q = 0; q < x.size(); ++q)
      agree[q / (3 * n)] &= std::abs(x[q] - cpu.positions()[q]) < tolerance;
    const double now = (k + 1) * dt;
    for (int s = 0; s < p.trailLength; ++s)
    {
      const std::size_t slot = std::size_t(cpu.trailSlot(s));
      ASSERT_EQ(d.trail[std::size_t(s)].time, cpu.trailTimes()[slot]);
      if (!(cpu.trailTimes()[slot] < now))
        continue;
      const std::vector<float> gpu = probe.shown(d, d.trail[std::size_t(s)]);
      for (std::size_t e = 0; e < E; ++e)
      {
        // TracerOutputArrays.cxx: trailPoses, pose by pose.
        const bool generation = cpu.trailGenerations()[slot * E + e] == cpu.generations()[e];
        const bool seam = cpu.trailAcrossSeam(slot, e, field);
        const bool cpuShown = generation && !(cpu.resetFlags()[e] & bp::HiddenFlags) && !seam;
        if (!agree[e])
        {
          ++skipped;
          continue;
        }
        apart += (gpu[e] > 0.5f) != cpuShown;
        shown += cpuShown;
        across += generation && seam;
      }
    }
  }
  std::printf("periodic trails: %d poses shown, %d across a seam left out, %d apart; %d poses "
              "of elements apart skipped\n",
    shown, across, apart, skipped);
  EXPECT_EQ(apart, 0);
  EXPECT_GT(across, 200); // the seams are crossed within the trails' span
  EXPECT_GT(shown, 10000);
  EXPECT_LT(skipped, (shown + across) / 50);
}

namespace
{
/// The Walls of the Surfaces (engine specification 2.10) on both engines:
/// a uniform flow onto a tilted plane, or solid-body rotation onto a
/// half-plane, each cut into triangles (Wall).
enum class WallSurface
{
  Tilted,    ///< x + 0.3 y = 0.4 across the box, 12 x 11 squares (264 triangles: two rows)
  HalfPlane, ///< y = 0, x in [0, 1], 8 x 6 squares (96 triangles)
  Corner,    ///< x = 0.5 (y below 0.6) and y = 0.6 (x below 0.5): an inward corner (144)
  Box,       ///< the closed box [-0.5, 0.5]^3, 3 x 3 squares a face (108)
  Prism      ///< a closed prism along z, 60-degree edges, 3 x 3 squares a side (56)
};

/// The triangles of each WallSurface.
std::size_t wallTriangles(WallSurface which)
{
  return which == WallSurface::Tilted ? 264
    : which == WallSurface::HalfPlane ? 96
    : which == WallSurface::Corner    ? 144
    : which == WallSurface::Box       ? 108
                                      : 56;
}

struct SurfaceWallCase
{
  WallSurface surface;
  bp::BuiltinShape shape;
  bp::Integrator integrator;
  bp::Restoration restoration;
  bp::Boundary boundary;
  bool heavy = false; ///< Maxey-Riley with gravity
};

/// The uniform flow u on [-1, 1]^3, 12 points a side.
bp::VectorField uniformField(std::array<float, 3> u = { 0.8f, 0.25f, 0.1f })
{
  bp::GridGeometry g = cubeGrid(12);
  bp::FieldSlice s;
  auto velocity = std::make_shared<std::vector<float>>(3 * g.pointCount());
  for (std::size_t k = 0; k < g.pointCount(); ++k)
  {
    std::copy(u.begin(), u.end(), velocity->begin() + long(3 * k));
  }
  s.velocity = velocity;
  return bp::VectorField(g, s);
}

/// The case's wall as Surfaces; `shift` moves it along z (out of the way).
std::shared_ptr<const bp::SurfaceSet> wallSurface(WallSurface which, float shift = 0.0f)
{
  bp::SurfaceTriangles t;
  auto square = [&](const float* a, const float* b, const float* c, const float* d)
  {
    for (const float* v : { a, b, c, a, c, d })
      t.corners.insert(t.corners.end(), { v[0], v[1], v[2] + shift });
    t.interaction.insert(t.interaction.end(), 2, bp::SurfaceInteraction::Wall);
    t.cells.insert(t.cells.end(), { std::int32_t(t.cells.size()), std::int32_t(t.cells.size()) });
  };
  if (which == WallSurface::Corner)
  {
    for (int plane = 0; plane < 2; ++plane)
      for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i)
        {
          float q[4][3];
          for (int c = 0; c < 4; ++c)
          {
            const float u = float(i + (c == 1 || c == 2)) / 6.0f;
            const float z = -1.2f + 2.4f * float(j + (c >= 2)) / 6.0f;
            const float along = plane == 0 ? -1.2f + 1.8f * u : -1.2f + 1.7f * u;
            q[c][0] = plane == 0 ? 0.5f : along;
            q[c][1] = plane == 0 ? along : 0.6f;
            q[c][2] = z;
          }
          square(q[0], q[1], q[2], q[3]);
        }
    return std::make_shared<const bp::SurfaceSet>(t);
  }
  if (which == WallSurface::Box)
  {
    for (int axis = 0; axis < 3; ++axis)
      for (const float side : { -0.5f, 0.5f })
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i)
          {
            float q[4][3];
            for (int c = 0; c < 4; ++c)
            {
              q[c][axis] = side;
              q[c][(axis + 1) % 3] = -0.5f + float(i + (c == 1 || c == 2)) / 3.0f;
              q[c][(axis + 2) % 3] = -0.5f + float(j + (c >= 2)) / 3.0f;
            }
            square(q[0], q[1], q[2], q[3]);
          }
    return std::make_shared<const bp::SurfaceSet>(t);
  }
  if (which == WallSurface::Prism)
  {
    // Equilateral cross-section, circumradius 0.5, a corner at (0, 0.5);
    // z in [-0.5, 0.5], closed by a triangle at each end.
    float v[3][2];
    for (int k = 0; k < 3; ++k)
    {
      v[k][0] = float(0.5 * std::cos(M_PI / 2 + 2 * M_PI * k / 3));
      v[k][1] = float(0.5 * std::sin(M_PI / 2 + 2 * M_PI * k / 3));
    }
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
        {
          float q[4][3];
          for (int c = 0; c < 4; ++c)
          {
            const float u = float(i + (c == 1 || c == 2)) / 3.0f;
            q[c][0] = v[k][0] + u * (v[(k + 1) % 3][0] - v[k][0]);
            q[c][1] = v[k][1] + u * (v[(k + 1) % 3][1] - v[k][1]);
            q[c][2] = -0.5f + float(j + (c >= 2)) / 3.0f;
          }
          square(q[0], q[1], q[2], q[3]);
        }
    for (const float z : { -0.5f, 0.5f })
    {
      t.corners.insert(
        t.corners.end(), { v[0][0], v[0][1], z, v[1][0], v[1][1], z, v[2][0], v[2][1], z });
      t.interaction.push_back(bp::SurfaceInteraction::Wall);
      t.cells.push_back(std::int32_t(t.cells.size()));
    }
    return std::make_shared<const bp::SurfaceSet>(t);
  }
  const bool tilted = which == WallSurface::Tilted;
  const int nu = tilted ? 12 : 8, nv = tilted ? 11 : 6;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
    {
      float q[4][3];
      for (int c = 0; c < 4; ++c)
      {
        const float u = float(i + (c == 1 || c == 2)) / float(nu);
        const float v = float(j + (c >= 2)) / float(nv);
        if (tilted)
        {
          const float y = -1.2f + 2.4f * u;
          q[c][0] = 0.4f - 0.3f * y;
          q[c][1] = y;
          q[c][2] = -1.2f + 2.4f * v;
        }
        else
        {
          q[c][0] = u;
          q[c][1] = 0.0f;
          q[c][2] = -1.0f + 2.0f * v;
        }
      }
      square(q[0], q[1], q[2], q[3]);
    }
  return std::make_shared<const bp::SurfaceSet>(t);
}

/// Distance of p from the case's wall's plane (the tilted plane's, or the
/// half-plane's where x is in [0, 1], else far).
float fromWall(WallSurface which, const float* p)
{
  if (which == WallSurface::Tilted)
    return std::abs(p[0] + 0.3f * p[1] - 0.4f) / std::sqrt(1.09f);
  if (which == WallSurface::Corner)
    return std::min(std::abs(p[0] - 0.5f), std::abs(p[1] - 0.6f));
  if (which == WallSurface::Box)
    return 0.5f - std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
  if (which == WallSurface::Prism)
  {
    float nearest = 0.5f - std::abs(p[2]);
    for (int k = 0; k < 3; ++k) // the side's outward normal at 150 + 120 k degrees, 0.25 off
    {
      const double a = 5 * M_PI / 6 + 2 * M_PI * k / 3;
      nearest = std::min(nearest, float(0.25 - std::cos(a) * p[0] - std::sin(a) * p[1]));
    }
    return nearest;
  }
  return p[0] >= 0.0f && p[0] <= 1.0f ? std::abs(p[1]) : 1.0f;
}

/// Both engines 150 steps with the case's wall: positions (and heavy
/// particles' slips, times the step) agree within 1e-4 of the diagonal but
/// for at most 1% of the elements, hidden elements and generations but for
/// at most 1% (the edge exception); with Stick every GPU particle that lay
/// on a Wall (SurfaceSet::onWall, two offsets) ten steps before, its element
/// not placed again since, is exactly where it was. Returns what the wall
/// did on the CPU engine: particles within 10^-3 of it, summed over every
/// tenth step (Stick, Slip, Bounce), or elements it ended (Release Again,
/// Terminate).
int compareSurfaceWalls(const SurfaceWallCase& c)
{
  const bool tilted = c.surface == WallSurface::Tilted;
  const bool corner = c.surface == WallSurface::Corner;
  const bool box = c.surface == WallSurface::Box;
  const bool prism = c.surface == WallSurface::Prism;
  // Into the box's edge x = y = 0.5 (the prism's at (0, 0.5)) and along it, to its corner.
  const bp::VectorField field = box ? uniformField({ 0.7f, 0.7f, 0.35f })
    : prism                         ? uniformField({ 0.1f, 0.8f, 0.35f })
    : tilted || corner              ? uniformField()
                                    : rotationField();
  bp::Parameters p = boundaryTrace(c.integrator, c.restoration, c.boundary, 0.4f, 1.0f, 17);
  p.restitution = 0.6f;
  if (tilted || corner)
    p.emitterMax[0] = 0.0f; // released before the wall
  if (corner)
    p.emitterMax[1] = 0.4f; // and below the corner's other wall
  if (box)
  {
    p.emitterMin = { -0.4f, -0.4f, -0.4f }; // inside the box
    p.emitterMax = { 0.4f, 0.4f, 0.4f };
  }
  if (prism)
  {
    p.emitterMin = { -0.15f, -0.15f, -0.4f }; // inside the prism
    p.emitterMax = { 0.15f, 0.15f, 0.4f };
  }
  if (c.heavy)
  {
    p.inertia = bp::Inertia::MaxeyRiley;
    p.responseTime = 0.2f;
    p.densityRatio = 1000.0f;
    p.gravity = { 0, 0, -4.0f };
  }
  p.surfaces = wallSurface(c.surface);
  EXPECT_EQ(p.surfaces->wallCorners().size(), 9u * wallTriangles(c.surface));
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  EnginePair engines(shape, p, field);
  bp::CpuStepper& cpu = engines.cpu;
  bp::GpuStepper& gpu = engines.gpu;
  const double dt = 0.01;
  const std::size_t elements = p.numberOfElements, n = shape.particleCount();
  const bool particles = bp::isWall(c.boundary);
  const bool stick = c.boundary == bp::Boundary::Stick;
  const float resting = 2.0f * bp::surfaceWallOffset(field.domain());
  Parity parity(elements, n);
  int met = 0, beyond = 0;
  long held = 0, heldMoved = 0;
  std::vector<float> heldBefore, generationsBefore;
  for (int k = 0; k < 150; ++k)
  {
    const std::vector<std::uint8_t> flagsBefore = cpu.engine().resetFlags();
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
    const bp::Engine& E = cpu.engine();
    for (std::size_t e = 0; !particles && e < elements; ++e)
    {
      // Ended in this step with lifetime left: at the wall (or, Release
      // Again, out through a side of the field).
      const std::uint8_t now = E.resetFlags()[e] & ~flagsBefore[e];
      met += (now & (bp::Terminated | bp::ResetDue)) && E.lifetimes()[e] > 0.0f;
    }
    if (k % 10 != 9)
      continue;
    const GpuReadback r = parity.check(gpu, E, c.heavy ? dt : 0.0);
    const std::vector<float>& x = r.x;
    const std::vector<float>& generations = r.generations;
    for (std::size_t q = 0; stick && !heldBefore.empty() && q < x.size(); q += 3)
    {
      // Held ten steps before (Stick), its element not placed again since.
      const std::size_t e = q / (3 * n);
      if (generations[e] == generationsBefore[e] && p.surfaces->onWall(&heldBefore[q], resting))
      {
        ++held;
        heldMoved +=
          !std::equal(x.begin() + long(q), x.begin() + long(q) + 3, heldBefore.begin() + long(q));
      }
    }
    heldBefore = x;
    generationsBefore = generations;
    for (std::size_t q = 0; particles && q < x.size(); q += 3)
    {
      met += fromWall(c.surface, E.positions().data() + q) < 1e-3f;
      // On the tilted wall's far side (released before it): none should be.
      beyond += tilted && x[q] + 0.3f * x[q + 1] - 0.4f > 0.0f;
      beyond += corner && (x[q] > 0.5f || x[q + 1] > 0.6f);
      beyond += (box || prism) && fromWall(c.surface, &x[q]) < 0.0f;
    }
  }
  std::printf("%s wall, %s, integrator %d, restoration %d, boundary %d%s: positions within %.3g "
              "but for %ld elements; the wall met %d times; %d GPU particles beyond it; %d "
              "hidden, %d generations apart; %ld held, %ld of them moved\n",
    tilted     ? "tilted"
      : corner ? "corner"
      : box    ? "box"
      : prism  ? "prism"
               : "half-plane",
    shape.name.c_str(), int(c.integrator), int(c.restoration), int(c.boundary),
    c.heavy ? ", heavy" : "", parity.worstKept, parity.elementsApart(), met, beyond,
    parity.hiddenApart, parity.generationsApart, held, heldMoved);
  parity.expectAgree(int(elements / 100));
  EXPECT_EQ(beyond, 0);
  if (stick)
  {
    EXPECT_GT(held, 20) << "Stick holds particles on the Walls";
    EXPECT_EQ(heldMoved, 0) << "a held particle stays exactly";
  }
  return met;
}

} // namespace

TEST(GpuBoundary, SurfaceWallsMatchTheCpuEngine)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using B = bp::Boundary;
  using S = WallSurface;
  const SurfaceWallCase cases[] = {
    { S::Tilted, bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, B::Slip },
    { S::Tilted, bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, B::Bounce },
    { S::HalfPlane, bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, B::Slip },
    { S::HalfPlane, bp::BuiltinShape::Strip4, I::Euler, R::GaussSeidel, B::Bounce },
    { S::Tilted, bp::BuiltinShape::Strip4, I::RK2, R::Jacobi, B::ReleaseAgain },
    { S::HalfPlane, bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, B::Terminate },
    // An inward corner: the rule taken again on the second wall.
    { S::Corner, bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, B::Slip },
    { S::Corner, bp::BuiltinShape::Strip4, I::RK2, R::AveragedJacobi, B::Bounce },
    // Stick: held where the step met the wall (and on it, the corner's).
    { S::Tilted, bp::BuiltinShape::Point, I::RK4, R::AveragedJacobi, B::Stick },
    { S::HalfPlane, bp::BuiltinShape::Strip4, I::RK2, R::GaussSeidel, B::Stick },
    { S::Corner, bp::BuiltinShape::Strip4, I::Euler, R::AveragedJacobi, B::Stick },
    // A closed box, the flow into an edge and along it: the step through
    // the edge meets both faces at one point, the rule taken on both.
    { S::Box, bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, B::Slip },
    { S::Box, bp::BuiltinShape::Strip4, I::RK2, R::AveragedJacobi, B::Bounce },
    { S::Box, bp::BuiltinShape::Point, I::RK4, R::AveragedJacobi, B::Stick },
    // A closed prism: at its 60-degree edges the segment from before the
    // step is tested last.
    { S::Prism, bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, B::Slip },
    { S::Prism, bp::BuiltinShape::Strip4, I::RK2, R::AveragedJacobi, B::Bounce },
  };
  for (const SurfaceWallCase& c : cases)
    EXPECT_GT(compareSurfaceWalls(c), 20) << "the wall acts";
}

TEST(GpuBoundary, SurfaceWallsMatchWithInertia)
{
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using B = bp::Boundary;
  using S = WallSurface;
  const SurfaceWallCase cases[] = {
    { S::Tilted, bp::BuiltinShape::Strip8, I::RK2, R::AveragedJacobi, B::Slip, true },
    { S::HalfPlane, bp::BuiltinShape::Cross, I::Euler, R::ShapeMatching, B::Bounce, true },
    { S::Tilted, bp::BuiltinShape::Point, I::RK4, R::AveragedJacobi, B::Bounce, true },
    { S::Tilted, bp::BuiltinShape::Strip4, I::RK2, R::AveragedJacobi, B::Stick, true },
  };
  for (const SurfaceWallCase& c : cases)
    EXPECT_GT(compareSurfaceWalls(c), 20) << "the wall acts";
}

TEST(GpuBoundary, AWallOutOfTheWayChangesNothing)
{
  // A wall no particle reaches (the half-plane moved 10 along z) runs every
  // wall test, per particle (Slip) and per element (Release Again), and
  // changes no bit.
  ASSERT_TRUE(bp::haveSharedContext());
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip8);
  long differ = 0;
  for (bp::Boundary b : { bp::Boundary::Slip, bp::Boundary::ReleaseAgain })
  {
    const std::vector<float> none = gpuTrace(shape, nullptr, b);
    const std::vector<float> wall = gpuTrace(shape, wallSurface(WallSurface::HalfPlane, 10.0f), b);
    ASSERT_EQ(wall.size(), none.size());
    for (std::size_t k = 0; k < none.size(); ++k)
      differ += wall[k] != none[k];
  }
  EXPECT_EQ(differ, 0);
  std::printf("a wall out of the way: %ld values apart\n", differ);
}

TEST(GpuBoundary, RefusesMoreWallTrianglesThanItTests)
{
  ASSERT_TRUE(bp::haveSharedContext());
  const std::string error =
    configureMoreThan(bp::GpuMaxWallTriangles, bp::SurfaceInteraction::Wall, bp::Boundary::Slip);
  EXPECT_NE(error.find("4097 Wall triangles"), std::string::npos) << error;
  EXPECT_EQ(bp::gpuWallError(bp::GpuMaxWallTriangles), "");
}

namespace
{
/// The plane x = -0.995 over y, z in [-1, 1] (0.005 past the x seam of
/// periodicField()) as two triangles of `kind`.
std::shared_ptr<const bp::SurfaceSet> pastTheSeam(bp::SurfaceInteraction kind)
{
  bp::SurfaceTriangles t;
  t.corners = { -0.995f, -1, -1, -0.995f, 1, -1, -0.995f, 1, 1, -0.995f, -1, -1, -0.995f, 1, 1,
    -0.995f, -1, 1 };
  t.surfaces = { 0, 0 };
  t.interaction = { kind, kind };
  t.cells = { 0, 1 };
  return std::make_shared<const bp::SurfaceSet>(t);
}

/// Both engines 150 steps on periodicField() (x and y periodic, the flow
/// along +x at 1 to 2) with pastTheSeam(kind): an Outlet, or a Wall under
/// the case's boundary (Release Again or Terminate). Positions agree within
/// 1e-4 of the diagonal, hidden elements and generations but for at most 1%
/// (the edge exception). Returns how many times the CPU engine flagged an
/// element in a step whose centre crossed the x seam and came to rest short
/// of the plane (x > -0.995): passed in the step's part past the seam alone.
int compareSeamSurfaces(const BoundaryCase& c, bp::SurfaceInteraction kind)
{
  const bp::VectorField field = periodicField();
  bp::Parameters p = boundaryTrace(c.integrator, c.restoration, c.boundary, 0.8f, 1.6f, 17);
  p.resetWhen = c.resetWhen;
  p.surfaces = pastTheSeam(kind);
  const bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
  EnginePair engines(shape, p, field);
  bp::CpuStepper& cpu = engines.cpu;
  bp::GpuStepper& gpu = engines.gpu;
  const double dt = 0.01;
  const std::size_t elements = p.numberOfElements, n = shape.particleCount();
  Parity parity(elements, n);
  std::vector<float> xs(elements, 0.0f);
  int pastSeam = 0;
  for (int k = 0; k < 150; ++k)
  {
    const std::vector<std::uint8_t> flagsBefore = cpu.engine().resetFlags();
    cpu.step(k * dt, dt);
    gpu.step(k * dt, dt);
    const bp::Engine& E = cpu.engine();
    for (std::size_t e = 0; e < elements; ++e)
    {
      float x = 0.0f;
      for (std::size_t i = 0; i < n; ++i)
        x += E.positions()[3 * (e * n + i)] / float(n);
      const std::uint8_t flag = E.resetFlags()[e];
      const bool flagged = (flag & (bp::ResetDue | bp::Terminated)) &&
        !(flagsBefore[e] & (bp::ResetDue | bp::HiddenFlags));
      pastSeam += k > 0 && flagged && xs[e] - x > 1.0f && x > -0.995f;
      xs[e] = x;
    }
    if (k % 10 == 9)
      parity.check(gpu, E);
  }
  std::printf("%s, integrator %d, boundary %d, %s just past the x seam: positions within %.3g "
              "but for %ld elements; %d passed past the seam; %d hidden, %d generations apart\n",
    shape.name.c_str(), int(c.integrator), int(c.boundary),
    kind == bp::SurfaceInteraction::Outlet ? "an outlet" : "a wall", parity.worstKept,
    parity.elementsApart(), pastSeam, parity.hiddenApart, parity.generationsApart);
  parity.expectAgree(int(elements / 100));
  return pastSeam;
}
} // namespace

TEST(GpuBoundary, SurfacesJustPastAPeriodicSeamMatchTheCpuEngine)
{
  // An element whose centre crosses the seam passes an Outlet, or a Wall
  // that ends elements, in the step's part past it (engine specification
  // 2.10) on both engines.
  ASSERT_TRUE(bp::haveSharedContext());
  using I = bp::Integrator;
  using R = bp::Restoration;
  using W = bp::ResetWhen;
  using B = bp::Boundary;
  using S = bp::SurfaceInteraction;
  const std::pair<BoundaryCase, S> cases[] = {
    { { bp::BuiltinShape::Point, I::Euler, R::AveragedJacobi, W::CenterLeaves, B::ReleaseAgain },
      S::Outlet },
    { { bp::BuiltinShape::Strip8, I::RK4, R::AveragedJacobi, W::CenterLeaves, B::Slip },
      S::Outlet },
    { { bp::BuiltinShape::Cross, I::RK2, R::ShapeMatching, W::CenterLeaves, B::ReleaseAgain },
      S::Wall },
    { { bp::BuiltinShape::Strip4, I::RK4, R::Jacobi, W::AnyParticleLeaves, B::Terminate },
      S::Wall },
  };
  for (const auto& [c, kind] : cases)
    EXPECT_GT(compareSeamSurfaces(c, kind), 10) << "passed in the step's part past the seam";
}
