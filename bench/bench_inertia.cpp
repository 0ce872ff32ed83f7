// SPDX-License-Identifier: BSD-3-Clause
// Heavy particles' step cost (issue 44): the CPU engine's step with Inertia
// = Maxey-Riley against the same job without, side by side in one run
// (alternating, medians of --repeats), for one-particle and Strip16 elements
// with each integrator, on the 128^3 shear layer (steady) and the double gyre
// (unsteady, where du/dt is sampled too), on every core; then the GPU
// engine on each of its paths (fragment, compute with a dispatch per kernel,
// the fused step) in a headless EGL context: on this machine that is Mesa's
// llvmpipe, a CPU renderer, so its rows say how the passes' work grows, not
// what a real GPU takes. The target is at most 1.3 times the massless step.
//
//   BoundParticlesInertiaBench [--repeats R] [--resolution N] [--quick] [--cpu-only]
//                              [--interleaved S] [--threads T] [--in-cache] [--divide D]
//                              [--gpu-path fragment|compute|fused]
//
// --cpu-only skips the GPU engine's rows (what a CPU change is measured by).
// --interleaved S steps the massless and the heavy engine alternately, step
// by step, S steps each in one run, and takes each one's median step: both
// see the same load, so on a shared, busy machine the ratio holds still where
// whole runs' medians swing. --threads sets the CPU engine's threads (default
// every core). --in-cache runs the CPU rows with a 32nd of the elements
// (8,192 particles), whose state and a 64^3 field stay in the caches: what
// is left of the ratio there is arithmetic, not waiting for memory.
// --divide D runs every row, CPU and GPU, with a D-th of its elements, and
// --gpu-path the GPU rows of one path alone (the bundle's real_gpu.sh, on a
// short budget).
#include "BenchFields.h"
#include "Engine.h"
#include "GpuEngine.h"
#include "GpuPath.h"
#include "HeadlessContext.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Job
{
  const char* shape;
  bp::BuiltinShape builtin;
  std::size_t elements;
  bp::Integrator integrator;
  const char* integratorName;
};

/// Job `job` with or without heavy particles.
bp::Parameters jobParameters(const bp::VectorField& field, const Job& job, bool inertia)
{
  bp::Parameters p = bench::parametersFor(field, job.elements);
  p.integrator = job.integrator;
  if (inertia)
  {
    p.inertia = bp::Inertia::MaxeyRiley;
    p.responseTime = 0.05f;
    p.densityRatio = 1000.0f;
    p.gravity = { 0.0f, 0.0f, -1.0f };
  }
  return p;
}

/// The GPU engine's seconds per step, as stepSeconds (finished before the clock stops).
double gpuStepSeconds(const bp::VectorField& field, const Job& job, bool inertia, int steps)
{
  bp::GpuEngine gpu;
  if (!gpu.configure(bp::builtinTemplate(job.builtin), jobParameters(field, job, inertia))
         .empty() ||
    !gpu.setField(field).empty())
  {
    gpu.release();
    return -1.0;
  }
  gpu.initialize();
  const double dt = 0.01;
  gpu.step(0.0, dt);
  glFinish();
  const auto start = Clock::now();
  for (int s = 1; s <= steps; ++s)
  {
    gpu.step(s * dt, dt);
  }
  glFinish();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count() / steps;
  gpu.release();
  return seconds;
}

/// Seconds per step of `steps` steps of a fresh system (after one warm-up step).
double stepSeconds(
  const bp::VectorField& field, const Job& job, bool inertia, int steps, const bp::RangeRunner& run)
{
  bp::Engine engine;
  engine.configure(bp::builtinTemplate(job.builtin), jobParameters(field, job, inertia));
  engine.initialize(run);
  const double dt = 0.01;
  engine.step(field, 0.0, dt, run);
  const auto start = Clock::now();
  for (int s = 1; s <= steps; ++s)
  {
    engine.step(field, s * dt, dt, run);
  }
  return std::chrono::duration<double>(Clock::now() - start).count() / steps;
}
/// The massless and the heavy engine stepped alternately, `steps` steps
/// each: each one's median milliseconds per step.
std::pair<double, double> interleavedMedians(
  const bp::VectorField& field, const Job& job, int steps, const bp::RangeRunner& run)
{
  bp::Engine engines[2];
  std::vector<double> times[2];
  const double dt = 0.01;
  for (int i = 0; i < 2; ++i)
  {
    engines[i].configure(bp::builtinTemplate(job.builtin), jobParameters(field, job, i == 1));
    engines[i].initialize(run);
    engines[i].step(field, 0.0, dt, run);
  }
  for (int s = 1; s <= steps; ++s)
  {
    for (int i = 0; i < 2; ++i)
    {
      const auto start = Clock::now();
      engines[i].step(field, s * dt, dt, run);
      times[i].push_back(1e3 * std::chrono::duration<double>(Clock::now() - start).count());
    }
  }
  return { median(times[0]), median(times[1]) };
}

void printGpuRows(const bench::Fields& fields, const Job (&allJobs)[4], int repeats, int steps,
  bool quick, std::size_t divide, const std::string& only)
{
  // --quick: a sixteenth of the elements (llvmpipe steps 262,144 particles slowly).
  std::vector<Job> jobs(std::begin(allJobs), std::end(allJobs));
  for (Job& job : jobs)
    job.elements = std::max<std::size_t>(1, job.elements / (quick ? 16 : 1) / divide);
  bp::HeadlessContext context;
  const std::string error = context.create();
  if (!error.empty())
  {
    std::printf("GPU engine: not measured (no headless OpenGL context: %s)\n", error.c_str());
    return;
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::printf("\nGPU engine on %s (llvmpipe is Mesa's CPU renderer: not a GPU's timing)\n",
    renderer ? renderer : "?");
  std::printf("%-8s %-9s %-8s %-9s %8s %14s %14s %7s %s\n", "shape", "field", "integr.", "path",
    "particles", "massless ms", "inertia ms", "ratio", "target <= 1.3");
  const char* paths[3][3] = { { "fragment", "fragment", "off" }, { "compute", "compute", "off" },
    { "fused", "compute", "on" } };
  for (const auto& path : paths)
  {
    if (!only.empty() && only != path[0])
      continue;
    setenv(bp::GpuPathVariable, path[1], 1);
    setenv(bp::FusedStepVariable, path[2], 1);
    for (const Job& job : jobs)
    {
      const bp::VectorField& field = fields.unsteady;
      std::vector<double> off, on;
      for (int r = 0; r < repeats; ++r)
      {
        off.push_back(gpuStepSeconds(field, job, false, steps));
        on.push_back(gpuStepSeconds(field, job, true, steps));
      }
      const double a = median(off), b = median(on);
      const std::size_t particles = job.elements * bp::builtinTemplate(job.builtin).particleCount();
      std::printf("%-8s %-9s %-8s %-9s %8zu %14.3f %14.3f %7.2f %s\n", job.shape, "unsteady",
        job.integratorName, path[0], particles, 1e3 * a, 1e3 * b, b / a,
        b / a <= 1.3 ? "met" : "missed");
      std::fflush(stdout);
    }
  }
  unsetenv(bp::GpuPathVariable);
  unsetenv(bp::FusedStepVariable);
}
} // namespace

int main(int argc, char** argv)
{
  int repeats = 5, resolution = 128, steps = 20;
  bool quick = false, cpuOnly = false, inCache = false;
  int interleaved = 0;
  std::size_t divide = 1;
  int repeatsGiven = 0; // --repeats wins over --quick's
  std::string gpuPath;  // --gpu-path: that path's rows alone
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  for (int a = 1; a < argc; ++a)
  {
    if (!std::strcmp(argv[a], "--repeats") && a + 1 < argc)
      repeatsGiven = std::max(1, std::atoi(argv[++a]));
    else if (!std::strcmp(argv[a], "--resolution") && a + 1 < argc)
      resolution = std::max(8, std::atoi(argv[++a]));
    else if (!std::strcmp(argv[a], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[a], "--cpu-only"))
      cpuOnly = true;
    else if (!std::strcmp(argv[a], "--interleaved") && a + 1 < argc)
      interleaved = std::max(1, std::atoi(argv[++a]));
    else if (!std::strcmp(argv[a], "--threads") && a + 1 < argc)
      threads = unsigned(std::max(1, std::atoi(argv[++a])));
    else if (!std::strcmp(argv[a], "--in-cache"))
      inCache = true;
    else if (!std::strcmp(argv[a], "--gpu-path") && a + 1 < argc)
      gpuPath = argv[++a];
    else if (!std::strcmp(argv[a], "--divide") && a + 1 < argc)
      divide = std::size_t(std::max(1, std::atoi(argv[++a])));
  }
  if (quick)
  {
    repeats = 3;
    resolution = 64;
    steps = 5;
  }
  repeats = repeatsGiven > 0 ? repeatsGiven : repeats;
  const bench::Fields fields = bench::benchFields(resolution);
  const bp::RangeRunner run = bp::poolRunner(threads);
  const Job jobs[] = {
    { "Point", bp::BuiltinShape::Point, 262144, bp::Integrator::Euler, "Euler" },
    { "Point", bp::BuiltinShape::Point, 262144, bp::Integrator::RK4, "RK4" },
    { "Strip16", bp::BuiltinShape::Strip16, 16384, bp::Integrator::Euler, "Euler" },
    { "Strip16", bp::BuiltinShape::Strip16, 16384, bp::Integrator::RK2, "RK2" },
  };
  const std::size_t cpuShare = (inCache ? 32 : 1) * divide;
  const std::string share =
    ", a " + std::to_string(cpuShare) + "th of the elements" + (inCache ? " (in cache)" : "");
  const char* where = cpuShare > 1 ? share.c_str() : "";
  if (interleaved)
  {
    std::printf("Heavy particles against massless, CPU engine, %u threads, %d^3 grid%s, stepped "
                "alternately, medians of %d steps each\n",
      threads, resolution, where, interleaved);
  }
  else
  {
    std::printf("Heavy particles against massless, CPU engine, %u threads, %d^3 grid%s, medians "
                "of %d runs of %d steps\n",
      threads, resolution, where, repeats, steps);
  }
  std::printf("%-8s %-9s %-8s %8s %14s %14s %7s %s\n", "shape", "field", "integr.", "particles",
    "massless ms", "inertia ms", "ratio", "target <= 1.3");
  for (Job job : jobs)
  {
    job.elements = std::max<std::size_t>(1, job.elements / cpuShare);
    for (int f = 0; f < 2; ++f)
    {
      const bp::VectorField& field = f == 0 ? fields.steady : fields.unsteady;
      double a, b;
      if (interleaved)
      {
        std::tie(a, b) = interleavedMedians(field, job, interleaved, run);
        a *= 1e-3;
        b *= 1e-3;
      }
      else
      {
        std::vector<double> off, on;
        for (int r = 0; r < repeats; ++r)
        {
          off.push_back(stepSeconds(field, job, false, steps, run));
          on.push_back(stepSeconds(field, job, true, steps, run));
        }
        a = median(off);
        b = median(on);
      }
      const std::size_t particles = job.elements * bp::builtinTemplate(job.builtin).particleCount();
      std::printf("%-8s %-9s %-8s %8zu %14.3f %14.3f %7.2f %s\n", job.shape,
        f == 0 ? "steady" : "unsteady", job.integratorName, particles, 1e3 * a, 1e3 * b, b / a,
        b / a <= 1.3 ? "met" : "missed");
    }
  }
  std::fflush(stdout);
  if (!cpuOnly)
  {
    printGpuRows(fields, jobs, repeats, steps, quick, divide, gpuPath);
  }
  return 0;
}
