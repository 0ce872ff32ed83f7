// SPDX-License-Identifier: BSD-3-Clause
// The GPU figures' rows (issue 55), for the bundle's real_gpu.sh: Strip16 and
// one-particle elements at the particle counts asked (1 M, 4 M and 16 M on a
// GPU), on the steady field with Euler and the unsteady one with RK4, poses
// tracked on Strip16 (as the display runs it); the GPU engine each way it
// steps (fragment, compute with a dispatch per kernel, fused) and the CPU
// engine on every core. Each cell is warmed up, then timed over at least
// --min-time seconds or --min-steps steps (whichever is more, but never more
// than 4 times --min-time), the median of --repeats runs; glFinish ends each
// GPU run. Rows run from the smallest; a row whose time, estimated from the
// rows before it, would end past --budget seconds is listed as skipped.
//
//   BoundParticlesGpuRows [--particles N,N,...] [--shapes Strip16,Point] [--min-time S]
//     [--min-steps N] [--repeats R] [--threads T] [--no-cpu] [--budget S] [--csv FILE]
//     [--resolution N] [--paths fragment,compute,fused] [--fields steady,unsteady]
//
// --paths: the GPU columns to run (the others print n/a); --fields: the
// steady (Euler) rows, the unsteady (RK4) ones, or both.
#include "BenchFields.h"
#include "Engine.h"
#include "GpuEngine.h"
#include "HeadlessContext.h"
#include "gpu_columns.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>
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

/// What the GPU engine says (its path, GpuPath.h), printed after the table
/// instead of inside its rows; each once.
std::vector<std::string>& engineMessages()
{
  static std::vector<std::string> messages;
  return messages;
}

void keepMessage(const std::string& text, bool warning)
{
  const std::string line = (warning ? "warning: " : "") + text;
  auto& m = engineMessages();
  if (std::find(m.begin(), m.end(), line) == m.end())
    m.push_back(line);
}

struct Options
{
  std::vector<std::size_t> particles{ 1048576, 4194304, 16777216 };
  std::vector<std::string> shapes{ "Strip16", "Point" };
  std::vector<std::string> paths{ "fragment", "compute", "fused" };
  std::vector<std::string> fields{ "steady", "unsteady" };
  double minTime = 0.3, budget = 1e9;
  int minSteps = 100, repeats = 3, resolution = 128;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  bool cpu = true;
  std::string csvPath;
};

std::vector<std::string> split(const char* list)
{
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty())
      items.push_back(item);
  return items;
}

bool parse(int argc, char** argv, Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
    const std::string a = argv[i];
    if (a == "--no-cpu")
    {
      o.cpu = false;
      continue;
    }
    if (!value)
      return false;
    else if (a == "--particles")
    {
      o.particles.clear();
      for (const std::string& n : split(value))
        o.particles.push_back(std::size_t(std::max(1L, std::atol(n.c_str()))));
    }
    else if (a == "--shapes")
      o.shapes = split(value);
    else if (a == "--paths")
      o.paths = split(value);
    else if (a == "--fields")
      o.fields = split(value);
    else if (a == "--min-time")
      o.minTime = std::max(1e-3, std::atof(value));
    else if (a == "--min-steps")
      o.minSteps = std::max(1, std::atoi(value));
    else if (a == "--repeats")
      o.repeats = std::max(1, std::atoi(value));
    else if (a == "--threads")
      o.threads = unsigned(std::max(1, std::atoi(value)));
    else if (a == "--budget")
      o.budget = std::max(1.0, std::atof(value));
    else if (a == "--csv")
      o.csvPath = value;
    else if (a == "--resolution")
      o.resolution = std::max(8, std::atoi(value));
    else
      return false;
    ++i;
  }
  return !o.particles.empty() && !o.shapes.empty();
}

/// Steps per second of `run` (n steps, synchronised, its seconds): a first
/// step, then warmed up in doubling batches until one lasts half of minTime, then timed over
/// max(minTime, minSteps steps) capped at 4 minTime; the median of repeats.
double stepsPerSecond(const std::function<double(int)>& run, const Options& o, int& timedSteps)
{
  run(1); // the first step builds what it needs (programs, scratch): not timed
  int n = 1;
  double took = run(n);
  while (took < 0.5 * o.minTime && n < (1 << 20))
  {
    n *= 2;
    took = run(n);
  }
  const double perStep = std::max(took / n, 1e-9);
  const double cap = std::ceil(4.0 * o.minTime / perStep);
  timedSteps = int(std::max(1.0,
    std::min(std::max(std::ceil(o.minTime / perStep), double(o.minSteps)), std::max(cap, 1.0))));
  std::vector<double> rates;
  for (int r = 0; r < o.repeats; ++r)
    rates.push_back(timedSteps / run(timedSteps));
  std::sort(rates.begin(), rates.end());
  return rates[rates.size() / 2];
}

bp::BuiltinShape shapeNamed(const std::string& name, bool& known)
{
  for (auto s : { bp::BuiltinShape::Point, bp::BuiltinShape::Square, bp::BuiltinShape::Strip8,
         bp::BuiltinShape::Strip16 })
    if (bp::builtinTemplate(s).name == name)
    {
      known = true;
      return s;
    }
  known = false;
  return bp::BuiltinShape::Point;
}

struct Row
{
  bool unsteady;
  bp::BuiltinShape shape;
  std::size_t particles;
};

/// One row: each GPU column, then the CPU engine on every core; printed and
/// written to the CSV. Returns the seconds the row took.
double runRow(const Row& row, const bench::Fields& fields, const Options& o, bool gpu,
  double bandwidth, std::FILE* csv)
{
  const auto start = Clock::now();
  const bp::VectorField& field = row.unsteady ? fields.unsteady : fields.steady;
  const double dt = 0.5 * fields.spacing / field.maxSpeed();
  const bp::ElementTemplate t = bp::builtinTemplate(row.shape);
  const std::size_t elements = std::max<std::size_t>(1, row.particles / t.particleCount());
  const std::size_t particles = elements * t.particleCount();
  bp::Parameters p = bench::parametersFor(field, elements);
  p.integrator = row.unsteady ? bp::Integrator::RK4 : bp::Integrator::Euler;
  p.trackPoses = t.particleCount() > 1;
  const char* fieldName = row.unsteady ? "unsteady" : "steady";
  std::printf(
    "%-8s %-5s %-8s %9zu", fieldName, row.unsteady ? "RK4" : "Euler", t.name.c_str(), particles);
  std::fflush(stdout);
  std::string csvLine = std::string(fieldName) + "," + (row.unsteady ? "RK4" : "Euler") + "," +
    t.name + "," + std::to_string(particles);
  char cell[160];
  for (const bench::GpuVariant& v : bench::gpuVariants())
  {
    bp::GpuEngine engine;
    double rate = 0.0, bytes = 0.0;
    int steps = 0;
    const bool wanted = std::find(o.paths.begin(), o.paths.end(), v.name) != o.paths.end();
    if (gpu && wanted && bench::configureVariant(engine, v, t, p, field))
    {
      engine.initialize();
      double time = 0.0;
      rate = stepsPerSecond(
        [&](int n)
        {
          glFinish();
          const auto begin = Clock::now();
          for (int s = 0; s < n; ++s, time += dt)
            engine.step(time, dt);
          glFinish();
          return seconds(begin);
        },
        o, steps);
      bytes = bench::bytesPerParticleStep(engine, time, dt, particles);
      engine.release();
    }
    const double share = bandwidth > 0.0 ? rate * particles * bytes / bandwidth : 0.0;
    std::snprintf(cell, sizeof cell, " | %9.1f %9.3f %5.1f%% %5.0f %5d", rate,
      rate * particles / 1e9, 100.0 * share, bytes, steps);
    std::printf("%s", rate > 0.0 ? cell : " |       n/a       n/a    n/a     -     -");
    std::fflush(stdout);
    std::snprintf(
      cell, sizeof cell, ",%.3f,%.1f,%.1f,%.5f,%d", rate, rate * particles, bytes, share, steps);
    csvLine += cell;
  }
  double cpuRate = 0.0;
  int cpuSteps = 0;
  if (o.cpu)
  {
    bp::Engine engine;
    engine.configure(t, p);
    const bp::RangeRunner run = bp::poolRunner(o.threads);
    engine.initialize(run);
    double time = 0.0;
    Options cpuOptions = o;
    cpuOptions.minSteps = 1; // the CPU engine's rows: at least minTime, not 100 steps
    cpuRate = stepsPerSecond(
      [&](int n)
      {
        const auto begin = Clock::now();
        for (int s = 0; s < n; ++s, time += dt)
          engine.step(field, time, dt, run);
        return seconds(begin);
      },
      cpuOptions, cpuSteps);
  }
  std::printf(" | %9.2f %9.4f %5d\n", cpuRate, cpuRate * particles / 1e9, cpuSteps);
  std::snprintf(
    cell, sizeof cell, ",%u,%.3f,%.1f,%d", o.threads, cpuRate, cpuRate * particles, cpuSteps);
  if (csv)
    std::fprintf(csv, "%s%s\n", csvLine.c_str(), cell);
  std::fflush(stdout);
  return seconds(start);
}
} // namespace

int main(int argc, char** argv)
{
  Options o;
  if (!parse(argc, argv, o))
  {
    std::fprintf(stderr,
      "usage: %s [--particles N,N,...] [--shapes Strip16,Point] [--paths fragment,compute,fused]\n"
      "          [--fields steady,unsteady]\n"
      "          [--min-time S] [--min-steps N]\n"
      "          [--repeats R] [--threads T] [--no-cpu] [--budget S] [--csv FILE] "
      "[--resolution N]\n",
      argv[0]);
    return 2;
  }
  const auto start = Clock::now();
  std::vector<Row> rows;
  for (std::size_t n : o.particles)
    for (bool unsteady : { false, true })
      for (const std::string& name : o.shapes)
        if (std::find(o.fields.begin(), o.fields.end(), unsteady ? "unsteady" : "steady") !=
          o.fields.end())
        {
          bool known = false;
          const bp::BuiltinShape shape = shapeNamed(name, known);
          if (!known)
          {
            std::fprintf(
              stderr, "no element shape named %s (Point, Square, Strip8, Strip16)\n", name.c_str());
            return 2;
          }
          rows.push_back({ unsteady, shape, n });
      }
  const bench::Fields fields = bench::benchFields(o.resolution);
  bp::setGpuMessageSink(keepMessage);
  bp::HeadlessContext context;
  const std::string error = context.create();
  const bool gpu = error.empty();
  std::string source;
  const char* renderer = gpu ? reinterpret_cast<const char*>(glGetString(GL_RENDERER)) : "";
  const double bandwidth =
    gpu ? bench::deviceBandwidth(0.0, renderer ? renderer : "", o.threads, source) : 0.0;
  std::printf("GPU engine on: %s\n", gpu ? context.description().c_str() : error.c_str());
  std::printf("%d^3 fields; each cell warmed up, then timed over >= %.3g s or %d steps (at most "
              "%.3g s), median of %d; CPU engine on %u threads; %%BW: share of %.0f GB/s (%s) "
              "at %s\n",
    o.resolution, o.minTime, o.minSteps, 4 * o.minTime, o.repeats, o.threads, bandwidth / 1e9,
    source.c_str(), "each path's bytes a particle-step (B/ps: what its passes read and write)");
  std::printf("%-8s %-5s %-8s %9s", "field", "integ", "shape", "particles");
  for (const bench::GpuVariant& v : bench::gpuVariants())
    std::printf(" | %-9s %9s %6s %5s %5s", v.name, "Gps/s", "%BW", "B/ps", "steps");
  std::printf(" | %-9s %9s %5s\n", ("CPU" + std::to_string(o.threads)).c_str(), "Gps/s", "steps");
  std::FILE* csv = o.csvPath.empty() ? nullptr : std::fopen(o.csvPath.c_str(), "w");
  if (csv)
  {
    std::fprintf(csv, "field,integrator,shape,particles");
    for (const bench::GpuVariant& v : bench::gpuVariants())
      std::fprintf(csv,
        ",%s_steps_per_s,%s_particle_steps_per_s,%s_bytes_per_particle_step,%s_bandwidth_share,"
        "%s_steps",
        v.name, v.name, v.name, v.name, v.name);
    std::fprintf(csv, ",cpu_threads,cpu_steps_per_s,cpu_particle_steps_per_s,cpu_steps\n");
  }
  double lastSeconds = 0.0;
  std::size_t lastParticles = 0;
  int skipped = 0;
  for (const Row& row : rows)
  {
    // The row's time, as the last one's scaled by the particles.
    const double estimate =
      lastParticles ? lastSeconds * double(row.particles) / double(lastParticles) : 0.0;
    if (seconds(start) + estimate > o.budget)
    {
      std::printf("%-8s %-5s %-8s %9zu | skipped (budget: about %.0f s more, %.0f s left)\n",
        row.unsteady ? "unsteady" : "steady", row.unsteady ? "RK4" : "Euler",
        bp::builtinTemplate(row.shape).name.c_str(), row.particles, estimate,
        std::max(0.0, o.budget - seconds(start)));
      ++skipped;
      continue;
    }
    lastSeconds = runRow(row, fields, o, gpu, bandwidth, csv);
    lastParticles = row.particles;
  }
  if (csv)
    std::fclose(csv);
  for (const std::string& message : engineMessages())
    std::printf("%s\n", message.c_str());
  std::printf(
    "rows: %zu run, %d skipped, in %.1f s\n", rows.size() - skipped, skipped, seconds(start));
  return gpu ? 0 : 1;
}
