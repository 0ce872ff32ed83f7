// SPDX-License-Identifier: BSD-3-Clause
// Frame times of the GPU engine while an unsteady field's time steps go by
// (issue 4): every frame steps the system once; a frame that crosses into a
// new data interval makes the next time step resident. Two ways, side by
// side in one run, on the same field and system:
//   whole:    the time step is uploaded whole in the frame that needs it (before);
//   streamed: each frame also uploads a slab of the time step after the
//             current interval within a 4 ms budget, as the Bound Particles
//             display does, so the crossing finds it resident (after).
// Every frame ends with glFinish, so its time includes the GPU's work.
// Prints, per way, the median frame in the middle of an interval and the
// median and worst frame that crosses a time step.
#include "AnalyticFlows.h"
#include "GpuEngine.h"
#include "HeadlessContext.h"

#include <epoxy/gl.h>

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
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}
} // namespace

int main(int argc, char** argv)
{
  int resolution = 128, framesPerInterval = 6, intervals = 8;
  std::size_t elements = 4096;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--resolution") && i + 1 < argc)
      resolution = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--frames-per-interval") && i + 1 < argc)
      framesPerInterval = std::max(2, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--elements") && i + 1 < argc)
      elements = std::size_t(std::atol(argv[++i]));
    else if (!std::strcmp(argv[i], "--quick"))
      intervals = 4;
  }
  bp::HeadlessContext context;
  const std::string contextError = context.create();
  if (!contextError.empty())
  {
    std::printf("no GPU engine here: %s\n", contextError.c_str());
    return 0;
  }

  bp::GridGeometry g;
  g.dims = { resolution, resolution, resolution };
  g.origin = { -1, -1, -1 };
  const double h = 2.0 / (resolution - 1);
  g.spacing = { h, h, h };
  // Distinct time steps (each its own allocation, as a reader delivers them),
  // computed from three samples of the double gyre to keep the set-up short.
  const double interval = 0.5;
  std::vector<std::vector<float>> samples;
  for (int k = 0; k < 3; ++k)
    samples.push_back(bp::sampleAnalyticFlow(bp::AnalyticFlow::DoubleGyre, g, interval * k));
  std::vector<bp::FieldSlice> series;
  for (int k = 0; k <= intervals + 1; ++k)
  {
    bp::FieldSlice s;
    s.time = interval * k;
    s.velocity = std::make_shared<std::vector<float>>(samples[std::size_t(k) % samples.size()]);
    series.push_back(s);
  }

  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = 0.05f;
  p.emitterMin = { -1.0f, -1.0f, -1.0f };
  p.emitterMax = { 1.0f, 1.0f, 1.0f };
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip8);
  const double megabytes = double(g.pointCount()) * 12.0 / (1 << 20);
  std::printf("GPU engine on %s\n", context.description().c_str());
  std::printf("%d^3 field (%.0f MiB per time step), %zu Strip8 elements, %d frames per data "
              "interval, %d intervals, one step per frame\n\n",
    resolution, megabytes, elements, framesPerInterval, intervals);
  std::printf(
    "%-10s %14s %16s %16s\n", "uploads", "middle (ms)", "crossing (ms)", "worst cross (ms)");

  for (int streamed = 0; streamed < 2; ++streamed)
  {
    bp::GpuEngine gpu;
    if (!gpu.configure(shape, p).empty())
      return 1;
    std::vector<double> middle, crossing;
    const double dt = interval / framesPerInterval;
    for (int k = 0; k < intervals; ++k)
    {
      for (int f = 0; f < framesPerInterval; ++f)
      {
        const auto start = Clock::now();
        if (f == 0)
        {
          const std::string error =
            gpu.setField(bp::VectorField(g, series[std::size_t(k)], series[std::size_t(k) + 1]));
          if (!error.empty())
          {
            std::printf("%s\n", error.c_str());
            return 1;
          }
          if (k == 0)
            gpu.initialize();
        }
        gpu.step(interval * k + dt * f, dt);
        if (streamed)
          gpu.stageSliceWithin(series[std::size_t(k) + 2], 0.004);
        glFinish();
        const double ms = 1e3 * std::chrono::duration<double>(Clock::now() - start).count();
        if (k == 0)
          continue; // the first interval uploads two time steps and compiles
        (f == 0 ? crossing : middle).push_back(ms);
      }
    }
    gpu.release();
    std::printf("%-10s %14.1f %16.1f %16.1f\n", streamed ? "streamed" : "whole", median(middle),
      median(crossing), *std::max_element(crossing.begin(), crossing.end()));
  }
  return 0;
}
