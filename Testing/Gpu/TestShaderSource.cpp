// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's shader assembly (Gpu/ShaderSource.h): compile errors name
// the file and line through the path every pass takes, and the constants the
// shaders get from Core/ (KernelConstants.h) read back as the C++ values.
// That no kernel copies one by hand is TestKernelConstants (Core).
#include "BoundParticlesShaders.h"
#include "KernelConstants.h"
#include "ShaderSource.h"
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

/// Row `name` of KernelConstants.h as written: an Int as its digits, a Uint
/// with its `u` (unsigned in GLSL, as in counterHash), a Float with its point
/// or exponent (GLSL reads "2" as an int) that reads back as the same float;
/// a HostOnly row not at all.
void checkDefinition(const std::map<std::string, std::string>& d, const std::string& name,
  const std::string& type, double value, bp::KernelConstantUse use, std::size_t& written)
{
  const auto found = d.find(name);
  if (use == bp::KernelConstantUse::HostOnly)
  {
    EXPECT_EQ(found, d.end()) << name << " is C++ only";
    return;
  }
  ASSERT_NE(found, d.end()) << name;
  ++written;
  const std::string& text = found->second;
  if (type == "Float")
  {
    EXPECT_EQ(readFloat(text), float(value)) << name << " " << text;
    EXPECT_NE(text.find_first_of(".e"), std::string::npos) << name << " " << text;
  }
  else
  {
    const std::string digits = std::to_string((long long)value);
    EXPECT_EQ(text, type == "Uint" ? digits + "u" : digits) << name;
  }
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
  std::size_t written = 0;
#define BP_CHECK(name, type, value, use)                                                           \
  checkDefinition(d, "BP_" #name, #type, double(value), bp::KernelConstantUse::use, written);
  BP_KERNEL_CONSTANTS(BP_CHECK)
#undef BP_CHECK
  // Nothing else: every #define the kernels get from C++ is a row.
  EXPECT_EQ(d.size(), written);
}
