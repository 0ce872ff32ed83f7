// SPDX-License-Identifier: BSD-3-Clause
// Speed of the engines, side by side in one run: the CPU engine (1 and 2
// threads) and the GPU engine (headless EGL) on the element shapes and counts
// of thesis Table 4.1 plus single-particle elements, on a steady and an
// unsteady field, against a plain trilinear Euler loop (no springs) compiled
// in the same build. Every cell is the median of 5 timed runs after a warm-up.
// Prints a table; --csv FILE also writes it as CSV.
#include "AnalyticFlows.h"
#include "BenchFields.h"
#include "CounterHash.h"
#include "Engine.h"
#include "GpuEngine.h"
#include "HeadlessContext.h"

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// Keeps the median of each benchmark Google Benchmark runs, and shows nothing:
/// the harness prints its own table, the ratios side by side.
class MedianReporter : public benchmark::BenchmarkReporter
{
public:
  double Median = 0.0;
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override
  {
    for (const Run& run : runs)
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
        this->Median = run.GetAdjustedRealTime(); // seconds: the unit is kSecond
  }
};

/// Median of 5 timed runs after one warm-up, through Google Benchmark's
/// repetitions; `run` returns the seconds it measured (its own clock, so a
/// GPU run can glFinish inside its timing and its setup stays outside).
double median(const std::function<double()>& run)
{
  run(); // warm-up (Google Benchmark 1.7 has no warm-up of its own)
  benchmark::RegisterBenchmark("run", [&](benchmark::State& state)
    { for (auto _ : state) state.SetIterationTime(run()); })
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(5)
    ->ReportAggregatesOnly()
    ->Unit(benchmark::kSecond);
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();
  return reporter.Median;
}

struct Config
{
  bp::BuiltinShape shape;
  std::size_t elements;
};

using bench::parametersFor;

/// The plain reference's own sampler, written apart from the engine's: a
/// uniform grid, trilinear in space and linear in time, nothing else (no
/// rectilinear axes, clamping as the engine does so particles stay valid).
struct PlainField
{
  float origin[3], inverse[3], last[3];
  std::size_t stride[3];
  const float* first;
  const float* second; // null when steady
  float startTime, inverseSpan;

  explicit PlainField(const bp::VectorField& f)
  {
    const bp::GridGeometry& g = f.grid();
    std::size_t s = 1;
    for (int a = 0; a < 3; ++a)
    {
      origin[a] = float(g.origin[a]);
      inverse[a] = float(1.0 / g.spacing[a]);
      last[a] = float(g.dims[a] - 2);
      stride[a] = s;
      s *= std::size_t(g.dims[a]);
    }
    first = f.firstSlice().velocity->data();
    second = f.secondSlice().velocity ? f.secondSlice().velocity->data() : nullptr;
    startTime = float(f.firstSlice().time);
    inverseSpan = second ? float(1.0 / (f.secondSlice().time - f.firstSlice().time)) : 0.0f;
  }

  void sample(const float p[3], float w, float v[3]) const
  {
    std::size_t base = 0;
    float f[3];
    for (int a = 0; a < 3; ++a)
    {
      const float g = std::min(std::max((p[a] - origin[a]) * inverse[a], 0.0f), last[a] + 1.0f);
      const float i = std::min(std::floor(g), last[a]);
      f[a] = g - i;
      base += std::size_t(i) * stride[a];
    }
    trilinear(first, base, f, v);
    if (second)
    {
      float u[3];
      trilinear(second, base, f, u);
      for (int k = 0; k < 3; ++k)
        v[k] += w * (u[k] - v[k]);
    }
  }

  void trilinear(const float* d, std::size_t b, const float f[3], float v[3]) const
  {
    const std::size_t x = stride[0], y = stride[1], z = stride[2];
    for (int k = 0; k < 3; ++k)
    {
      const float c00 = d[3 * b + k] + f[0] * (d[3 * (b + x) + k] - d[3 * b + k]);
      const float c10 = d[3 * (b + y) + k] + f[0] * (d[3 * (b + x + y) + k] - d[3 * (b + y) + k]);
      const float c01 = d[3 * (b + z) + k] + f[0] * (d[3 * (b + x + z) + k] - d[3 * (b + z) + k]);
      const float c11 =
        d[3 * (b + y + z) + k] + f[0] * (d[3 * (b + x + y + z) + k] - d[3 * (b + y + z) + k]);
      const float c0 = c00 + f[1] * (c10 - c00), c1 = c01 + f[1] * (c11 - c01);
      v[k] = c0 + f[2] * (c1 - c0);
    }
  }

  float weight(double t) const
  {
    return second ? std::min(std::max(float(t - startTime) * inverseSpan, 0.0f), 1.0f) : 0.0f;
  }
};

/// Plain reference: every particle advected by trilinear Euler (or RK4), no
/// springs, no resets, its own sampler, over ranges like the engine. Its
/// particles are uniformly random and, its best case, sorted once into the
/// field's memory order (z, then y, then x cell), so consecutive particles
/// sample neighbouring memory, as the engine's visiting order makes them do.
double referenceLoop(const bp::VectorField& field, std::size_t particles, int steps, double dt,
  const bp::RangeRunner& run, bool rk4 = false)
{
  const PlainField plain(field);
  const auto b = field.grid().bounds();
  std::vector<std::pair<std::size_t, std::array<float, 3>>> seeds(particles);
  for (std::size_t i = 0; i < particles; ++i)
  {
    std::size_t cell = 0;
    for (int a = 0; a < 3; ++a)
    {
      const float u = bp::uniformDraw(7, std::uint32_t(i), 0, std::uint32_t(a));
      seeds[i].second[a] = float(b[2 * a] + (b[2 * a + 1] - b[2 * a]) * u);
      cell += std::size_t(u * float(field.grid().dims[a] - 1)) * plain.stride[a];
    }
    seeds[i].first = cell;
  }
  std::sort(
    seeds.begin(), seeds.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  std::vector<float> x(3 * particles);
  for (std::size_t i = 0; i < particles; ++i)
    for (int a = 0; a < 3; ++a)
      x[3 * i + a] = seeds[i].second[a];
  const auto start = Clock::now();
  for (int s = 0; s < steps; ++s)
  {
    const float h = float(dt);
    const float w0 = plain.weight(s * dt), w1 = plain.weight((s + 0.5) * dt),
                w2 = plain.weight((s + 1) * dt);
    run(particles,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          float* p = &x[3 * i];
          float k1[3];
          plain.sample(p, w0, k1);
          if (!rk4)
          {
            for (int k = 0; k < 3; ++k)
              p[k] += h * k1[k];
            continue;
          }
          float q[3], k2[3], k3[3], k4[3];
          for (int k = 0; k < 3; ++k)
            q[k] = p[k] + 0.5f * h * k1[k];
          plain.sample(q, w1, k2);
          for (int k = 0; k < 3; ++k)
            q[k] = p[k] + 0.5f * h * k2[k];
          plain.sample(q, w1, k3);
          for (int k = 0; k < 3; ++k)
            q[k] = p[k] + h * k3[k];
          plain.sample(q, w2, k4);
          for (int k = 0; k < 3; ++k)
            p[k] += h / 6.0f * (k1[k] + 2.0f * k2[k] + 2.0f * k3[k] + k4[k]);
        }
      });
  }
  return seconds(start);
}

long peakRssKiB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0)
      return std::atol(line.c_str() + 6);
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  int resolution = 128;
  bool quick = false, gpu = true;
  std::string csvPath;
  std::vector<std::string> only; // "Strip16x65536": just these rows
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--resolution") && i + 1 < argc)
      resolution = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--no-gpu"))
      gpu = false;
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc)
      csvPath = argv[++i];
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
      only.push_back(argv[++i]);
    else
    {
      std::fprintf(stderr,
        "usage: %s [--quick] [--no-gpu] [--resolution N] [--csv FILE] [--only SHAPExCOUNT]...\n"
        "  --quick       4096 elements of each shape only\n"
        "  --no-gpu      CPU engine and plain loop only\n"
        "  --only S xN   only the rows of shape S with N elements, e.g. --only Strip16x65536\n",
        argv[0]);
      return std::strcmp(argv[i], "--help") ? 2 : 0;
    }
  }

  const bench::Fields fields = bench::benchFields(resolution);
  const double h = fields.spacing;
  const bp::VectorField& steady = fields.steady;
  const bp::VectorField& unsteady = fields.unsteady;

  bp::HeadlessContext context;
  std::string gpuName = "none";
  if (gpu)
  {
    const std::string error = context.create();
    gpu = error.empty();
    gpuName = gpu ? context.description() : error;
  }

  std::vector<Config> configs;
  const std::vector<std::size_t> counts = quick
    ? std::vector<std::size_t>{ 4096 }
    : std::vector<std::size_t>{ 256, 1024, 4096, 16384, 65536 };
  for (auto shape :
    { bp::BuiltinShape::Square, bp::BuiltinShape::Strip8, bp::BuiltinShape::Strip16 })
    for (std::size_t n : counts)
      configs.push_back({ shape, n });
  if (!quick)
  {
    configs.push_back({ bp::BuiltinShape::Point, 262144 });
    configs.push_back({ bp::BuiltinShape::Point, 1048576 });
  }
  if (!only.empty())
  {
    std::vector<Config> all = configs;
    for (auto shape : { bp::BuiltinShape::Point, bp::BuiltinShape::Square, bp::BuiltinShape::Strip8,
           bp::BuiltinShape::Strip16 })
      for (std::size_t n : { 256, 1024, 4096, 16384, 65536, 262144, 1048576 })
        all.push_back({ shape, n });
    configs.clear();
    for (const Config& c : all)
    {
      const std::string name = bp::builtinTemplate(c.shape).name + "x" + std::to_string(c.elements);
      const bool wanted = std::find(only.begin(), only.end(), name) != only.end();
      const bool seen = std::any_of(configs.begin(), configs.end(),
        [&](const Config& k) { return k.shape == c.shape && k.elements == c.elements; });
      if (wanted && !seen)
        configs.push_back(c);
    }
    if (configs.empty())
    {
      std::fprintf(stderr, "--only matched no shape and count (names as in the table)\n");
      return 2;
    }
  }

  std::printf(
    "Bound particles, %d^3 fields; Euler, 1 averaged-Jacobi iteration; median of 5 runs\n",
    resolution);
  std::printf("GPU engine on: %s\n", gpuName.c_str());
  std::printf("%-8s %-8s %9s %9s %11s %11s %11s %9s %9s %11s %11s %8s\n", "field", "shape",
    "elements", "particles", "CPU1 st/s", "CPU2 st/s", "CPU2 Mps/s", "2 vs 1", "vs plain",
    "GPU st/s", "GPUgen st/s", "B/elem");
  std::FILE* csv = csvPath.empty() ? nullptr : std::fopen(csvPath.c_str(), "w");
  if (csv)
    std::fprintf(csv,
      "field,shape,elements,particles,cpu1_steps_per_s,cpu2_steps_per_s,"
      "cpu2_particle_steps_per_s,plain2_particle_steps_per_s,gpu_steps_per_s,bytes_per_element,"
      "gpu_generated_steps_per_s\n");

  for (const bool isUnsteady : { false, true })
  {
    const bp::VectorField& field = isUnsteady ? unsteady : steady;
    const double dt = 0.5 * h / field.maxSpeed();
    for (const Config& c : configs)
    {
      const bp::ElementTemplate t = bp::builtinTemplate(c.shape);
      const std::size_t particles = c.elements * t.particleCount();
      const int steps = int(std::max<std::size_t>(5, 3000000 / particles));
      const bp::Parameters p = parametersFor(field, c.elements);
      std::size_t stateBytes = 0;
      auto cpu = [&](unsigned threads)
      {
        return median(
          [&]
          {
            bp::Engine engine;
            engine.configure(t, p);
            const bp::RangeRunner run = bp::poolRunner(threads);
            engine.initialize(run);
            stateBytes = sizeof(float) *
                (engine.positions().size() + engine.normals().size() + engine.forces().size() +
                  engine.lifetimes().size() + engine.initialCenters().size() +
                  engine.orientations().size()) +
              engine.generations().size() * 4 + engine.resetFlags().size();
            const auto start = Clock::now();
            for (int s = 0; s < steps; ++s)
              engine.step(field, s * dt, dt, run);
            return seconds(start);
          });
      };
      const double one = cpu(1), two = cpu(2);
      const double plain =
        median([&] { return referenceLoop(field, particles, steps, dt, bp::poolRunner(2)); });
      // The GPU engine, its Jacobi pass reading the springs from a buffer or
      // with them generated into the program (GpuEngine::setGeneratedSprings).
      auto gpuSteps = [&](bool generated)
      {
        double rate = 0.0;
        bp::GpuEngine engine;
        engine.setGeneratedSprings(generated);
        if (engine.configure(t, p).empty() && engine.setField(field).empty())
        {
          engine.initialize();
          const double took = median(
            [&]
            {
              glFinish();
              const auto start = Clock::now();
              for (int s = 0; s < steps; ++s)
                engine.step(s * dt, dt);
              glFinish();
              return seconds(start);
            });
          rate = steps / took;
        }
        engine.release();
        return rate;
      };
      const double gpuRate = gpu ? gpuSteps(false) : 0.0;
      const double gpuGeneratedRate = gpu ? gpuSteps(true) : 0.0;
      const double ps = particles * steps / two;
      const double plainPs = particles * steps / plain;
      std::printf("%-8s %-8s %9zu %9zu %11.1f %11.1f %11.2f %8.2fx %8.2fx %11.1f %11.1f %8zu\n",
        isUnsteady ? "unsteady" : "steady", t.name.c_str(), c.elements, particles, steps / one,
        steps / two, ps / 1e6, one / two, plainPs / ps, gpuRate, gpuGeneratedRate,
        stateBytes / c.elements);
      if (csv)
        std::fprintf(csv, "%s,%s,%zu,%zu,%.3f,%.3f,%.1f,%.1f,%.3f,%zu,%.3f\n",
          isUnsteady ? "unsteady" : "steady", t.name.c_str(), c.elements, particles, steps / one,
          steps / two, ps, plainPs, gpuRate, stateBytes / c.elements, gpuGeneratedRate);
      std::fflush(stdout);
    }
  }
  // One-particle elements with RK4 (the job of ParaView's Particle Tracer)
  // against the plain RK4 loop: how close the engine runs to this machine's
  // limit when there is nothing to restore.
  std::printf("\nPoint elements, RK4, 2 threads: engine against the plain RK4 loop\n");
  std::printf(
    "%-8s %9s %14s %14s %9s\n", "field", "particles", "engine Mps/s", "plain Mps/s", "vs plain");
  const std::size_t points = quick ? 65536 : 262144;
  for (const bool isUnsteady : { false, true })
  {
    const bp::VectorField& field = isUnsteady ? unsteady : steady;
    const double dt = 0.5 * h / field.maxSpeed();
    bp::Parameters p = parametersFor(field, points);
    p.integrator = bp::Integrator::RK4;
    p.lifetimeMin = p.lifetimeMax = 1e9f; // as ParaView's tracer: no resets
    const int steps = 20;
    const double engine = median(
      [&]
      {
        bp::Engine e;
        e.configure(bp::builtinTemplate(bp::BuiltinShape::Point), p);
        const bp::RangeRunner run = bp::poolRunner(2);
        e.initialize(run);
        const auto start = Clock::now();
        for (int s = 0; s < steps; ++s)
          e.step(field, s * dt, dt, run);
        return seconds(start);
      });
    const double plain =
      median([&] { return referenceLoop(field, points, steps, dt, bp::poolRunner(2), true); });
    std::printf("%-8s %9zu %14.2f %14.2f %8.2fx\n", isUnsteady ? "unsteady" : "steady", points,
      points * steps / engine / 1e6, points * steps / plain / 1e6, engine / plain);
    std::fflush(stdout);
  }
  // What seeing rotation costs the CPU engine (issue 19): the pose fit of
  // every element every step (trackPoses, the pose arrays ticked) and a trail
  // of 8 poses recorded every 4 steps, against the plain step, measured in
  // turn so the machine's noise falls on all three alike.
  std::printf("\nStrip16, 2 threads, steady: seeing rotation against the plain step\n");
  std::printf(
    "%9s %16s %16s %16s\n", "elements", "plain steps/s", "poses steps/s", "trail steps/s");
  for (std::size_t elements : { std::size_t(4096), std::size_t(65536) })
  {
    const double dt = 0.5 * h / steady.maxSpeed();
    const int steps = elements > 4096 ? 8 : 80;
    auto rate = [&](bool poses, bool trail)
    {
      bp::Parameters p = parametersFor(steady, elements);
      p.trackPoses = poses;
      p.trailLength = trail ? 8 : 0;
      p.trailInterval = 4 * dt;
      return median(
        [&]
        {
          bp::Engine e;
          e.configure(bp::builtinTemplate(bp::BuiltinShape::Strip16), p);
          const bp::RangeRunner run = bp::poolRunner(2);
          e.initialize(run);
          const auto start = Clock::now();
          for (int s = 0; s < steps; ++s)
            e.step(steady, s * dt, dt, run);
          return seconds(start);
        });
    };
    const double plain = rate(false, false), poses = rate(true, false), trail = rate(false, true);
    std::printf(
      "%9zu %16.1f %16.1f %16.1f\n", elements, steps / plain, steps / poses, steps / trail);
    std::fflush(stdout);
  }
  std::printf("peak resident memory: %.1f MiB\n", peakRssKiB() / 1024.0);
  if (csv)
    std::fclose(csv);
  return 0;
}
