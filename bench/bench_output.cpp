// SPDX-License-Identifier: BSD-3-Clause
// What the CPU path's output costs against the engine's step it shows, side
// by side in one run (issue 40): Strip16 elements on the 128^3 shear layer,
// the tracer's own output code (bpvtk::fillParticleOutput) with the default
// Output Arrays, and the cost of each array alone over the points. Every
// figure is the median of rounds as Play makes them (a step, then an output
// of it, the same arrays each round), wall clock and the process's CPU
// time, so a busy machine shows in both. Then the field sampled at every
// particle alone, in memory order, in space order and from hot cells, and
// the update the output's samples taken in the step would give, projected
// from those rows beside today's.
//
//   BoundParticlesOutputBench [--elements N]... [--threads T] [--rounds R]
#include "AnalyticFlows.h"
#include "Engine.h"
#include "OutputArrays.h"
#include "SampleAtPositions.h"
#include "TracerOutput.h"

#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

namespace
{
struct Cost
{
  double wall = 0.0, cpu = 0.0;
};

double cpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

Cost timed(const std::function<void()>& f)
{
  const auto wall = std::chrono::steady_clock::now();
  const double cpu = cpuSeconds();
  f();
  return { std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(),
    cpuSeconds() - cpu };
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// The frame the tracer would show: the grid is local (origin 0), the world's at -1.
bpvtk::OutputFrame frameOf(const bp::VectorField& field, double time)
{
  bpvtk::OutputFrame frame;
  frame.time = time;
  frame.offset = { -1, -1, -1 };
  frame.domain = field.grid().bounds();
  frame.reach = 1.0;
  frame.cellLength = field.grid().cellLength();
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    frame.wanted[std::size_t(row.id)] = row.onByDefault;
  }
  return frame;
}

struct Row
{
  std::string name;
  std::vector<double> wall, cpu;
};

void keep(Row& row, const Cost& c)
{
  row.wall.push_back(c.wall);
  row.cpu.push_back(c.cpu);
}

void printRows(const std::vector<Row>& rows, double step)
{
  for (const Row& row : rows)
  {
    std::printf("%-22s %10.2f %10.2f %10.2f\n", row.name.c_str(), 1e3 * median(row.wall),
      1e3 * median(row.cpu), median(row.wall) / step);
  }
}

void prefetchPositions(const float* p, std::size_t n)
{
#if defined(__GNUC__)
  for (std::size_t b = 0; b < 3 * n; b += 16)
    __builtin_prefetch(p + b);
#else
  (void)p;
  (void)n;
#endif
}

/// The elements sorted by the grid cell of their first particle: an order
/// in space, as the engine's step visits them.
std::vector<std::uint32_t> spaceOrder(const bp::Engine& engine, const bp::VectorField& field)
{
  const std::size_t n = engine.particlesPerElement();
  const bp::GridGeometry& g = field.grid();
  std::vector<std::uint64_t> keys(engine.elementCount());
  for (std::size_t e = 0; e < keys.size(); ++e)
  {
    const float* p = engine.positions().data() + 3 * e * n;
    std::uint64_t key = 0;
    for (int a = 2; a >= 0; --a)
    {
      const double c = std::floor((p[a] - g.origin[a]) / g.spacing[a]);
      key = key * std::uint64_t(g.dims[a] + 2) +
        std::uint64_t(std::clamp(c + 1.0, 0.0, double(g.dims[a] + 1)));
    }
    keys[e] = key;
  }
  std::vector<std::uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
    [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return order;
}

/**
 * What sampling the field at every particle costs, by where its cells are
 * (issue 40: would the output's samples be cheaper at the end of the step,
 * where the element's cells are hot in cache?). The output samples in memory
 * order (bp::sampleAtPositions); an element visited in space order has its
 * cells near the last element's; "hot" samples each element's particles
 * with velocity and curl right after sampling their velocity, as a step that
 * sampled again after restoring an element would. Its cost over the
 * velocity-only pass in space order is what such a step would add (it
 * would no longer sample at its start: the velocity at the end is the next
 * Euler step's first sample): returned, in wall seconds.
 */
double samplingRows(const bp::Engine& engine, const bp::VectorField& field, double t,
  const bp::RangeRunner& pool, int rounds, double step)
{
  const std::size_t count = engine.particleCount(), n = engine.particlesPerElement();
  const float* positions = engine.positions().data();
  const float weight = field.timeWeight(t);
  std::vector<float> velocity(3 * count), vorticity(count);
  const std::vector<std::uint32_t> order = spaceOrder(engine, field);
  // pass: 0 velocity, 1 velocity and curl, 2 velocity then velocity and curl.
  auto inSpaceOrder = [&](int pass)
  {
    pool(order.size(),
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t k = begin; k < end; ++k)
        {
          // Ahead as the step fetches: an element's positions, then its cells.
          constexpr std::size_t StateAhead = 16, FieldAhead = 6;
          if (k + StateAhead < end)
            prefetchPositions(positions + 3 * n * order[k + StateAhead], n);
          for (std::size_t i = 0; k + FieldAhead < end && i < n; ++i)
            field.prefetch(positions + 3 * (n * order[k + FieldAhead] + i));
          const std::size_t first = order[k] * n;
          for (std::size_t i = first; i < first + n && pass != 1; ++i)
            field.sampleWeighted(positions + 3 * i, weight, velocity.data() + 3 * i);
          for (std::size_t i = first; i < first + n && pass != 0; ++i)
            vorticity[i] =
              field.sampleWithVorticity(positions + 3 * i, weight, velocity.data() + 3 * i);
        }
      });
  };
  std::vector<Row> rows = { { "velocity, memory order", {}, {} }, { "  + curl", {}, {} },
    { "velocity, space order", {}, {} }, { "  + curl", {}, {} },
    { "  + hot curl after it", {}, {} } };
  const std::function<void()> passes[] = { [&]
    { bp::sampleAtPositions(field, t, positions, count, velocity.data(), nullptr, pool); },
    [&]
    { bp::sampleAtPositions(field, t, positions, count, velocity.data(), vorticity.data(), pool); },
    [&] { inSpaceOrder(0); }, [&] { inSpaceOrder(1); }, [&] { inSpaceOrder(2); } };
  for (int r = 0; r < rounds; ++r)
  {
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
      keep(rows[k], timed(passes[k]));
    }
  }
  std::printf("sampling at every particle, alone (alternated)\n");
  printRows(rows, step);
  return median(rows[4].wall) - median(rows[2].wall);
}

/// `elements` Strip16 elements released over the whole grid.
void configureStrips(bp::Engine& engine, std::size_t elements)
{
  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = 0.04f;
  for (int a = 0; a < 3; ++a)
  {
    p.emitterMin[a] = 0.0f;
    p.emitterMax[a] = 2.0f;
  }
  p.lifetimeMin = 2.0f;
  p.lifetimeMax = 4.0f;
  const std::string error = engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip16), p);
  if (!error.empty())
  {
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(1);
  }
}

/// Where Vorticity is among the arrays timed alone.
std::size_t vorticityRow(const std::vector<bp::OutputArrayId>& alone)
{
  return std::size_t(
    std::find(alone.begin(), alone.end(), bp::OutputArrayId::Vorticity) - alone.begin());
}

void run(std::size_t elements, unsigned threads, int rounds)
{
  const int res = 128;
  bp::GridGeometry g;
  g.dims = { res, res, res };
  g.origin = { 0, 0, 0 };
  const double h = 2.0 / (res - 1);
  g.spacing = { h, h, h };
  bp::FieldSlice slice;
  slice.velocity = std::make_shared<std::vector<float>>(
    bp::sampleAnalyticFlow(bp::AnalyticFlow::ShearLayer, g, 0.0));
  const bp::VectorField field(g, slice);
  const double dt = 0.5 * h / 1.25;
  bp::Engine engine;
  configureStrips(engine, elements);
  const bp::RangeRunner pool = bp::poolRunner(threads);
  engine.initialize(pool);
  double t = 0.0;
  for (int s = 0; s < 5; ++s, t += dt)
  {
    engine.step(field, t, dt, pool);
  }
  bpvtk::OutputStorage storage;
  // The arrays alone: each default array's output with the points only.
  std::vector<Row> rows = { { "step", {}, {} }, { "output (defaults)", {}, {} },
    { "  points only", {}, {} } };
  std::vector<bp::OutputArrayId> alone;
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    if (row.onByDefault && row.source != bp::ArraySource::TrailAge)
    {
      rows.push_back({ std::string("  + ") + row.name, {}, {} });
      alone.push_back(row.id);
    }
  }
  // Each output goes to a new polydata, as the tracer's output object is
  // handed on and the last one let go of (its arrays are reused).
  auto output = [&](const bpvtk::OutputFrame& frame)
  {
    vtkNew<vtkPolyData> out;
    return timed([&] { bpvtk::fillParticleOutput(out, engine, field, frame, storage, pool); });
  };
  // Rounds as Play makes them, a step and its output, with the same arrays
  // from one round to the next: the defaults; the points alone; each array
  // with the points.
  auto play = [&](const bpvtk::OutputFrame& wanted, Row* stepRow, Row& outputRow)
  {
    for (int r = 0; r < rounds; ++r)
    {
      const Cost step = timed([&] { engine.step(field, t, dt, pool); });
      t += dt;
      bpvtk::OutputFrame frame = wanted;
      frame.time = t;
      const Cost out = output(frame);
      if (r > 0) // the first round after a change of arrays writes them all
      {
        if (stepRow)
          keep(*stepRow, step);
        keep(outputRow, out);
      }
    }
  };
  bpvtk::OutputFrame frame = frameOf(field, t);
  play(frame, &rows[0], rows[1]);
  frame.wanted.fill(false);
  play(frame, nullptr, rows[2]);
  for (std::size_t k = 0; k < alone.size(); ++k)
  {
    frame.wanted.fill(false);
    frame.wanted[std::size_t(alone[k])] = true;
    Row with;
    play(frame, nullptr, with);
    const double wall = median(rows[2].wall), cpu = median(rows[2].cpu);
    for (std::size_t r = 0; r < with.wall.size(); ++r)
      keep(rows[3 + k], { with.wall[r] - wall, with.cpu[r] - cpu });
  }
  const double step = median(rows[0].wall);
  std::printf("\n%zu Strip16 elements (%zu particles), %u threads, medians of %d rounds\n",
    elements, engine.particleCount(), threads, rounds);
  std::printf("%-22s %10s %10s %10s\n", "", "wall ms", "cpu ms", "/ step");
  printRows(rows, step);
  const double update = step + median(rows[1].wall);
  std::printf("one-step update (step + output) / step: %.2f (target <= 1.3)\n", update / step);
  // The samples taken in the step instead: the step adds the hot curl, the
  // output no longer samples (Vorticity's row with the velocity it brings).
  const double added = samplingRows(engine, field, t, pool, rounds, step);
  const double sampled = median(rows[3 + vorticityRow(alone)].wall);
  std::printf("one-step update / step, samples in the step (projected): %.2f, as today: %.2f\n",
    (update + added - sampled) / step, update / step);
  std::fflush(stdout);
}
} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> counts;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  int rounds = 15;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--elements") && i + 1 < argc)
      counts.push_back(std::size_t(std::atol(argv[++i])));
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
      threads = unsigned(std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc)
      rounds = std::atoi(argv[++i]);
    else
    {
      std::fprintf(stderr, "usage: %s [--elements N]... [--threads T] [--rounds R]\n", argv[0]);
      return 2;
    }
  }
  if (counts.empty())
    counts = { 4096, 65536 };
  std::printf("The CPU output against the engine's step: 128^3 shear layer, Strip16, default "
              "Output Arrays (Age only with trails)\n");
  for (std::size_t n : counts)
    run(n, threads, rounds);
  return 0;
}
