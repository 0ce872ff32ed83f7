// SPDX-License-Identifier: BSD-3-Clause
// Step plus draw without ParaView (issue 55): what a frame of Play costs the
// GPU, in frames per second, for the step alone, the draw alone, and both,
// on each way the GPU engine steps (fragment, compute with a dispatch per
// kernel, fused). The step is the display's (GpuStepper: poses tracked, then
// the normals recomputed, as the mapper does after its steps), Strip16
// elements on the steady shear layer with Euler; the draw is the display's
// own draw shaders and vertex texture fetch without VTK (element_draw.h),
// into an offscreen framebuffer (1920x1080 RGBA8 and depth by default),
// coloured by Force. bench/step_draw.py measures the same in ParaView.
//
// Each cell is warmed up, then timed over at least --min-time seconds or
// --min-frames frames (whichever is more, at most 4 times --min-time), the
// median of --repeats runs. Times come from GPU timer queries, one
// GL_TIME_ELAPSED query around each frame (PassTimer.h; on a software
// renderer, whose queries do not time deferred work, the CPU clock around
// each finished frame); the wall column is the frames over the wall clock,
// glFinish at both ends. After each path's last frame the framebuffer is
// read back: "drawn" counts the pixels that differ from the clear colour.
//
//   BoundParticlesStepDrawBench [--elements N | --particles N] [--size WxH]
//     [--paths fragment,compute,fused] [--min-time S] [--min-frames N] [--repeats R]
//     [--seconds S] [--resolution N] [--element-size L]
//
// --paths: the paths to run, in this order. --seconds: the budget; a path
// whose time, estimated from the path before it, would end past it is listed
// as skipped. The last line sums up each path's step plus draw. Exits 0
// unless there is no context (1), an argument is bad (2), or the draw
// failed: it did not compile, a path's last frame drew no pixel, or OpenGL
// reported an error (3).
#include "BenchFields.h"
#include "GpuEngine.h"
#include "HeadlessContext.h"
#include "PassTimer.h"
#include "element_draw.h"
#include "gpu_columns.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// The target beside the figures (issue 39), at 1 M particles and more.
constexpr double TargetFps = 200.0;
constexpr std::size_t TargetParticles = 1 << 20;

struct Options
{
  std::size_t elements = 65536; // 1 M Strip16 particles
  int width = 1920, height = 1080;
  std::vector<std::string> paths{ "fragment", "compute", "fused" };
  double minTime = 0.3, budget = 1e9;
  int minFrames = 100, repeats = 3, resolution = 128;
  float elementSize = 0.02f; // as bench/step_draw.py
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
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i];
    const char* value = argv[i + 1];
    if (a == "--elements")
      o.elements = std::size_t(std::max(1L, std::atol(value)));
    else if (a == "--particles")
      o.elements = std::size_t(std::max(1L, std::atol(value) / 16));
    else if (a == "--size")
    {
      if (std::sscanf(value, "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1)
        return false;
    }
    else if (a == "--paths")
      o.paths = split(value);
    else if (a == "--min-time")
      o.minTime = std::max(1e-3, std::atof(value));
    else if (a == "--min-frames")
      o.minFrames = std::max(1, std::atoi(value));
    else if (a == "--repeats")
      o.repeats = std::max(1, std::atoi(value));
    else if (a == "--seconds")
      o.budget = std::max(1.0, std::atof(value));
    else if (a == "--resolution")
      o.resolution = std::max(8, std::atoi(value));
    else if (a == "--element-size")
      o.elementSize = float(std::max(1e-4, std::atof(value)));
    else
      return false;
  }
  for (const std::string& name : o.paths)
    if (std::none_of(bench::gpuVariants().begin(), bench::gpuVariants().end(),
          [&](const bench::GpuVariant& v) { return name == v.name; }))
      return false;
  return argc % 2 == 1 && !o.paths.empty();
}

/// One timed run: the frames' time by the timer queries and by the wall clock.
struct Run
{
  double timed = 0.0; ///< seconds, the sum of the frames' timer queries
  double wall = 0.0;  ///< seconds, glFinish at both ends
};

/// One cell: frames per second by the queries (the median of the runs) and
/// by the wall clock (the same run's), and the frames each run timed.
struct Cell
{
  double fps = 0.0, wallFps = 0.0;
  int frames = 0;
};

/// `frame` n times, each inside the timer's query.
Run timeFrames(const std::function<void()>& frame, int n)
{
  bp::PassTimer timer;
  timer.enable(true);
  glFinish();
  const auto start = Clock::now();
  for (int k = 0; k < n; ++k)
  {
    timer.begin("frame");
    frame();
    timer.end();
  }
  glFinish();
  Run run;
  run.wall = seconds(start);
  for (const bp::PassTime& t : timer.collect())
    run.timed += t.seconds;
  timer.enable(false);
  return run;
}

/// A first frame (not timed), frames in doubling batches until one lasts
/// half of minTime, then `repeats` runs of max(minTime, minFrames frames),
/// at most 4 minTime; the median run by the queries.
Cell timeCell(const std::function<void()>& frame, const Options& o)
{
  timeFrames(frame, 1);
  int n = 1;
  Run run = timeFrames(frame, n);
  while (run.timed < 0.5 * o.minTime && n < (1 << 20))
  {
    n *= 2;
    run = timeFrames(frame, n);
  }
  const double perFrame = std::max(run.timed / n, 1e-9);
  const double cap = std::max(1.0, std::ceil(4.0 * o.minTime / perFrame));
  Cell cell;
  cell.frames = int(std::min(std::max(std::ceil(o.minTime / perFrame), double(o.minFrames)), cap));
  std::vector<Run> runs;
  for (int r = 0; r < o.repeats; ++r)
    runs.push_back(timeFrames(frame, cell.frames));
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.timed < b.timed; });
  const Run& median = runs[runs.size() / 2];
  cell.fps = median.timed > 0.0 ? cell.frames / median.timed : 0.0;
  cell.wallFps = median.wall > 0.0 ? cell.frames / median.wall : 0.0;
  return cell;
}

std::string cellText(const char* what, const Cell& c)
{
  char text[128];
  std::snprintf(text, sizeof text, " | %s %9.1f fps %8.3f ms (wall %9.1f)", what, c.fps,
    c.fps > 0.0 ? 1e3 / c.fps : 0.0, c.wallFps);
  return text;
}

/// The three cells of one path, the pixels drawn, the seconds it took.
struct PathResult
{
  bool ran = false;
  Cell step, draw, both;
  std::size_t drawn = 0;
  double configure = 0.0; ///< seconds to configure and initialise (compiling the passes)
  double seconds = 0.0;
};

PathResult runPath(const bench::GpuVariant& v, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, double dt, bench::ElementDraw& draw,
  const Options& o)
{
  const auto start = Clock::now();
  PathResult r;
  bp::GpuEngine engine;
  if (!bench::configureVariant(engine, v, shape, p, field))
    return r;
  engine.initialize();
  engine.updateNormals();
  glFinish();
  r.configure = seconds(start);
  double time = 0.0;
  const auto step = [&]
  {
    engine.step(time, dt);
    engine.updateNormals(); // as the mapper does after its steps
    time += dt;
  };
  const auto drawFrame = [&] { draw.draw(engine.drawInputs()); };
  r.step = timeCell(step, o);
  r.draw = timeCell(drawFrame, o);
  r.both = timeCell(
    [&]
    {
      step();
      drawFrame();
    },
    o);
  r.drawn = draw.drawnPixels();
  engine.release();
  r.ran = true;
  r.seconds = seconds(start);
  return r;
}
} // namespace

int main(int argc, char** argv)
{
  Options o;
  if (!parse(argc, argv, o))
  {
    std::fprintf(stderr,
      "usage: %s [--elements N | --particles N] [--size WxH] [--paths fragment,compute,fused]\n"
      "          [--min-time S] [--min-frames N] [--repeats R] [--seconds S] [--resolution N]\n"
      "          [--element-size L]\n",
      argv[0]);
    return 2;
  }
  const auto start = Clock::now();
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip16);
  const std::size_t particles = o.elements * shape.particleCount();
  const bench::Fields fields = bench::benchFields(o.resolution);
  const bp::VectorField& field = fields.steady;
  const double dt = 0.5 * fields.spacing / field.maxSpeed();
  bp::Parameters p = bench::parametersFor(field, o.elements);
  p.elementSize = o.elementSize;
  p.trackPoses = true; // as the display's engine (GpuStepper)

  bp::HeadlessContext context;
  const std::string error = context.create();
  if (!error.empty())
  {
    std::printf("no OpenGL context: %s\n", error.c_str());
    return 1;
  }
  std::printf("step plus draw: %zu Strip16 elements (%zu particles), %dx%d RGBA8 + depth, "
              "steady shear layer %d^3, Euler, poses tracked, coloured by Force\n",
    o.elements, particles, o.width, o.height, o.resolution);
  std::printf("renderer: %s\n", context.description().c_str());
  std::printf("each cell warmed up, then timed over >= %.3g s or %d frames (at most %.3g s), "
              "median of %d; fps from GPU timer queries (a GL_TIME_ELAPSED query a frame; on a "
              "software renderer the CPU clock around each finished frame), wall: over the wall "
              "clock\n",
    o.minTime, o.minFrames, 4 * o.minTime, o.repeats);
  std::printf("target (issue 39): >= %.0f fps step plus draw at 1 M particles\n", TargetFps);

  bench::ElementDraw draw;
  const std::string drawError = draw.create(shape, o.width, o.height);
  if (!drawError.empty())
  {
    std::printf("no draw: %s\n", drawError.c_str());
    return 3;
  }
  // ParaView's camera of bench/step_draw.py: from (2.5, 2, 4) off the emitter's centre.
  std::array<float, 3> center{};
  for (std::size_t a = 0; a < 3; ++a)
    center[a] = 0.5f * (p.emitterMin[a] + p.emitterMax[a]);
  draw.setCamera({ center[0] + 2.5f, center[1] + 2.0f, center[2] + 4.0f }, center);

  double last = 0.0;
  int failed = 0;
  std::string summary;
  for (const std::string& name : o.paths)
  {
    const auto v = std::find_if(bench::gpuVariants().begin(), bench::gpuVariants().end(),
      [&](const bench::GpuVariant& g) { return name == g.name; });
    if (seconds(start) + last > o.budget)
    {
      std::printf("%-9s | skipped (budget: about %.0f s more, %.0f s left)\n", v->name, last,
        std::max(0.0, o.budget - seconds(start)));
      summary += std::string(summary.empty() ? "" : ", ") + v->name + " skipped";
      continue;
    }
    const PathResult r = runPath(*v, shape, p, field, dt, draw, o);
    if (!r.ran)
    {
      std::printf("%-9s | n/a (not on this context)\n", v->name);
      summary += std::string(summary.empty() ? "" : ", ") + v->name + " n/a";
      continue;
    }
    last = r.seconds;
    std::printf("%-9s%s%s%s | drawn %zu px (%.1f%%) | %.1f s (configured in %.1f)\n", v->name,
      cellText("step", r.step).c_str(), cellText("draw", r.draw).c_str(),
      cellText("step+draw", r.both).c_str(), r.drawn,
      100.0 * double(r.drawn) / (double(o.width) * o.height), r.seconds, r.configure);
    if (particles >= TargetParticles)
      std::printf("%-9s   step plus draw %.1f fps at %zu particles: %s the target of %.0f fps\n",
        v->name, r.both.fps, particles, r.both.fps >= TargetFps ? "meets" : "below", TargetFps);
    std::fflush(stdout);
    char text[64];
    std::snprintf(text, sizeof text, "%s %.1f fps", v->name, r.both.fps);
    summary += std::string(summary.empty() ? "" : ", ") + text;
    failed += r.drawn == 0 ? 1 : 0;
  }
  std::printf(
    "step+draw: %s; %zu particles, %dx%d\n", summary.c_str(), particles, o.width, o.height);
  const GLenum glError = glGetError();
  draw.release();
  std::printf("done in %.1f s%s\n", seconds(start),
    glError != GL_NO_ERROR ? (", OpenGL error " + std::to_string(glError)).c_str() : "");
  return failed || glError != GL_NO_ERROR ? 3 : 0;
}
