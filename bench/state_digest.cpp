// SPDX-License-Identifier: BSD-3-Clause
// Digests of both engines' state after a trace, one line per configuration
// and quantity: what a change that must keep the results bit for bit (a
// refactoring of the engines or their shaders) is checked with, by running
// this from the build before and the build after and comparing the output.
// It is not a test (its digests belong to one driver and one compiler).
//
//   BoundParticlesStateDigest [--path fragment|compute] [--fused always|never]
//                             [--no-gpu] > digests.txt
//
// The GPU engine runs in a headless EGL context; --path forces its path as
// BOUNDPARTICLES_GPU_PATH does, --fused whether the compute path fuses the
// step (GpuEngine::setFusedSteps; automatic by default).
#include "AnalyticFlows.h"
#include "DomainMask.h"
#include "Engine.h"
#include "GpuEngine.h"
#include "HeadlessContext.h"
#include "ReleaseLattice.h"
#include "ReleaseWeights.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace
{
/// FNV-1a over the bits of the values.
std::uint64_t digest(const std::vector<float>& values)
{
  std::uint64_t h = 1469598103934665603ull;
  for (float v : values)
  {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int k = 0; k < 4; ++k)
    {
      h ^= (bits >> (8 * k)) & 0xffu;
      h *= 1099511628211ull;
    }
  }
  return h;
}

struct Config
{
  const char* name;
  bp::BuiltinShape shape;
  std::size_t elements;
  bool unsteady;
  void (*adjust)(bp::Parameters&, bp::ElementTemplate&);
};

/// The parity tests' fields: a 24^3 grid over [-1, 1]^3 (steady) or 41 x 21 x 6
/// points 0.05 apart from the origin (the double gyre's box, unsteady).
bp::GridGeometry gridFor(bool unsteady)
{
  bp::GridGeometry g;
  g.dims = unsteady ? std::array<int, 3>{ 41, 21, 6 } : std::array<int, 3>{ 24, 24, 24 };
  const double spacing = unsteady ? 0.05 : 2.0 / 23;
  g.origin = unsteady ? std::array<double, 3>{ 0, 0, 0 } : std::array<double, 3>{ -1, -1, -1 };
  g.spacing = { spacing, spacing, spacing };
  return g;
}

void none(bp::Parameters&, bp::ElementTemplate&) {}

const Config Configs[] = {
  { "strip16-aj-euler", bp::BuiltinShape::Strip16, 300, false, none },
  { "strip16-jacobi-rk2", bp::BuiltinShape::Strip16, 300, false,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.restoration = bp::Restoration::Jacobi;
      p.integrator = bp::Integrator::RK2;
    } },
  { "cross-gs-rk4-unsteady", bp::BuiltinShape::Cross, 200, true,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.restoration = bp::Restoration::GaussSeidel;
      p.integrator = bp::Integrator::RK4;
    } },
  { "paddle-match-unsteady-poses", bp::BuiltinShape::Paddlewheel, 200, true,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.restoration = bp::Restoration::ShapeMatching;
      p.trackPoses = true;
      p.trailLength = 4;
      p.trailStart = 0.02;
      p.trailInterval = 0.03;
    } },
  { "cross-linear-match", bp::BuiltinShape::Cross, 150, false,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.restoration = bp::Restoration::ShapeMatching;
      p.linearShapeMatching = true;
      p.linearBlend = 0.4f;
    } },
  { "fish-aj-pinned", bp::BuiltinShape::Fish, 100, false,
    [](bp::Parameters& p, bp::ElementTemplate& t)
    {
      t.pinned.assign(t.particleCount(), 0);
      for (std::size_t i = 0; i < t.particleCount(); i += 5)
        t.pinned[i] = 1;
      p.restoration = bp::Restoration::GaussSeidel;
    } },
  { "point-alone", bp::BuiltinShape::Point, 500, true, none },
  { "strip4-tube", bp::BuiltinShape::Strip4, 64, true,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.linking = bp::Linking::Tube;
      p.linkStiffness = 0.8f;
      p.trackPoses = true;
    } },
  { "point-torus", bp::BuiltinShape::Point, 100, false,
    [](bp::Parameters& p, bp::ElementTemplate&) { p.linking = bp::Linking::Torus; } },
  { "paddle-anchored", bp::BuiltinShape::Paddlewheel, 150, true,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.restoration = bp::Restoration::ShapeMatching;
      p.anchor = bp::Anchor::Centre;
      p.trackPoses = true;
    } },
  { "strip8-anyparticle-along-flow", bp::BuiltinShape::Strip8, 200, true,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
      p.orientation = bp::Orientation::AlongFlow;
      p.releaseStart = 0.3;
      p.releaseStop = 0.8;
    } },
  { "square-lattice", bp::BuiltinShape::Square, 216, false,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      p.releasePattern = bp::ReleasePattern::Lattice;
      p.lattice = bp::releaseLattice(p.emitterMin, p.emitterMax, p.numberOfElements, 0.0);
    } },
  { "strip4-seeds", bp::BuiltinShape::Strip4, 120, false,
    [](bp::Parameters& p, bp::ElementTemplate&)
    {
      for (int k = 0; k < 37; ++k)
        for (int a = 0; a < 3; ++a)
          p.seedPoints.push_back(float(-0.5 + std::fmod(0.618034 * (k + 1) * (a + 1), 1.0)));
    } },
};

/// Both engines' readbacks, named.
struct Readback
{
  std::vector<std::pair<std::string, std::vector<float>>> quantities;
  void add(const char* name, std::vector<float> v) { quantities.push_back({ name, std::move(v) }); }
};

Readback readGpu(bp::GpuEngine& gpu, double t)
{
  Readback r;
  std::vector<float> a, b, c, d, e, f;
  gpu.updateNormals();
  gpu.read(&a, &b, &c);
  r.add("positions", a);
  r.add("forces", b);
  r.add("normals", c);
  gpu.readElements(&a, &b, &c, &d, &e, &f);
  r.add("lifetimes", a);
  r.add("generations", b);
  r.add("centers", c);
  r.add("orientations", d);
  r.add("flags", e);
  r.add("hidden", f);
  gpu.readPoses(&a, &b);
  r.add("poses", a);
  r.add("spins", b);
  for (int k = 0; k < gpu.trailLength(); ++k)
  {
    std::vector<std::uint32_t> g;
    gpu.readTrail(k, &a, &g);
    a.push_back(float(gpu.trailTime(k)));
    for (std::uint32_t x : g)
      a.push_back(float(x));
    r.add("trail", a);
  }
  gpu.updateFieldSamples(t);
  gpu.readFieldSamples(&a, &b);
  r.add("velocity", a);
  r.add("vorticity", b);
  return r;
}

Readback readCpu(bp::Engine& cpu)
{
  Readback r;
  cpu.updateNormals(bp::serialRunner());
  r.add("positions", cpu.positions());
  r.add("forces", cpu.forces());
  r.add("normals", cpu.normals());
  r.add("lifetimes", cpu.lifetimes());
  r.add("centers", cpu.initialCenters());
  r.add("orientations", cpu.orientations());
  r.add("poses", cpu.poses());
  r.add("spins", cpu.spins());
  r.add("trail", cpu.trailPositions());
  return r;
}
} // namespace

int main(int argc, char** argv)
{
  bool gpuWanted = true;
  bp::FusedSteps fused = bp::FusedSteps::Automatic;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--path") && i + 1 < argc)
      setenv(bp::GpuPathVariable, argv[++i], 1);
    else if (!std::strcmp(argv[i], "--fused") && i + 1 < argc)
    {
      ++i;
      fused = !std::strcmp(argv[i], "always") ? bp::FusedSteps::Always
        : !std::strcmp(argv[i], "never")      ? bp::FusedSteps::Never
                                              : bp::FusedSteps::Automatic;
    }
    else if (!std::strcmp(argv[i], "--no-gpu"))
      gpuWanted = false;
    else
    {
      std::fprintf(stderr,
        "usage: %s [--path fragment|compute] [--fused always|never] [--no-gpu]\n", argv[0]);
      return 2;
    }
  }
  bp::HeadlessContext context;
  if (gpuWanted && !context.create().empty())
  {
    std::fprintf(stderr, "no headless OpenGL context\n");
    return 1;
  }
  const std::array<double, 6> steadyBox{ -1, 1, -1, 1, -1, 1 }, gyreBox{ 0, 2, 0, 1, 0, 0.25 };
  for (const Config& c : Configs)
  {
    const bp::GridGeometry g = gridFor(c.unsteady);
    const std::array<double, 6>& box = c.unsteady ? gyreBox : steadyBox;
    auto slice = [&](bp::AnalyticFlow flow, double t)
    {
      bp::FieldSlice s;
      s.time = t;
      s.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, t));
      return s;
    };
    const bp::VectorField field = c.unsteady
      ? bp::VectorField(g, slice(bp::AnalyticFlow::DoubleGyre, 0.0),
          slice(bp::AnalyticFlow::DoubleGyre, 2.0))
      : bp::VectorField(g, slice(bp::AnalyticFlow::SolidBodyRotation, 0.0));
    bp::Parameters p;
    p.numberOfElements = c.elements;
    p.elementSize = 0.1f;
    for (int a = 0; a < 3; ++a)
    {
      p.emitterMin[a] = float(box[2 * a] + 0.2 * (box[2 * a + 1] - box[2 * a]));
      p.emitterMax[a] = float(box[2 * a + 1] - 0.2 * (box[2 * a + 1] - box[2 * a]));
    }
    p.lifetimeMin = 0.3f;
    p.lifetimeMax = 1.2f;
    p.iterations = 2;
    p.seed = 17;
    bp::ElementTemplate shape = bp::builtinTemplate(c.shape);
    c.adjust(p, shape);
    const double dt = 0.01;
    const int steps = 80;
    bp::Engine cpu;
    if (!cpu.configure(shape, p).empty())
    {
      std::printf("%s: the CPU engine refuses it\n", c.name);
      continue;
    }
    cpu.setReleaseMask(g, bp::releaseUnfitCells(field, p.releaseMinSpeed),
      bp::releaseWeightsOf(g, field.firstSlice().releaseWeights));
    cpu.initialize(bp::serialRunner(), 0.0, &field);
    for (int s = 0; s < steps; ++s)
      cpu.step(field, s * dt, dt, bp::serialRunner());
    for (const auto& q : readCpu(cpu).quantities)
      std::printf("cpu %-32s %-13s %016llx\n", c.name, q.first.c_str(),
        (unsigned long long)digest(q.second));
    if (!gpuWanted)
      continue;
    bp::GpuEngine gpu;
    gpu.setFusedSteps(fused);
    const std::string error = gpu.configure(shape, p);
    if (!error.empty() || !gpu.setField(field).empty())
    {
      std::printf("gpu %s: %s\n", c.name, error.c_str());
      gpu.release();
      continue;
    }
    gpu.initialize(0.0);
    for (int s = 0; s < steps; ++s)
    {
      gpu.step(s * dt, dt);
      if (s == steps / 2)
      {
        // A short step shown and taken back, as the tracer does.
        gpu.saveState();
        gpu.step((s + 1) * dt, 0.5 * dt);
        gpu.restoreState();
      }
    }
    for (const auto& q : readGpu(gpu, steps * dt).quantities)
      std::printf("gpu %-32s %-13s %016llx\n", c.name, q.first.c_str(),
        (unsigned long long)digest(q.second));
    gpu.release();
  }
  return 0;
}
