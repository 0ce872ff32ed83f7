// SPDX-License-Identifier: BSD-3-Clause
// Steps per second of the CPU engine on a steady analytic flow, for element
// shapes and counts of thesis Table 4.1, on 1 and 2 threads side by side.
// Each cell is the median of 5 timed runs after one warm-up run.
#include "AnalyticFlows.h"
#include "Engine.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace
{
struct Config
{
  bp::BuiltinShape shape;
  std::size_t elements;
};

double medianSeconds(
  const bp::VectorField& field, const Config& c, const bp::RangeRunner& run, int steps, double dt)
{
  std::vector<double> times;
  for (int repeat = 0; repeat < 6; ++repeat)
  {
    bp::Engine engine;
    bp::Parameters p;
    p.numberOfElements = c.elements;
    p.elementSize = 0.1f;
    const auto b = field.grid().bounds();
    for (int a = 0; a < 3; ++a)
    {
      p.emitterMin[a] = float(b[2 * a]);
      p.emitterMax[a] = float(b[2 * a + 1]);
    }
    p.lifetimeMin = 2.0f;
    p.lifetimeMax = 4.0f;
    const std::string error = engine.configure(bp::builtinTemplate(c.shape), p);
    if (!error.empty())
    {
      std::fprintf(stderr, "%s\n", error.c_str());
      std::exit(1);
    }
    engine.initialize(run);
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s)
    {
      engine.step(field, s * dt, dt, run);
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (repeat > 0) // the first run warms caches and the allocator
    {
      times.push_back(seconds);
    }
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}
} // namespace

int main(int argc, char** argv)
{
  int resolution = 128;
  bool quick = false;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--resolution") && i + 1 < argc)
      resolution = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
  }
  bp::GridGeometry g;
  g.dims = { resolution, resolution, resolution };
  g.origin = { -1, -1, -1 };
  const double h = 2.0 / (resolution - 1);
  g.spacing = { h, h, h };
  bp::FieldSlice slice;
  slice.velocity = std::make_shared<std::vector<float>>(
    bp::sampleAnalyticFlow(bp::AnalyticFlow::ShearLayer, g, 0.0));
  const bp::VectorField field(g, slice);
  const double dt = 0.5 * h / field.maxSpeed();

  std::vector<Config> configs;
  const std::vector<std::size_t> counts = quick
    ? std::vector<std::size_t>{ 4096 }
    : std::vector<std::size_t>{ 256, 1024, 4096, 16384, 65536 };
  for (auto shape :
    { bp::BuiltinShape::Square, bp::BuiltinShape::Strip8, bp::BuiltinShape::Strip16 })
    for (std::size_t n : counts)
      configs.push_back({ shape, n });

  std::printf(
    "CPU engine, shear layer %d^3, Euler, 1 averaged-Jacobi iteration; median of 5\n", resolution);
  std::printf("%-8s %-10s %8s %14s %14s %18s %8s\n", "shape", "elements", "particles",
    "steps/s 1 thr", "steps/s 2 thr", "particle-steps/s 2", "2 vs 1");
  for (const Config& c : configs)
  {
    const bp::ElementTemplate t = bp::builtinTemplate(c.shape);
    const std::size_t particles = c.elements * t.particleCount();
    // Enough steps for about 0.2 s of work per run.
    const int steps = int(std::max<std::size_t>(5, 4000000 / particles));
    const double one = medianSeconds(field, c, bp::threadRunner(1), steps, dt);
    const double two = medianSeconds(field, c, bp::threadRunner(2), steps, dt);
    std::printf("%-8s %-10zu %8zu %14.1f %14.1f %18.3e %7.2fx\n", t.name.c_str(), c.elements,
      particles, steps / one, steps / two, particles * steps / two, one / two);
  }
  return 0;
}
