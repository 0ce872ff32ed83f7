// SPDX-License-Identifier: BSD-3-Clause
#include "gpu_columns.h"

#include "PassTimer.h"
#include "PassTraffic.h"
#include "WorkQueue.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace bench
{
namespace
{
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// Data-sheet memory bandwidths (GB/s), by a part of the GL_RENDERER name;
/// the first match wins, so the longer names come first.
struct KnownDevice
{
  const char* name;
  double gigabytesPerSecond;
};
const KnownDevice KnownDevices[] = { { "H200", 4800.0 }, { "H100 NVL", 3900.0 },
  { "H100 PCIe", 2000.0 }, { "H100", 3350.0 } };

/// This host's memory copy rate (bytes read and written per second) on
/// `threads` threads: the best of 3 copies of 256 MiB.
double hostCopyRate(unsigned threads)
{
  const std::size_t bytes = std::size_t(256) << 20;
  std::vector<char> from(bytes, 1), to(bytes, 0);
  double best = 0.0;
  for (int round = 0; round < 3; ++round)
  {
    const auto start = Clock::now();
    std::vector<std::thread> workers;
    const std::size_t share = bytes / threads;
    for (unsigned t = 0; t < threads; ++t)
      workers.emplace_back([&, t] { std::memcpy(&to[t * share], &from[t * share], share); });
    for (std::thread& w : workers)
      w.join();
    best = std::max(best, 2.0 * double(share * threads) / seconds(start));
  }
  return best;
}

} // namespace

bool configureVariant(bp::GpuEngine& engine, const GpuVariant& variant,
  const bp::ElementTemplate& shape, const bp::Parameters& p, const bp::VectorField& field,
  bool generated)
{
  const char* was = std::getenv(bp::GpuPathVariable);
  const std::string before = was ? was : "";
  setenv(bp::GpuPathVariable, bp::gpuPathName(variant.path), 1);
  engine.setFusedSteps(variant.fused);
  engine.setGeneratedSprings(generated);
  const bool made = engine.configure(shape, p).empty() && engine.setField(field).empty() &&
    engine.path() == variant.path &&
    engine.fusedStep() == (variant.fused == bp::FusedSteps::Always);
  if (was)
    setenv(bp::GpuPathVariable, before.c_str(), 1);
  else
    unsetenv(bp::GpuPathVariable);
  if (!made)
    engine.release();
  return made;
}

const std::vector<GpuVariant>& gpuVariants()
{
  static const std::vector<GpuVariant> variants = {
    { "fragment", bp::GpuPath::Fragment, bp::FusedSteps::Never },
    { "compute", bp::GpuPath::Compute, bp::FusedSteps::Never },
    { "fused", bp::GpuPath::Compute, bp::FusedSteps::Always }
  };
  return variants;
}

double bytesPerParticleStep(bp::GpuEngine& engine, double t, double dt, std::size_t particles)
{
  bp::PassTraffic traffic;
  engine.setPassObserver(&traffic);
  engine.step(t, dt);
  engine.setPassObserver(nullptr);
  return double(traffic.bytes()) / double(std::max<std::size_t>(particles, 1));
}

double deviceBandwidth(
  double given, const std::string& renderer, unsigned threads, std::string& source)
{
  if (given > 0.0)
  {
    source = "as given";
    return given * 1e9;
  }
  for (const KnownDevice& device : KnownDevices)
    if (renderer.find(device.name) != std::string::npos)
    {
      source = std::string("the ") + device.name + "'s data sheet";
      return device.gigabytesPerSecond * 1e9;
    }
  if (bp::rendererKind(renderer) == bp::RendererKind::Software)
  {
    source = "this host's memory copy rate on " + std::to_string(threads) + " threads, measured";
    return hostCopyRate(threads);
  }
  source = "unknown (give --bandwidth GB/s)";
  return 0.0;
}

GpuRate gpuRate(const GpuVariant& variant, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, int steps, double dt, bool generated,
  const std::function<double(const std::function<double()>&)>& median)
{
  bp::GpuEngine engine;
  if (!configureVariant(engine, variant, shape, p, field, generated))
    return {};
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
  GpuRate rate;
  rate.stepsPerSecond = steps / took;
  rate.bytesPerParticleStep =
    bytesPerParticleStep(engine, steps * dt, dt, p.numberOfElements * shape.particleCount());
  engine.release();
  return rate;
}

std::vector<bp::PassTime> gpuPassTimes(const GpuVariant& variant,
  const bp::ElementTemplate& shape, const bp::Parameters& p, const bp::VectorField& field,
  int steps, double dt)
{
  bp::GpuEngine engine;
  if (!configureVariant(engine, variant, shape, p, field, false))
    return {};
  engine.initialize();
  for (int s = 0; s < std::min(steps, 3); ++s) // warm-up: the first runs compile
    engine.step(s * dt, dt);
  bp::PassTimer timer;
  timer.enable(true);
  engine.setPassObserver(&timer);
  for (int s = 0; s < steps; ++s)
    engine.step(s * dt, dt);
  std::vector<bp::PassTime> times = timer.collect();
  engine.setPassObserver(nullptr);
  timer.enable(false);
  engine.release();
  for (bp::PassTime& t : times)
  {
    t.seconds /= steps;
    t.runs = (t.runs + steps - 1) / steps; // per step
  }
  return times;
}

} // namespace bench
