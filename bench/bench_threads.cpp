// SPDX-License-Identifier: BSD-3-Clause
// How the CPU engine scales with threads (issue 40): steps per second at 1,
// 2, 4, 8 and 16 threads (those this machine has; the rest are listed as not
// measured), the parallel efficiency against one thread, and the memory
// bandwidth the step's state traffic reaches against the machine's own (a
// STREAM-like triad on the same threads, its memory placed by the threads
// that use it). Strip16 and one-particle elements on the 128^3 shear layer
// (steady) and the double gyre (unsteady); medians of --repeats runs.
//
//   BoundParticlesThreadsBench [--threads 1,2,4,8,16] [--repeats R] [--quick] [--divide D]
//
// --divide D runs every row with a D-th of its elements (the bundle's
// real_gpu.sh, on a short budget).
#include "AnalyticFlows.h"
#include "BenchFields.h"
#include "Engine.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
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

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/**
 * The machine's memory bandwidth on `threads` threads: a[i] = b[i] + s c[i]
 * over arrays much larger than the caches, each thread touching first (so
 * placing) the part it then works on; 3 arrays of 4-byte floats move 16 bytes
 * per element (a is written without being read only with streaming stores,
 * which the compiler does not use here: the write costs a read too).
 */
double triadBytesPerSecond(unsigned threads, int repeats)
{
  const std::size_t n = std::size_t(48) << 20; // 192 MB per array
  std::unique_ptr<float[]> a(new float[n]), b(new float[n]), c(new float[n]);
  const bp::RangeRunner run = bp::poolRunner(threads);
  run(n,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        a[i] = 0.0f;
        b[i] = 1.0f;
        c[i] = 2.0f;
      }
    });
  std::vector<double> rates;
  for (int r = 0; r < repeats + 1; ++r)
  {
    const auto start = Clock::now();
    run(n,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          a[i] = b[i] + 0.5f * c[i];
        }
      });
    if (r > 0) // the first is a warm-up
      rates.push_back(16.0 * double(n) / seconds(start));
  }
  return median(rates);
}

struct Job
{
  const char* name;
  bp::BuiltinShape shape;
  std::size_t elements;
  bool unsteady;
};

/// Steps per second of `job` on `threads` threads, and the bytes of state
/// each step reads and writes at least (every per-element array once each way).
std::pair<double, double> engineRate(
  const Job& job, const bp::VectorField& field, double dt, unsigned threads, int repeats)
{
  bp::Parameters p = bench::parametersFor(field, job.elements);
  p.elementSize = 0.04f; // as the tracer's benches (play_frames.py)
  const bp::ElementTemplate shape = bp::builtinTemplate(job.shape);
  const std::size_t particles = job.elements * shape.particleCount();
  const int steps = int(std::max<std::size_t>(5, 4000000 / particles));
  std::vector<double> rates;
  double bytes = 0.0;
  for (int r = 0; r < repeats; ++r)
  {
    bp::Engine engine;
    engine.configure(shape, p);
    const bp::RangeRunner run = bp::poolRunner(threads);
    engine.initialize(run);
    engine.step(field, 0.0, dt, run); // sizes the step's scratch, sorts the visiting order
    bytes = 2.0 *
      double(sizeof(float) *
          (engine.positions().size() + engine.forces().size() + engine.lifetimes().size() +
            engine.initialCenters().size() + engine.orientations().size()) +
        engine.generations().size() * 4 + engine.resetFlags().size());
    const auto start = Clock::now();
    for (int s = 1; s <= steps; ++s)
      engine.step(field, s * dt, dt, run);
    rates.push_back(steps / seconds(start));
  }
  return { median(rates), bytes };
}

std::vector<unsigned> parseThreads(const char* list)
{
  std::vector<unsigned> threads;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    threads.push_back(unsigned(std::max(1, std::atoi(item.c_str()))));
  return threads;
}
} // namespace

int main(int argc, char** argv)
{
  std::vector<unsigned> wanted = { 1, 2, 4, 8, 16 };
  int repeats = 3;
  bool quick = false;
  std::size_t divide = 1;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
      wanted = parseThreads(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc)
      repeats = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--divide") && i + 1 < argc)
      divide = std::size_t(std::max(1, std::atoi(argv[++i])));
    else
    {
      std::fprintf(
        stderr, "usage: %s [--threads 1,2,4,8,16] [--repeats R] [--quick] [--divide D]\n", argv[0]);
      return 2;
    }
  }
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<unsigned> counts, skipped;
  for (unsigned t : wanted)
    (t <= cores ? counts : skipped).push_back(t);
  const int res = 128;
  const bench::Fields fields = bench::benchFields(res);
  const double h = fields.spacing;
  const bp::VectorField& steady = fields.steady;
  const bp::VectorField& unsteady = fields.unsteady;
  std::vector<Job> jobs = { { "Strip16", bp::BuiltinShape::Strip16, 65536, false },
    { "Strip16", bp::BuiltinShape::Strip16, 65536, true },
    { "Point", bp::BuiltinShape::Point, 1048576, false } };
  if (!quick)
    jobs.insert(jobs.begin() + 1, { "Strip16", bp::BuiltinShape::Strip16, 16384, false });
  for (Job& job : jobs)
    job.elements = std::max<std::size_t>(1, job.elements / divide);

  std::printf("The CPU engine on 1 to %u threads (this machine has %u cores); %d^3 fields, "
              "Euler, medians of %d\n",
    counts.empty() ? 0 : counts.back(), cores, res, repeats);
  if (!skipped.empty())
  {
    std::printf("not measured (more threads than this machine's cores):");
    for (unsigned t : skipped)
      std::printf(" %u", t);
    std::printf("\n");
  }
  std::vector<double> triad;
  for (unsigned t : counts)
    triad.push_back(triadBytesPerSecond(t, repeats));
  std::printf("\n%-8s %-8s %9s %8s %10s %12s %11s %11s %9s\n", "field", "shape", "elements",
    "threads", "steps/s", "efficiency", "state GB/s", "triad GB/s", "of triad");
  for (const Job& job : jobs)
  {
    const bp::VectorField& field = job.unsteady ? unsteady : steady;
    const double dt = 0.5 * h / field.maxSpeed();
    double one = 0.0;
    for (std::size_t k = 0; k < counts.size(); ++k)
    {
      const auto [rate, bytes] = engineRate(job, field, dt, counts[k], repeats);
      one = k == 0 && counts[0] == 1 ? rate : one;
      const double efficiency = one > 0.0 ? rate / (counts[k] * one) : 0.0;
      std::printf("%-8s %-8s %9zu %8u %10.1f %11.0f%% %11.2f %11.2f %8.0f%%\n",
        job.unsteady ? "unsteady" : "steady", job.name, job.elements, counts[k], rate,
        100.0 * efficiency, bytes * rate / 1e9, triad[k] / 1e9, 100.0 * bytes * rate / triad[k]);
      std::fflush(stdout);
    }
  }
  std::printf("efficiency: steps/s over (threads x steps/s on 1 thread); state GB/s: each "
              "per-element array read and written once a step (a lower bound of the step's "
              "traffic: the field's reads and the restoration's repeated passes come on top); "
              "triad: a[i] = b[i] + s c[i] on the same threads, 16 bytes an element\n");
  return 0;
}
