// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's paths (Gpu/GpuPath.h): which one a context gets, the
// message that says so, the fused step against a dispatch per kernel, and the
// pass observer with the per-pass timer (Gpu/Support/PassTimer.h). The parity
// and physics suites run on every path (CMakeLists.txt), each checking that it
// runs the path asked for (TestGpuEngine.cpp: GpuPath.IsTheOneTheEnvironmentAsks).
#include "AnalyticFlows.h"
#include "GpuEngine.h"
#include "GpuPasses.h"
#include "PassTimer.h"
#include "PassTraffic.h"
#include "SharedContext.h"
#include "WorkQueue.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
/// What the engine said (setGpuMessageSink), in order.
std::vector<std::pair<std::string, bool>>& said()
{
  static std::vector<std::pair<std::string, bool>> messages;
  return messages;
}

void listen(const std::string& text, bool warning)
{
  said().push_back({ text, warning });
}

bp::VectorField rotation()
{
  bp::GridGeometry g;
  g.dims = { 16, 16, 16 };
  g.origin = { -1, -1, -1 };
  g.spacing = { 2.0 / 15, 2.0 / 15, 2.0 / 15 };
  bp::FieldSlice s;
  s.velocity = std::make_shared<std::vector<float>>(
    bp::sampleAnalyticFlow(bp::AnalyticFlow::SolidBodyRotation, g, 0.0));
  return bp::VectorField(g, s);
}

bp::Parameters strips(std::size_t elements)
{
  bp::Parameters p;
  p.numberOfElements = elements;
  p.elementSize = 0.1f;
  p.emitterMin = { -0.6f, -0.6f, -0.6f };
  p.emitterMax = { 0.6f, 0.6f, 0.6f };
  p.lifetimeMin = 0.1f;
  p.lifetimeMax = 0.3f; // resets within the run
  p.iterations = 3;
  p.trackPoses = true;
  p.seed = 5;
  return p;
}

/// Positions and poses after `steps` steps of a Strip16 system.
std::vector<float> trace(bp::GpuEngine& gpu, const bp::Parameters& p, int steps)
{
  const bp::VectorField field = rotation();
  EXPECT_EQ(gpu.configure(bp::builtinTemplate(bp::BuiltinShape::Strip16), p), "");
  EXPECT_EQ(gpu.setField(field), "");
  gpu.initialize();
  for (int s = 0; s < steps; ++s)
    gpu.step(0.01 * s, 0.01);
  std::vector<float> positions, poses;
  gpu.read(&positions, nullptr, nullptr);
  gpu.readPoses(&poses, nullptr);
  positions.insert(positions.end(), poses.begin(), poses.end());
  return positions;
}

/// The path and fused step the engines take from the environment, set for a
/// test and put back as they were when it goes.
class PathEnvironment
{
public:
  PathEnvironment()
    : Path(saved(bp::GpuPathVariable))
    , Fused(saved(bp::FusedStepVariable))
  {
  }
  ~PathEnvironment()
  {
    restore(bp::GpuPathVariable, this->Path);
    restore(bp::FusedStepVariable, this->Fused);
  }
  void set(const char* path, const char* fused) const
  {
    setenv(bp::GpuPathVariable, path, 1);
    setenv(bp::FusedStepVariable, fused, 1);
  }

private:
  using Saved = std::pair<bool, std::string>;
  static Saved saved(const char* name)
  {
    const char* value = std::getenv(name);
    return { value != nullptr, value ? value : "" };
  }
  static void restore(const char* name, const Saved& value)
  {
    if (value.first)
      setenv(name, value.second.c_str(), 1);
    else
      unsetenv(name);
  }
  Saved Path, Fused;
};
} // namespace

TEST(GpuPath, ComputeFromOpenGL43UnlessTheFragmentPathIsAsked)
{
  const std::string mesa = "4.5 (Core Profile) Mesa";
  bp::GpuPathChoice c = bp::chooseGpuPath(45, mesa, nullptr);
  EXPECT_EQ(c.path, bp::GpuPath::Compute);
  EXPECT_EQ(c.warning, "");
  EXPECT_NE(c.note.find("the compute path, chosen automatically, on OpenGL " + mesa), std::string::npos)
    << c.note;
  EXPECT_EQ(bp::chooseGpuPath(43, mesa, "").path, bp::GpuPath::Compute);
  EXPECT_EQ(bp::chooseGpuPath(45, mesa, "compute").path, bp::GpuPath::Compute);
  c = bp::chooseGpuPath(46, mesa, "fragment");
  EXPECT_EQ(c.path, bp::GpuPath::Fragment);
  EXPECT_NE(c.note.find("fragment path, as BOUNDPARTICLES_GPU_PATH asks"), std::string::npos)
    << c.note;
  EXPECT_EQ(bp::chooseGpuPath(42, "4.2", nullptr).path, bp::GpuPath::Fragment);
  EXPECT_EQ(bp::chooseGpuPath(33, "3.3", nullptr).warning, "");
}

TEST(GpuPath, ForcedComputeBelow43WarnsWithTheVersionAndRunsTheFragmentPath)
{
  const bp::GpuPathChoice c = bp::chooseGpuPath(41, "4.1 (Core Profile) Mesa 22.3.6", "compute");
  EXPECT_EQ(c.path, bp::GpuPath::Fragment);
  EXPECT_NE(c.warning.find("this OpenGL context is version 4.1"), std::string::npos) << c.warning;
  EXPECT_NE(c.warning.find("compute shaders need 4.3"), std::string::npos) << c.warning;
  EXPECT_NE(c.note.find("the fragment path"), std::string::npos) << c.note;
  // A value it does not know is said, and the choice is automatic.
  const bp::GpuPathChoice odd = bp::chooseGpuPath(45, "4.5", "vulkan");
  EXPECT_EQ(odd.path, bp::GpuPath::Compute);
  EXPECT_NE(odd.warning.find("=vulkan is not one of"), std::string::npos) << odd.warning;
}

TEST(GpuPath, StepsFuseOnAGpuUnlessTold)
{
  using F = bp::FusedSteps;
  const std::string gpu = "NVIDIA H200/PCIe/SSE2", software = "llvmpipe (LLVM 15.0.6, 256 bits)";
  EXPECT_TRUE(bp::fusesSteps(F::Automatic, gpu, nullptr));
  EXPECT_FALSE(bp::fusesSteps(F::Automatic, software, nullptr));
  EXPECT_TRUE(bp::fusesSteps(F::Automatic, software, "on"));
  EXPECT_FALSE(bp::fusesSteps(F::Automatic, gpu, "off"));
  EXPECT_TRUE(bp::fusesSteps(F::Always, software, "off")); // the caller's word wins
  EXPECT_FALSE(bp::fusesSteps(F::Never, gpu, "on"));
  // A value it does not know is said as BOUNDPARTICLES_GPU_PATH's is, and the
  // choice is automatic.
  std::string warning;
  EXPECT_FALSE(bp::fusesSteps(F::Automatic, software, "yes", &warning));
  EXPECT_NE(warning.find("BOUNDPARTICLES_GPU_FUSED_STEP=yes is not one of on, off or automatic:"),
    std::string::npos)
    << warning;
  EXPECT_TRUE(bp::fusesSteps(F::Automatic, gpu, "yes", &warning));
  EXPECT_TRUE(bp::fusesSteps(F::Automatic, gpu, "automatic", &warning));
  EXPECT_EQ(warning, "");
  EXPECT_TRUE(bp::fusesSteps(F::Automatic, software, "on", &warning));
  EXPECT_EQ(warning, "");
}

// BOUNDPARTICLES_FUSED_GROUP: the fused step's elements a workgroup, as
// asked where the limits hold them, fewer where they do not; a value that is
// not a whole number from 1 to 1024 is none (automatic).
TEST(GpuPath, FusedGroupIsSetWithinTheLimits)
{
  EXPECT_EQ(bp::fusedGroupValue(nullptr), 0);
  EXPECT_EQ(bp::fusedGroupValue(""), 0);
  EXPECT_EQ(bp::fusedGroupValue("16"), 16);
  EXPECT_EQ(bp::fusedGroupValue("16x"), 0);
  EXPECT_EQ(bp::fusedGroupValue("0"), 0);
  EXPECT_EQ(bp::fusedGroupValue("2048"), 0);
  bp::Parameters p;
  p.numberOfElements = 1000;
  const bp::ComputeLimits limits{ 1024, 49152, 8 };
  const int automatic = bp::FusedStep::of(p, 16, true, limits).groupElements;
  EXPECT_EQ(automatic, 32);
  EXPECT_EQ(bp::FusedStep::of(p, 16, true, limits, 8).groupElements, 8);
  EXPECT_EQ(bp::FusedStep::of(p, 16, true, limits, 16).groupElements, 16);
  // 64 Strip16 elements are 1024 threads: the most a workgroup holds.
  EXPECT_EQ(bp::FusedStep::of(p, 16, true, limits, 100).groupElements, 64);
  // Shared memory: 16 bytes a particle and 96 an element: 32 KiB hold 93.
  EXPECT_EQ(bp::FusedStep::of(p, 16, true, { 4096, 32768, 8 }, 200).groupElements, 93);
}

// The fused step stores into every element texture and the particles (and
// the slips of heavy particles) at once: a GPU whose compute stage binds
// fewer images gets the per-kernel passes, which store into at most four.
TEST(GpuPath, FusedStepNeedsAnImageUnitForEachTextureItStores)
{
  bp::Parameters p;
  p.numberOfElements = 1000;
  const int massless = bp::FusedStep::imagesBound(false);
  EXPECT_EQ(bp::FusedStep::imagesBound(true), massless + 1);
  EXPECT_GT(bp::FusedStep::of(p, 16, true, { 1024, 49152, massless }).groupElements, 0);
  EXPECT_EQ(bp::FusedStep::of(p, 16, true, { 1024, 49152, massless - 1 }).groupElements, 0);
  p.inertia = bp::Inertia::MaxeyRiley;
  p.responseTime = 0.1f;
  EXPECT_EQ(bp::FusedStep::of(p, 16, true, { 1024, 49152, massless }).groupElements, 0);
  EXPECT_GT(bp::FusedStep::of(p, 16, true, { 1024, 49152, massless + 1 }).groupElements, 0);
  // OpenGL 4.3 promises 8 compute image uniforms: every fused step fits.
  EXPECT_LE(bp::FusedStep::imagesBound(true), 8);
}

TEST(GpuPath, EnvironmentValuesAreCheckedAlike)
{
  std::string warning;
  EXPECT_EQ(bp::acceptedValue("V", "b", { "a", "b", "c" }, "it decides.", warning), "b");
  EXPECT_EQ(warning, "");
  EXPECT_EQ(bp::acceptedValue("V", nullptr, { "a", "b" }, "it decides.", warning), "");
  EXPECT_EQ(bp::acceptedValue("V", "", { "a", "b" }, "it decides.", warning), "");
  EXPECT_EQ(warning, "");
  EXPECT_EQ(bp::acceptedValue("V", "d", { "a", "b", "c" }, "it decides.", warning), "");
  EXPECT_EQ(warning, "V=d is not one of a, b or c: it decides.");
  // Both variables' messages come from it.
  const bp::GpuPathChoice odd = bp::chooseGpuPath(45, "4.5", "vulkan");
  EXPECT_EQ(odd.warning,
    "BOUNDPARTICLES_GPU_PATH=vulkan is not one of compute, fragment or automatic: the GPU "
    "engine chooses its path itself.");
}

// Run with BOUNDPARTICLES_GPU_PATH=compute on a context Mesa made to offer
// OpenGL 4.1 (ctest's GpuPath.ForcedComputeOnOpenGL41FallsBack): the engine
// runs its fragment path and warns once, naming the version.
TEST(GpuPath, ForcedComputeFallsBackBelow43)
{
  bp::setGpuMessageSink(listen);
  if (!bp::haveSharedContext())
    return;
  if (epoxy_gl_version() >= bp::ComputePathVersion)
    GTEST_SKIP() << "this context offers OpenGL " << epoxy_gl_version()
                 << " (MESA_GL_VERSION_OVERRIDE=4.1 acts on Mesa only)";
  bp::GpuEngine gpu;
  const std::vector<float> state = trace(gpu, strips(64), 5);
  EXPECT_EQ(gpu.path(), bp::GpuPath::Fragment);
  for (float v : state)
    ASSERT_TRUE(std::isfinite(v));
  gpu.release();
  bp::GpuEngine again;
  trace(again, strips(16), 1);
  again.release();
  bp::setGpuMessageSink(nullptr);
  int warnings = 0;
  for (const auto& message : said())
  {
    std::printf("%s%s\n", message.second ? "warning: " : "", message.first.c_str());
    if (message.second)
    {
      ++warnings;
      EXPECT_NE(message.first.find("version 4.1"), std::string::npos) << message.first;
    }
  }
  EXPECT_EQ(warnings, 1) << "said once for two configurations";
}

// A compute program the driver refuses (forced here: every compute program
// fails to compile) leaves the engine on its fragment path, with one warning
// that names the program and the compiler's message, and loses nothing: the
// same bits as the fragment path asked for.
TEST(GpuPath, ComputeCompileFailureFallsBackToTheFragmentPath)
{
  if (!bp::haveSharedContext())
    return;
  if (epoxy_gl_version() < bp::ComputePathVersion)
    GTEST_SKIP() << "no compute path on this context";
  said().clear();
  bp::setGpuMessageSink(listen);
  bp::setComputeCompileFailureForTesting(true);
  for (const char* fused : { "on", "off" })
  {
    const PathEnvironment environment;
    environment.set("compute", fused);
    bp::GpuEngine refused;
    const std::vector<float> got = trace(refused, strips(40), 6);
    EXPECT_EQ(refused.path(), bp::GpuPath::Fragment) << "fused " << fused;
    EXPECT_FALSE(refused.fusedStep());
    refused.release();
    environment.set("fragment", fused);
    bp::GpuEngine fragment;
    const std::vector<float> want = trace(fragment, strips(40), 6);
    fragment.release();
    ASSERT_EQ(got.size(), want.size());
    EXPECT_EQ(std::memcmp(got.data(), want.data(), got.size() * sizeof(float)), 0)
      << "the fallback runs the fragment path's kernels, bit for bit";
  }
  bp::setComputeCompileFailureForTesting(false);
  bp::setGpuMessageSink(nullptr);
  int warnings = 0;
  for (const auto& message : said())
  {
    std::printf("%s%s\n", message.second ? "warning: " : "", message.first.c_str());
    if (!message.second)
      continue;
    ++warnings;
    EXPECT_NE(message.first.find("compute path could not be built"), std::string::npos)
      << message.first;
    EXPECT_NE(message.first.find("does not compile"), std::string::npos) << message.first;
    EXPECT_NE(message.first.find("compute programs refused"), std::string::npos) << message.first;
    EXPECT_EQ(message.first.find('\n'), std::string::npos) << "one line";
  }
  // One for the per-kernel programs, one for the fused step's (a message is
  // said once per process unless its text differs).
  EXPECT_GE(warnings, 1);
  EXPECT_LE(warnings, 2);
}

// The fused step and a dispatch per kernel run the same kernels on the same
// values: they agree to the parity bar (on Mesa's llvmpipe, bit for bit).
TEST(GpuPath, FusedAndPerKernelStepsAgree)
{
  if (!bp::haveSharedContext())
    return;
  if (epoxy_gl_version() < bp::ComputePathVersion ||
    (std::getenv(bp::GpuPathVariable) &&
      std::strcmp(std::getenv(bp::GpuPathVariable), "fragment") == 0))
    GTEST_SKIP() << "the compute path does not run here";
  for (bp::Restoration r : { bp::Restoration::AveragedJacobi, bp::Restoration::GaussSeidel,
         bp::Restoration::ShapeMatching })
  {
    bp::Parameters p = strips(100);
    p.restoration = r;
    bp::GpuEngine fused, kernels;
    fused.setFusedSteps(bp::FusedSteps::Always);
    kernels.setFusedSteps(bp::FusedSteps::Never);
    const std::vector<float> a = trace(fused, p, 25), b = trace(kernels, p, 25);
    EXPECT_TRUE(fused.fusedStep());
    EXPECT_FALSE(kernels.fusedStep());
    ASSERT_EQ(a.size(), b.size());
    double worst = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
      worst = std::max(worst, double(std::abs(a[k] - b[k])));
    EXPECT_LT(worst, 1e-4 * std::sqrt(12.0)) << "restoration " << int(r);
    std::printf("restoration %d: fused and per kernel differ by %.3g%s\n", int(r), worst,
      std::memcmp(a.data(), b.data(), 4 * a.size()) == 0 ? " (the same bits)" : "");
    fused.release();
    kernels.release();
  }
}

// On a software renderer (llvmpipe) a compute dispatch runs when the next
// command needs it, so a GL_TIME_ELAPSED query charged each pass with the
// one before it (the reset pass, which does next to nothing when no release
// is due, measured 35 times the fragment path's). There the timer reads the
// CPU clock around each finished pass: each pass gets its own time, and the
// reset pass stays below the advect pass.
TEST(GpuEngine, PassTimesOnASoftwareRendererAreEachPasssOwn)
{
  if (!bp::haveSharedContext())
    return;
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (bp::rendererKind(renderer ? renderer : "") != bp::RendererKind::Software ||
    epoxy_gl_version() < bp::ComputePathVersion)
    GTEST_SKIP() << "a software renderer with the compute path only";
  const PathEnvironment environment;
  environment.set("compute", "off");
  bp::Parameters p = strips(4096);
  p.lifetimeMin = p.lifetimeMax = 100.0f; // no release due: the reset pass has nothing to do
  p.iterations = 1;
  bp::GpuEngine gpu;
  trace(gpu, p, 1);
  bp::PassTimer timer;
  timer.enable(true);
  gpu.setPassObserver(&timer);
  for (int s = 0; s < 4; ++s)
    gpu.step(0.01 * (s + 1), 0.01);
  const std::vector<bp::PassTime> times = timer.collect();
  gpu.setPassObserver(nullptr);
  timer.enable(false);
  gpu.release();
  double reset = -1.0, advect = -1.0;
  for (const bp::PassTime& t : times)
  {
    std::printf("  %-14s %3ld runs %9.3f ms\n", t.pass.c_str(), t.runs, 1e3 * t.seconds);
    reset = t.pass == "reset" ? t.seconds : reset;
    advect = t.pass == "advect" ? t.seconds : advect;
  }
  ASSERT_GE(reset, 0.0);
  ASSERT_GT(advect, 0.0);
  EXPECT_LT(reset, advect) << "the reset pass charged with another pass's time";
}

// Per-pass GPU times (GL_TIME_ELAPSED) name every pass a step runs, once a
// step each, and nothing while timing is off.
TEST(GpuEngine, PassTimesSayWhereTheTimeGoes)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuEngine gpu;
  bp::PassTimer timer;
  timer.enable(true);
  gpu.setPassObserver(&timer); // before configure(): the observer stays across it
  trace(gpu, strips(64), 6);
  const std::vector<bp::PassTime> times = timer.collect();
  ASSERT_FALSE(times.empty());
  long runs = 0;
  for (const bp::PassTime& t : times)
  {
    std::printf("  %-14s %3ld runs %9.3f ms\n", t.pass.c_str(), t.runs, 1e3 * t.seconds);
    EXPECT_GE(t.seconds, 0.0) << t.pass;
    if (t.pass == (gpu.fusedStep() ? "step (fused)" : "finalize"))
      runs = t.runs;
  }
  EXPECT_EQ(runs, gpu.fusedStep() ? 6 : 7) << "a run a step (finalize also at initialisation)";
  timer.enable(false);
  gpu.step(0.1, 0.01);
  EXPECT_TRUE(timer.collect().empty()) << "timed while off";
  gpu.setPassObserver(nullptr);
  gpu.release();
}

namespace
{
/// Counts what the engine tells it, and checks that calls never nest.
struct CountingObserver : bp::PassObserver
{
  std::map<std::string, int> begun;
  int ended = 0;
  bool open = false;
  bool nested = false;
  void begin(const std::string& name) override
  {
    nested = nested || open;
    open = true;
    ++begun[name];
  }
  void end() override
  {
    nested = nested || !open;
    open = false;
    ++ended;
  }
  int total() const
  {
    int n = 0;
    for (const auto& b : begun)
      n += b.second;
    return n;
  }
};
} // namespace

// The engine's hook (PassObserver.h): told of every pass, begin and end in
// pairs, by the names the timer reports, across configure() and release(),
// and of nothing once detached.
TEST(GpuEngine, PassObserverIsToldOfEveryPassUntilDetached)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuEngine gpu;
  CountingObserver seen;
  gpu.setPassObserver(&seen);
  trace(gpu, strips(64), 3);
  EXPECT_FALSE(seen.nested);
  EXPECT_FALSE(seen.open);
  EXPECT_GT(seen.total(), 0);
  EXPECT_EQ(seen.ended, seen.total());
  // a run a step (finalize also at initialisation, as PassTimesSayWhereTheTimeGoes)
  const std::string stepped = gpu.fusedStep() ? "step (fused)" : "finalize";
  const int initial = gpu.fusedStep() ? 0 : 1;
  EXPECT_EQ(seen.begun[stepped], 3 + initial) << stepped;
  EXPECT_EQ(seen.begun.count("pass"), 0u) << "a pass with no name";

  gpu.release();
  const int before = seen.total();
  trace(gpu, strips(64), 2); // a new system keeps the observer
  EXPECT_EQ(seen.begun[stepped], 5 + 2 * initial) << stepped;
  EXPECT_GT(seen.total(), before);

  gpu.setPassObserver(nullptr);
  const int detached = seen.total();
  gpu.step(0.1, 0.01);
  EXPECT_EQ(seen.total(), detached) << "told after it was detached";
  EXPECT_EQ(seen.ended, seen.total());
  gpu.release();
}

namespace
{
/// One step's compulsory traffic (PassTraffic.h) on `path`, fused or not,
/// after five steps; its passes counted apart from the tellings.
struct StepTraffic : bp::PassTraffic
{
  long told = 0;
  void traffic(std::size_t read, std::size_t written) override
  {
    ++told;
    bp::PassTraffic::traffic(read, written);
  }
};

StepTraffic stepTraffic(const char* path, const char* fused, const bp::Parameters& p)
{
  const PathEnvironment environment;
  environment.set(path, fused);
  bp::GpuEngine gpu;
  trace(gpu, p, 5);
  StepTraffic traffic;
  gpu.setPassObserver(&traffic);
  gpu.step(0.05, 0.01);
  gpu.setPassObserver(nullptr);
  gpu.release();
  return traffic;
}
} // namespace

// The bandwidth share the benchmarks give comes from what each path's passes
// move (PassObserver::traffic), not one byte count for every path: every pass
// tells it; the fragment path and a dispatch per kernel run the same passes on
// the same textures, so move the same bytes; the fused step keeps positions in
// shared memory between kernels, so moves fewer; and every path at least reads
// and writes each particle's texel (32 bytes a particle).
TEST(GpuEngine, PassTrafficIsEachPathsOwn)
{
  if (!bp::haveSharedContext())
    return;
  if (epoxy_gl_version() < bp::ComputePathVersion)
    GTEST_SKIP() << "no compute path on this context";
  const bp::Parameters p = strips(256);
  const std::size_t particles = 256 * 16;
  const StepTraffic fragment = stepTraffic("fragment", "off", p);
  const StepTraffic kernels = stepTraffic("compute", "off", p);
  const StepTraffic fused = stepTraffic("compute", "on", p);
  for (const StepTraffic* t : { &fragment, &kernels, &fused })
  {
    EXPECT_EQ(t->told, t->passes()) << "a pass that told no traffic";
    EXPECT_GE(t->bytesRead(), 16 * particles);
    EXPECT_GE(t->bytesWritten(), 16 * particles);
  }
  EXPECT_EQ(fragment.bytes(), kernels.bytes());
  EXPECT_EQ(fragment.passes(), kernels.passes());
  EXPECT_EQ(fused.passes(), 1);
  EXPECT_LT(fused.bytes(), kernels.bytes());
  std::printf("bytes a particle-step: fragment %.1f, compute %.1f, fused %.1f (%ld passes, %ld)\n",
    double(fragment.bytes()) / particles, double(kernels.bytes()) / particles,
    double(fused.bytes()) / particles, kernels.passes(), fused.passes());
}

// A pass sets its uniforms every step; their locations are asked of the
// driver once per program and name, at the first step, never again.
TEST(GpuEngine, UniformLocationsAreAskedOncePerProgram)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuEngine gpu;
  trace(gpu, strips(64), 2);
  const long first = gpu.uniformLookups();
  EXPECT_GT(first, 0);
  for (int s = 2; s < 12; ++s)
    gpu.step(0.01 * s, 0.01);
  EXPECT_EQ(gpu.uniformLookups(), first) << "asked again while stepping";
  gpu.release();
}
