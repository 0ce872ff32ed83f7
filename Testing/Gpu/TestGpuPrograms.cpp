// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's programs compiled for a trace's integrator, poses and
// inertia (Gpu/GpuPasses.h: KernelSpecialisation, #defines rather than
// uniform branches) and kept in the engine's cache (Gpu/GpuProgramCache.h):
// a setting changed mid-session switches program and goes on as a trace
// begun with it, bit for bit; each source is compiled once, and only the
// programs that depend on a setting are compiled again for it; what the
// driver compiles for Euler holds none of RK4's samples. Run on every path
// (CMakeLists.txt), as the parity suites are.
#include "AnalyticFlows.h"
#include "BoundParticlesShaders.h"
#include "EngineState.h"
#include "GpuEngine.h"
#include "GpuPasses.h"
#include "GpuProgramCache.h"
#include "SharedContext.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace
{
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

bp::Parameters strips()
{
  bp::Parameters p;
  p.numberOfElements = 40;
  p.elementSize = 0.1f;
  p.emitterMin = { -0.6f, -0.6f, -0.6f };
  p.emitterMax = { 0.6f, 0.6f, 0.6f };
  p.lifetimeMin = 0.1f;
  p.lifetimeMax = 0.3f; // resets within the run
  p.iterations = 3;
  p.seed = 5;
  return p;
}

/// `p` with heavy particles (bp::carriesInertia) or massless ones.
bp::Parameters withInertia(bp::Parameters p, bool heavy)
{
  p.inertia = heavy ? bp::Inertia::MaxeyRiley : bp::Inertia::None;
  p.responseTime = heavy ? 0.05f : 0.0f;
  p.densityRatio = 4.0f;
  return p;
}

/// Configures `gpu` for `p`, starts from `from` (initialised where null) at
/// `t`, and steps `steps` times: the positions, poses, spins and slips after.
std::vector<float> trace(
  bp::GpuEngine& gpu, const bp::Parameters& p, const bp::EngineState* from, double t, int steps)
{
  const bp::VectorField field = rotation();
  EXPECT_EQ(gpu.configure(bp::builtinTemplate(bp::BuiltinShape::Strip16), p), "");
  EXPECT_EQ(gpu.setField(field), "");
  if (from)
    EXPECT_EQ(gpu.loadState(*from), "");
  else
    gpu.initialize(t);
  for (int s = 0; s < steps; ++s)
    gpu.step(t + 0.01 * s, 0.01);
  std::vector<float> all, poses, spins, slips;
  gpu.read(&all, nullptr, nullptr);
  gpu.readPoses(&poses, &spins);
  gpu.readSlips(slips);
  for (const std::vector<float>* part : { &poses, &spins, &slips })
    all.insert(all.end(), part->begin(), part->end());
  return all;
}

/// The same trace on a fresh engine, which compiles every program anew.
std::vector<float> freshTrace(const bp::Parameters& p, const bp::EngineState* from, double t)
{
  bp::GpuEngine fresh;
  std::vector<float> values = trace(fresh, p, from, t, 6);
  fresh.release();
  return values;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

const char* integratorName(bp::Integrator integrator)
{
  return integrator == bp::Integrator::Euler ? "Euler"
    : integrator == bp::Integrator::RK2      ? "RK2"
                                             : "RK4";
}
} // namespace

// The filter changes the Integrator mid-trace: the engine is configured
// again and goes on from the state it had. It must run the new integrator's
// programs (a cached program of the old one would give the old one's bits),
// as an engine that never ran the old one does.
TEST(GpuPrograms, AnIntegratorChangedMidTraceGoesOnAsATraceBegunWithIt)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuEngine gpu;
  bp::Parameters p = strips();
  p.trackPoses = true;
  trace(gpu, p, nullptr, 0.0, 4);
  bp::EngineState state;
  ASSERT_EQ(gpu.readState(state), "");
  std::vector<std::vector<float>> results;
  for (bp::Integrator integrator :
    { bp::Integrator::RK4, bp::Integrator::RK2, bp::Integrator::Euler, bp::Integrator::RK4 })
  {
    p.integrator = integrator;
    const std::vector<float> got = trace(gpu, p, &state, 0.04, 6);
    EXPECT_TRUE(sameBits(got, freshTrace(p, &state, 0.04)))
      << "changed to " << integratorName(integrator) << ": not the bits of a trace begun with it";
    results.push_back(got);
  }
  // The integrators move the particles differently: the bits above tell them apart.
  EXPECT_FALSE(sameBits(results[0], results[1])) << "RK4 and RK2 gave the same bits";
  EXPECT_FALSE(sameBits(results[0], results[2])) << "RK4 and Euler gave the same bits";
  EXPECT_FALSE(sameBits(results[1], results[2])) << "RK2 and Euler gave the same bits";
  EXPECT_TRUE(sameBits(results[0], results[3])) << "RK4 again, after Euler";
  gpu.release();
}

// Inertia and the poses (Trails, Output Arrays) switched on and off between
// traces: each trace is the one a fresh engine gives, and each setting
// changes the bits it is meant to change.
TEST(GpuPrograms, InertiaAndPosesChangedBetweenTracesGiveAFreshEnginesBits)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuEngine gpu;
  std::vector<std::vector<float>> results;
  for (int k = 0; k < 5; ++k)
  {
    const bool heavy = k == 1 || k == 3, poses = k == 2 || k == 3;
    bp::Parameters p = withInertia(strips(), heavy);
    p.integrator = bp::Integrator::RK2;
    p.trackPoses = poses;
    const std::vector<float> got = trace(gpu, p, nullptr, 0.0, 6);
    EXPECT_TRUE(sameBits(got, freshTrace(p, nullptr, 0.0)))
      << (heavy ? "heavy" : "massless") << (poses ? " with poses" : " without poses");
    results.push_back(got);
  }
  EXPECT_FALSE(sameBits(results[0], results[1])) << "inertia changed nothing";
  EXPECT_FALSE(sameBits(results[0], results[2])) << "poses changed nothing";
  EXPECT_TRUE(sameBits(results[0], results[4])) << "massless without poses again";
  gpu.release();
}

// A configure compiles only what its cache does not hold: the same settings
// nothing, another integrator the advect kernel and the two slip kernels
// that include it (and the fused step), poses the fused step only, inertia
// the advect kernel (and the fused step). release() deletes them all.
TEST(GpuPrograms, EachSourceIsCompiledOnceAndOnlyWhatASettingChanges)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuEngine gpu;
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Strip16);
  bp::Parameters p = strips();
  ASSERT_EQ(gpu.configure(shape, p), "");
  const long fused = gpu.fusedStep() ? 1 : 0;
  const long all = gpu.programsCompiled();
  EXPECT_EQ(all, 15 + fused) << "every kernel's pass, and the fused step";
  EXPECT_EQ(gpu.programsKept(), std::size_t(all));
  struct Change
  {
    const char* what;
    bp::Parameters p;
    long compiled;
  };
  bp::Parameters rk4 = p, poses = p, heavy = withInertia(p, true), rk4Heavy = withInertia(p, true);
  rk4.integrator = rk4Heavy.integrator = bp::Integrator::RK4;
  poses.trackPoses = true;
  const Change changes[] = { { "the same settings", p, 0 }, { "RK4", rk4, 3 + fused },
    { "Euler again", p, 0 }, { "poses", poses, fused }, { "RK4 again", rk4, 0 },
    { "heavy particles", heavy, 1 + fused }, { "heavy particles, RK4", rk4Heavy, 1 + fused },
    { "massless, poses again", poses, 0 } };
  long compiled = all;
  for (const Change& c : changes)
  {
    ASSERT_EQ(gpu.configure(shape, c.p), "") << c.what;
    EXPECT_EQ(gpu.programsCompiled() - compiled, c.compiled) << c.what;
    compiled = gpu.programsCompiled();
  }
  EXPECT_EQ(gpu.programsKept(), std::size_t(compiled)) << "each source kept once";
  gpu.release();
  EXPECT_EQ(gpu.programsCompiled(), 0);
  EXPECT_EQ(gpu.programsKept(), 0u);
  // A configure the engine's checks refuse keeps nothing either: a display
  // releases only an engine it configured, in the context it configured it in.
  ASSERT_EQ(gpu.configure(shape, p), "");
  EXPECT_GT(gpu.programsKept(), 0u);
  bp::Parameters refused = p;
  refused.restitution = 2.0f;
  EXPECT_NE(gpu.configure(shape, refused), "");
  EXPECT_EQ(gpu.programsKept(), 0u) << "a refused configure keeps no program";
}

// The specialisation is in the code the driver compiles: the advect
// kernel's program for Euler samples the field once, RK2's twice, RK4's four
// times, so their binaries grow in that order (a branch on a uniform would
// compile all three into each, the same size); and a program of the kernel
// built without an integrator does not compile at all.
TEST(GpuPrograms, TheAdvectProgramOfEachIntegratorHoldsItsOwnCodeOnly)
{
  if (!bp::haveSharedContext())
    return;
  const bp::GpuPath path =
    epoxy_gl_version() >= bp::ComputePathVersion ? bp::GpuPath::Compute : bp::GpuPath::Fragment;
  const std::vector<bp::ShaderPiece> pieces = { { bpShaderAdvectNumber, bpShaderAdvect },
    { bpShaderPassNumber, bpShaderPass },
    path == bp::GpuPath::Compute ? bp::ShaderPiece{ bpShaderPassCompNumber, bpShaderPassComp }
                                 : bp::ShaderPiece{ bpShaderPassFragNumber, bpShaderPassFrag } };
  const std::string pass = "#define BP_PASS bpAdvectPass\n#define BP_TARGETS 2\n";
  bp::GpuProgramCache cache;
  GLuint none = 0;
  const std::string error = cache.build(path, "advect", pass, pieces, none);
  EXPECT_NE(error.find("BP_INTEGRATOR is not defined"), std::string::npos) << error;
  EXPECT_EQ(none, 0u);
  GLint formats = 0;
  glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
  std::vector<GLint> sizes;
  for (bp::Integrator integrator :
    { bp::Integrator::Euler, bp::Integrator::RK2, bp::Integrator::RK4 })
  {
    bp::KernelSpecialisation s;
    s.integrator = integrator;
    GLuint program = 0;
    ASSERT_EQ(cache.build(path, "advect", pass + s.defines(true, true), pieces, program), "");
    GLint bytes = 0;
    glGetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &bytes);
    std::printf("advect program for %s: %d bytes of binary\n", integratorName(integrator), bytes);
    sizes.push_back(bytes);
  }
  EXPECT_EQ(cache.compiles(), 4) << "the refused one and one per integrator";
  cache.clear();
  if (formats == 0 || sizes[0] == 0)
    GTEST_SKIP() << "the driver gives no program binaries to compare";
  EXPECT_LT(sizes[0], sizes[1]) << "Euler's program is not smaller than RK2's";
  EXPECT_LT(sizes[1], sizes[2]) << "RK2's program is not smaller than RK4's";
}

// The cache keeps at most GpuProgramCache::MostKept programs: a beginUse()
// deletes the ones handed out the longest ago, never those of the last
// configure; a program deleted is compiled again when asked for.
TEST(GpuPrograms, TheCacheKeepsItsBoundAndWhatIsInUse)
{
  if (!bp::haveSharedContext())
    return;
  bp::GpuProgramCache cache;
  const std::vector<bp::ShaderPiece> pieces = { { bpShaderPassFragNumber,
    "vec3 bpPositionOf(int e, int i)\n{\n  return vec3(0.0);\n}\n"
    "layout(location = 0) out vec4 bpTarget0;\nvoid main()\n{\n  bpTarget0 = "
    "vec4(BP_VALUE);\n}\n" } };
  const auto build = [&](int k)
  {
    GLuint program = 0;
    EXPECT_EQ(cache.build(bp::GpuPath::Fragment, "value",
                "#define BP_VALUE " + std::to_string(k) + ".0\n", pieces, program),
      "");
    return program;
  };
  const int half = int(bp::GpuProgramCache::MostKept) / 2 + 8;
  cache.beginUse();
  for (int k = 0; k < half; ++k)
    build(k);
  cache.beginUse();
  std::vector<GLuint> inUse;
  for (int k = half; k < 2 * half; ++k)
    inUse.push_back(build(k));
  EXPECT_EQ(cache.size(), std::size_t(2 * half)) << "nothing deleted while in use";
  EXPECT_EQ(cache.compiles(), 2 * half);
  cache.beginUse();
  EXPECT_EQ(cache.size(), bp::GpuProgramCache::MostKept);
  for (GLuint program : inUse)
    EXPECT_TRUE(glIsProgram(program)) << "a program of the last use deleted";
  EXPECT_EQ(build(2 * half - 1), inUse.back()) << "kept: not compiled again";
  EXPECT_EQ(cache.compiles(), 2 * half);
  build(0);
  EXPECT_EQ(cache.compiles(), 2 * half + 1) << "the oldest was deleted, so compiled again";
  cache.clear();
  EXPECT_EQ(cache.size(), 0u);
  for (GLuint program : inUse)
    EXPECT_FALSE(glIsProgram(program)) << "clear() deletes every program";
}
