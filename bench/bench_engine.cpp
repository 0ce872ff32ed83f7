// SPDX-License-Identifier: BSD-3-Clause
// Speed of the engines, side by side in one run: the CPU engine (1 and 2
// threads, and all the host's cores where it has more) and the GPU engine
// (headless EGL) each way it steps (the fragment path, the compute path with
// a dispatch per kernel, the compute path's fused step: gpu_columns.h), on
// the element shapes and counts of thesis Table 4.1 plus single-particle
// elements, on a steady and an unsteady field, against a plain trilinear
// Euler loop (no springs) compiled in the same build. Every cell is the
// median of 5 timed runs after a warm-up. Each GPU column gives steps/s,
// particle-steps/s and the share of the device's memory bandwidth the
// state a step must move would take at that rate. Prints a table; --csv
// FILE also writes it as CSV; --pass-times adds each pass's GPU time per
// step for every row.
#include "AnalyticFlows.h"
#include "BenchFields.h"
#include "CounterHash.h"
#include "Engine.h"
#include "GpuEngine.h"
#include "HeadlessContext.h"
#include "gpu_columns.h"

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
#include <thread>
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
  benchmark::RegisterBenchmark("run",
    [&](benchmark::State& state)
    {
      for (auto _ : state)
        state.SetIterationTime(run());
    })
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

/// Each pass's GPU time per step, by row and GPU column (--pass-times).
void printPassTimes(
  const std::vector<std::pair<std::string, std::vector<std::vector<bp::PassTime>>>>& rows)
{
  for (const auto& row : rows)
  {
    std::printf("\nGPU time per step, by pass (GL_TIME_ELAPSED; on a software renderer the CPU "
                "clock around each finished pass), %s: ms per step (runs a step)\n",
      row.first.c_str());
    std::vector<std::string> passes;
    for (const auto& times : row.second)
      for (const bp::PassTime& t : times)
        if (std::find(passes.begin(), passes.end(), t.pass) == passes.end())
          passes.push_back(t.pass);
    std::printf("%-14s", "pass");
    for (const bench::GpuVariant& v : bench::gpuVariants())
      std::printf(" %18s", v.name);
    std::printf("\n");
    std::vector<double> totals(row.second.size(), 0.0);
    for (const std::string& pass : passes)
    {
      std::printf("%-14s", pass.c_str());
      for (std::size_t k = 0; k < row.second.size(); ++k)
      {
        const auto& times = row.second[k];
        const auto t = std::find_if(
          times.begin(), times.end(), [&](const bp::PassTime& x) { return x.pass == pass; });
        if (t == times.end())
          std::printf(" %18s", "-");
        else
          std::printf(" %11.3f (%3ld)", 1e3 * t->seconds, t->runs);
        totals[k] += t == times.end() ? 0.0 : t->seconds;
      }
      std::printf("\n");
    }
    std::printf("%-14s", "total");
    for (double total : totals)
      std::printf(" %11.3f      ", 1e3 * total);
    std::printf("\n");
  }
}

/// What the GPU engine said (its path, GpuPath.h), printed after the table
/// instead of inside its rows.
std::vector<std::string>& engineMessages()
{
  static std::vector<std::string> messages;
  return messages;
}

void keepMessage(const std::string& text, bool warning)
{
  engineMessages().push_back((warning ? "warning: " : "") + text);
}

/// The options.
struct Options
{
  int resolution = 128;
  bool quick = false, gpu = true, passTimes = false;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency()); ///< "all cores"
  double bandwidth = 0.0; ///< GB/s; 0: from the device's name, or measured
  std::string csvPath;
  std::vector<std::string> only; ///< "Strip16x65536": just these rows
};

/// False, after the usage, for arguments it does not know.
bool parse(int argc, char** argv, Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const bool value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--resolution") && value)
      o.resolution = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick"))
      o.quick = true;
    else if (!std::strcmp(argv[i], "--no-gpu"))
      o.gpu = false;
    else if (!std::strcmp(argv[i], "--pass-times"))
      o.passTimes = true;
    else if (!std::strcmp(argv[i], "--threads") && value)
      o.threads = unsigned(std::max(1, std::atoi(argv[++i])));
    else if (!std::strcmp(argv[i], "--bandwidth") && value)
      o.bandwidth = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--csv") && value)
      o.csvPath = argv[++i];
    else if (!std::strcmp(argv[i], "--only") && value)
      o.only.push_back(argv[++i]);
    else
    {
      std::fprintf(stderr,
        "usage: %s [--quick] [--no-gpu] [--pass-times] [--threads N] [--bandwidth GB/s]\n"
        "       [--resolution N] [--csv FILE] [--only SHAPExCOUNT]...\n"
        "  --quick       4096 elements of each shape only\n"
        "  --no-gpu      CPU engine and plain loop only\n"
        "  --pass-times  each GPU pass's time per step, for every row\n"
        "  --threads N   the CPU engine's \"all cores\" column (default: this host's cores)\n"
        "  --bandwidth   the GPU's memory bandwidth (default: known GPUs' data sheets;\n"
        "                on a software renderer this host's memory copy rate)\n"
        "  --only S xN   only the rows of shape S with N elements, e.g. --only Strip16x65536\n",
        argv[0]);
      return false;
    }
  }
  return true;
}

/// The rows: every shape and count asked for.
std::vector<Config> rowsFor(const Options& o)
{
  std::vector<Config> configs;
  const std::vector<std::size_t> counts = o.quick
    ? std::vector<std::size_t>{ 4096 }
    : std::vector<std::size_t>{ 256, 1024, 4096, 16384, 65536 };
  for (auto shape :
    { bp::BuiltinShape::Square, bp::BuiltinShape::Strip8, bp::BuiltinShape::Strip16 })
    for (std::size_t n : counts)
      configs.push_back({ shape, n });
  if (!o.quick)
  {
    configs.push_back({ bp::BuiltinShape::Point, 262144 });
    configs.push_back({ bp::BuiltinShape::Point, 1048576 });
  }
  if (o.only.empty())
    return configs;
  std::vector<Config> wanted;
  for (const std::string& name : o.only)
    for (auto shape : { bp::BuiltinShape::Point, bp::BuiltinShape::Square, bp::BuiltinShape::Strip8,
           bp::BuiltinShape::Strip16 })
      for (std::size_t n : { 256, 1024, 4096, 16384, 65536, 262144, 1048576 })
      {
        const bool seen = std::any_of(wanted.begin(), wanted.end(),
          [&](const Config& k) { return k.shape == shape && k.elements == n; });
        if (name == bp::builtinTemplate(shape).name + "x" + std::to_string(n) && !seen)
          wanted.push_back({ shape, n });
      }
  return wanted;
}

/// The CPU engine's steps per second on `threads` threads (median of 5).
double cpuStepsPerSecond(const bp::ElementTemplate& t, const bp::Parameters& p,
  const bp::VectorField& field, int steps, double dt, unsigned threads)
{
  return steps /
    median(
      [&]
      {
        bp::Engine engine;
        engine.configure(t, p);
        const bp::RangeRunner run = bp::poolRunner(threads);
        engine.initialize(run);
        const auto start = Clock::now();
        for (int s = 0; s < steps; ++s)
          engine.step(field, s * dt, dt, run);
        return seconds(start);
      });
}

/// The engine's state in bytes per element (the table's last column).
std::size_t stateBytesPerElement(const bp::ElementTemplate& t, const bp::Parameters& p)
{
  bp::Engine e;
  e.configure(t, p);
  e.initialize(bp::serialRunner());
  return (sizeof(float) *
             (e.positions().size() + e.normals().size() + e.forces().size() + e.lifetimes().size() +
               e.initialCenters().size() + e.orientations().size()) +
           e.generations().size() * 4 + e.resetFlags().size()) /
    p.numberOfElements;
}

/// The columns' heads, for the table and the CSV.
void printHeads(const Options& o, bool cpuAll, std::FILE* csv)
{
  std::printf("%-8s %-8s %9s %9s %10s %10s", "field", "shape", "elements", "particles", "CPU1 st/s",
    "CPU2 st/s");
  if (cpuAll)
    std::printf(" %10s", ("CPU" + std::to_string(o.threads) + " st/s").c_str());
  std::printf(" %9s %9s", "CPU Mps/s", "vs plain");
  for (const bench::GpuVariant& v : bench::gpuVariants())
    std::printf(" | %-8s %8s %8s %6s %5s", v.name, "st/s", "Mps/s", "%BW", "B/ps");
  std::printf(" %7s\n", "B/elem");
  if (csv)
  {
    std::fprintf(csv,
      "field,shape,elements,particles,cpu1_steps_per_s,cpu2_steps_per_s,"
      "cpu_all_threads,cpu_all_steps_per_s,cpu2_particle_steps_per_s,"
      "plain2_particle_steps_per_s,bytes_per_element");
    for (const bench::GpuVariant& v : bench::gpuVariants())
      std::fprintf(csv,
        ",%s_steps_per_s,%s_particle_steps_per_s,%s_bytes_per_particle_step,%s_bandwidth_share",
        v.name, v.name, v.name, v.name);
    std::fprintf(csv, "\n");
  }
}
} // namespace

int main(int argc, char** argv)
{
  Options o;
  if (!parse(argc, argv, o))
    return 2;
  const int resolution = o.resolution;
  const bench::Fields fields = bench::benchFields(resolution);
  const double h = fields.spacing;
  const bp::VectorField& steady = fields.steady;
  const bp::VectorField& unsteady = fields.unsteady;

  bp::setGpuMessageSink(keepMessage);
  bp::HeadlessContext context;
  std::string gpuName = "none", bandwidthSource;
  double bandwidth = 0.0;
  bool gpu = o.gpu;
  if (gpu)
  {
    const std::string error = context.create();
    gpu = error.empty();
    gpuName = gpu ? context.description() : error;
    const char* renderer = gpu ? reinterpret_cast<const char*>(glGetString(GL_RENDERER)) : "";
    if (gpu)
      bandwidth =
        bench::deviceBandwidth(o.bandwidth, renderer ? renderer : "", o.threads, bandwidthSource);
  }
  const std::vector<Config> configs = rowsFor(o);
  if (configs.empty())
  {
    std::fprintf(stderr, "--only matched no shape and count (names as in the table)\n");
    return 2;
  }
  const bool cpuAll = o.threads > 2;

  std::printf(
    "Bound particles, %d^3 fields; Euler, 1 averaged-Jacobi iteration; median of 5 runs\n",
    resolution);
  std::printf("GPU engine on: %s\n", gpuName.c_str());
  if (gpu)
    std::printf("GPU columns: fragment path, compute path (a dispatch per kernel), compute path's "
                "fused step; %%BW: the share of %.0f GB/s (%s) that the state a step moves "
                "(bytes per particle-step below) takes at that rate\n",
      bandwidth / 1e9, bandwidthSource.c_str());
  std::FILE* csv = o.csvPath.empty() ? nullptr : std::fopen(o.csvPath.c_str(), "w");
  printHeads(o, cpuAll, csv);
  std::vector<std::pair<std::string, std::vector<std::vector<bp::PassTime>>>> passTimes;

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
      const double one = cpuStepsPerSecond(t, p, field, steps, dt, 1);
      const double two = cpuStepsPerSecond(t, p, field, steps, dt, 2);
      const double all = cpuAll ? cpuStepsPerSecond(t, p, field, steps, dt, o.threads) : two;
      const double plain =
        median([&] { return referenceLoop(field, particles, steps, dt, bp::poolRunner(2)); });
      const char* fieldName = isUnsteady ? "unsteady" : "steady";
      std::printf("%-8s %-8s %9zu %9zu %10.1f %10.1f", fieldName, t.name.c_str(), c.elements,
        particles, one, two);
      if (cpuAll)
        std::printf(" %10.1f", all);
      const double ps = particles * two;
      std::printf(" %9.2f %8.2fx", ps / 1e6, (particles * steps / plain) / ps);
      std::vector<bench::GpuRate> rates;
      for (const bench::GpuVariant& v : bench::gpuVariants())
      {
        const bench::GpuRate r =
          gpu ? bench::gpuRate(v, t, p, field, steps, dt, false, median) : bench::GpuRate();
        const double rate = r.stepsPerSecond;
        const double share =
          bandwidth > 0.0 ? rate * particles * r.bytesPerParticleStep / bandwidth : 0.0;
        rates.push_back(r);
        std::printf(" | %-8s %8.1f %8.1f %5.1f%% %5.0f", "", rate, rate * particles / 1e6,
          100 * share, r.bytesPerParticleStep);
      }
      const std::size_t stateBytes = stateBytesPerElement(t, p);
      std::printf(" %7zu\n", stateBytes);
      if (csv)
      {
        std::fprintf(csv, "%s,%s,%zu,%zu,%.3f,%.3f,%u,%.3f,%.1f,%.1f,%zu", fieldName,
          t.name.c_str(), c.elements, particles, one, two, cpuAll ? o.threads : 2u, all, ps,
          particles * steps / plain, stateBytes);
        for (const bench::GpuRate& r : rates)
        {
          const double rate = r.stepsPerSecond, bytes = r.bytesPerParticleStep;
          std::fprintf(csv, ",%.3f,%.1f,%.1f,%.5f", rate, rate * particles, bytes,
            bandwidth > 0.0 ? rate * particles * bytes / bandwidth : 0.0);
        }
        std::fprintf(csv, "\n");
      }
      if (gpu && o.passTimes)
      {
        std::vector<std::vector<bp::PassTime>> times;
        for (const bench::GpuVariant& v : bench::gpuVariants())
          times.push_back(bench::gpuPassTimes(v, t, p, field, std::min(steps, 50), dt));
        passTimes.push_back(
          { std::string(fieldName) + " " + t.name + " x " + std::to_string(c.elements), times });
      }
      std::fflush(stdout);
    }
  }
  printPassTimes(passTimes);
  for (const std::string& message : engineMessages())
    std::printf("%s\n", message.c_str());
  // One-particle elements with RK4 (the job of ParaView's Particle Tracer)
  // against the plain RK4 loop: how close the engine runs to this machine's
  // limit when there is nothing to restore.
  std::printf("\nPoint elements, RK4, 2 threads: engine against the plain RK4 loop\n");
  std::printf(
    "%-8s %9s %14s %14s %9s\n", "field", "particles", "engine Mps/s", "plain Mps/s", "vs plain");
  const std::size_t points = o.quick ? 65536 : 262144;
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
