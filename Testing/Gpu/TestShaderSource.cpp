// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's shader assembly (Gpu/ShaderSource.h): compile errors name
// the file and line through the path every pass takes, and the constants the
// shaders get from Core/ read back as the C++ values.
#include "BoundParticlesShaders.h"
#include "CounterHash.h"
#include "Engine.h"
#include "GpuState.h"
#include "Pose.h"
#include "ReleaseWeights.h"
#include "ShaderSource.h"
#include "ShapeMatching.h"
#include "SharedContext.h"

#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

namespace
{
/// Whether `log` names `file` at `line`, as Mesa ("file:3(") or NVIDIA ("file(3)") writes it.
bool names(const std::string& log, const std::string& file, int line)
{
  const std::string n = std::to_string(line);
  return log.find(file + ":" + n + "(") != std::string::npos ||
    log.find(file + "(" + n + ")") != std::string::npos ||
    log.find(file + ":" + n + ":") != std::string::npos;
}

/// The #define values of engineConstantDefinitions(), by name.
std::map<std::string, std::string> definitions()
{
  std::map<std::string, std::string> out;
  std::istringstream lines(bp::engineConstantDefinitions());
  std::string hash, name, value;
  while (lines >> hash >> name >> value)
  {
    EXPECT_EQ(hash, "#define");
    out[name] = value;
  }
  return out;
}

float readFloat(const std::string& text)
{
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  float value = 0.0f;
  in >> value;
  return value;
}
} // namespace

TEST(ShaderSource, ACompileErrorNamesThePassFileAndLine)
{
  if (!bp::haveSharedContext())
    return;
  // Line 3 of the kernel, after bp_shared.glsl, bp_inputs.glsl and bp_common.glsl,
  // on either path (the compute path on a context that has it).
  for (bp::GpuPath path : { bp::GpuPath::Fragment, bp::GpuPath::Compute })
  {
    if (path == bp::GpuPath::Compute && epoxy_gl_version() < bp::ComputePathVersion)
      continue;
    bp::GlProgram program;
    const std::string error = bp::buildProgram(path, "bp_test.glsl", "",
      { { bpShaderTestNumber, "void main()\n{\n  float x = bpNoSuchName;\n}\n" } }, program);
    EXPECT_TRUE(names(error, "bp_test.glsl", 3)) << error;
    std::printf("%s", error.c_str());
    EXPECT_NE(error.find("(bp_test.glsl) does not compile"), std::string::npos) << error;
  }
}

TEST(ShaderSource, ErrorsInAndAfterGeneratedSpringsNameTheirSource)
{
  if (!bp::haveSharedContext())
    return;
  const std::string pass = "void main()\n{\n//TAG\n  float y = BROKEN_AFTER;\n}\n";
  const std::string code = "  float a = 1.0;\n  float b = BROKEN_IN;";
  const int restore = bpShaderRestoreNumber;
  const bp::ShaderPiece spliced = { restore,
    bp::spliceCode(pass, restore, "//TAG", code, bp::GeneratedSpringsSource) };
  bp::GlProgram program;
  std::string error = bp::buildProgram(
    bp::GpuPath::Fragment, "restore", "#define BROKEN_AFTER 0.0\n", { spliced }, program);
  EXPECT_TRUE(names(error, bp::shaderFileName(bp::GeneratedSpringsSource), 2)) << error;
  error = bp::buildProgram(
    bp::GpuPath::Fragment, "restore", "#define BROKEN_IN 0.0\n", { spliced }, program);
  EXPECT_TRUE(names(error, "bp_restore.glsl", 4)) << error;
}

TEST(ShaderSource, LogsOfOtherDriversNameTheFile)
{
  const std::string common = bp::shaderFileName(bpShaderCommonNumber);
  EXPECT_EQ(common, "bp_common.glsl");
  const std::string n = std::to_string(bpShaderCommonNumber);
  EXPECT_EQ(bp::describeShaderLog(n + "(17) : error C1008: undefined variable \"x\"\n"),
    common + "(17) : error C1008: undefined variable \"x\"\n");
  EXPECT_EQ(bp::describeShaderLog("ERROR: " + n + ":17: 'x' : undeclared identifier\n"),
    "ERROR: " + common + ":17: 'x' : undeclared identifier\n");
  EXPECT_EQ(bp::describeShaderLog(n + ":17(3): error: `x' undeclared\n"),
    common + ":17(3): error: `x' undeclared\n");
  // Mesa keeps the line of a #line directive but not its source-string number.
  EXPECT_EQ(bp::describeShaderLog("0:" + n + "00017(3): error: `x' undeclared\n"),
    common + ":17(3): error: `x' undeclared\n");
}

TEST(ShaderSource, ConstantsReadBackAsTheCoreValues)
{
  std::map<std::string, std::string> d = definitions();
  EXPECT_EQ(d["BP_RELEASE_TRIES"], std::to_string(bp::ReleaseTries));
  EXPECT_EQ(d["BP_MATCH_ITERATIONS"], std::to_string(bp::MatchIterations));
  EXPECT_EQ(d["BP_POSE_ITERATIONS"], std::to_string(bp::PoseIterations));
  EXPECT_EQ(readFloat(d["BP_ROTATION_DAMPING"]), bp::RotationDamping);
  EXPECT_EQ(readFloat(d["BP_MAX_NEWTON_STEP"]), bp::MaxNewtonStep);
  EXPECT_EQ(readFloat(d["BP_MIN_VORTICITY_STEP"]), bp::MinVorticityStep);
  EXPECT_EQ(readFloat(d["BP_MAX_SPIN_VORTICITY_RATIO"]), bp::MaxSpinVorticityRatio);
  for (const char* name : { "BP_ROTATION_DAMPING", "BP_MAX_NEWTON_STEP", "BP_MIN_VORTICITY_STEP",
         "BP_MAX_SPIN_VORTICITY_RATIO" })
  {
    // GLSL reads "2" as an int: a float constant needs its point.
    EXPECT_NE(d[name].find_first_of(".e"), std::string::npos) << name;
  }
  // The hash and the draws are unsigned in GLSL, as in counterHash.
  EXPECT_EQ(d["BP_HASH_MULTIPLIER"], std::to_string(bp::HashMultiplier) + "u");
  EXPECT_EQ(d["BP_HASH_INCREMENT"], std::to_string(bp::HashIncrement) + "u");
  EXPECT_EQ(d["BP_ORIENTATION_DRAW"], std::to_string(bp::OrientationDraw) + "u");
  EXPECT_EQ(d["BP_LIFETIME_DRAW"], std::to_string(bp::LifetimeDraw) + "u");
  EXPECT_EQ(d["BP_FURTHER_CANDIDATE_DRAW"], std::to_string(bp::FurtherCandidateDraw) + "u");
  EXPECT_EQ(d["BP_FIRST_WEIGHT_DRAW"], std::to_string(bp::FirstWeightDraw) + "u");
  EXPECT_EQ(d["BP_SEED_ROW"], std::to_string(bp::SeedPointsPerRow) + "u");
  EXPECT_EQ(d["BP_INTEGRATOR_RK4"], std::to_string(int(bp::Integrator::RK4)));
  EXPECT_EQ(d["BP_ORIENTATION_ALONG_FLOW"], std::to_string(int(bp::Orientation::AlongFlow)));
}

TEST(ShaderSource, KernelsNameTheSharedConstantsNotTheirValues)
{
  // A number the shaders share with C++ reaches them as a #define; a literal
  // copy in a kernel would drift from Core's unseen.
  for (const char* text : { bpShaderShared, bpShaderCommon, bpShaderReset, bpShaderAdvect })
  {
    const std::string source = text;
    EXPECT_EQ(source.find("1664525"), std::string::npos);
    EXPECT_EQ(source.find("bpIntegrator == 0"), std::string::npos);
    EXPECT_EQ(source.find("bpOrientation == 1"), std::string::npos);
    EXPECT_EQ(source.find("% 256u"), std::string::npos);
  }
}
