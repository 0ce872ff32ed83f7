// SPDX-License-Identifier: BSD-3-Clause
// The numbers C++ and the kernels share have one home (Core/Engine/
// KernelConstants.h): every file in Shaders/, comments stripped, names them
// (BP_<NAME>) and never writes one of their values, and every row a kernel
// should name is named. Core only: reads the shaders as text, needs no GL.
#include "KernelConstants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Row
{
  std::string name; ///< BP_<NAME>
  bool isFloat;
  double value;
  bp::KernelConstantUse use;
};

std::vector<Row> rows()
{
  std::vector<Row> out;
#define BP_ROW(name, type, value, use)                                                             \
  out.push_back(                                                                                   \
    { "BP_" #name, std::string(#type) == "Float", double(value), bp::KernelConstantUse::use });
  BP_KERNEL_CONSTANTS(BP_ROW)
#undef BP_ROW
  return out;
}

/// `text` without its // and /* */ comments (newlines kept).
std::string stripComments(const std::string& text)
{
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i)
  {
    if (text.compare(i, 2, "//") == 0)
    {
      i = text.find('\n', i);
      if (i == std::string::npos)
        break;
      out += '\n';
    }
    else if (text.compare(i, 2, "/*") == 0)
    {
      const std::size_t end = text.find("*/", i + 2);
      out += std::string(std::size_t(std::count(text.begin() + long(i),
                           end == std::string::npos ? text.end() : text.begin() + long(end), '\n')),
        '\n');
      if (end == std::string::npos)
        break;
      i = end + 1;
    }
    else
    {
      out += text[i];
    }
  }
  return out;
}

/// Every file in Shaders/, by name, comments stripped.
std::vector<std::pair<std::string, std::string>> shaders()
{
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& entry : std::filesystem::directory_iterator(BP_SHADERS_DIR))
  {
    if (!entry.is_regular_file())
      continue;
    std::ifstream in(entry.path());
    std::ostringstream text;
    text << in.rdbuf();
    out.emplace_back(entry.path().filename().string(), stripComments(text.str()));
  }
  return out;
}

/// The numeric literals of GLSL `code`, with the text each was written as.
std::vector<std::pair<std::string, double>> literals(const std::string& code)
{
  std::vector<std::pair<std::string, double>> out;
  auto word = [](char c) { return std::isalnum((unsigned char)c) || c == '_' || c == '.'; };
  for (std::size_t i = 0; i < code.size(); ++i)
  {
    const bool starts = std::isdigit((unsigned char)code[i]) ||
      (code[i] == '.' && i + 1 < code.size() && std::isdigit((unsigned char)code[i + 1]));
    if (!starts || (i > 0 && word(code[i - 1])))
      continue;
    char* end = nullptr;
    const double value = std::strtod(code.c_str() + i, &end);
    std::size_t next = std::size_t(end - code.c_str());
    while (next < code.size() && std::isalnum((unsigned char)code[next]))
      ++next; // a suffix: u, f, lf
    out.emplace_back(code.substr(i, next - i), value);
    i = next - 1;
  }
  return out;
}

bool near(double a, double b)
{
  return std::abs(a - b) <= 1e-6 * std::abs(b);
}

/// Whether a literal `value` in a kernel is row `r`'s value written out: the
/// value itself, its reciprocal (1.0 / 16777216.0), or for a fraction its
/// double (2 pi). Small whole numbers (below 10: 0, 1, 2, a group of 8, ...)
/// are every kernel's arithmetic and are not taken for a copy; the work-group
/// and enum checks below cover the small ones that are.
bool copies(double value, const Row& r)
{
  const double v = r.value;
  if (v == 0.0 || (std::abs(v) < 10.0 && v == std::floor(v)))
  {
    return false;
  }
  if (near(value, v) || (value != 0.0 && near(1.0 / value, v)))
  {
    return true;
  }
  return v != std::floor(v) && near(value, 2.0 * v);
}
} // namespace

TEST(KernelConstants, TheShadersAreRead)
{
  const auto files = shaders();
  EXPECT_GE(files.size(), 20u);
  bool reset = false;
  for (const auto& f : files)
    reset = reset || f.first == "bp_reset.glsl";
  EXPECT_TRUE(reset) << BP_SHADERS_DIR;
  // The literal reader sees what the kernels write.
  const auto l = literals("x = 1.0e-6 + y2 * 3u - .5 + 0x10 + bpTarget0;");
  ASSERT_EQ(l.size(), 4u);
  EXPECT_EQ(l[0].second, 1.0e-6);
  EXPECT_EQ(l[1].first, "3u");
  EXPECT_EQ(l[2].second, 0.5);
  EXPECT_EQ(l[3].second, 16.0);
  EXPECT_EQ(stripComments("a // 64\nb /* 1e-6\n */ c"), "a \nb \n c");
}

TEST(KernelConstants, NoKernelWritesASharedValue)
{
  for (const auto& file : shaders())
  {
    for (const auto& literal : literals(file.second))
    {
      for (const Row& r : rows())
      {
        EXPECT_FALSE(copies(literal.second, r))
          << file.first << " writes " << literal.first << ", a copy of " << r.name << " ("
          << r.value << "): name it instead (Core/Engine/KernelConstants.h)";
      }
    }
  }
}

TEST(KernelConstants, NoKernelWritesAGroupSizeOrAnEnumValueAsADigit)
{
  static const std::regex groupSize(R"(local_size_[xyz]\s*=\s*[0-9])");
  static const std::regex enumDigit(
    R"(\b(BP_INTEGRATOR|bpOrientation|BP_RESTORATION)\s*[!=<>]=?\s*[0-9]|[0-9]\s*[!=<>]=?\s*(BP_INTEGRATOR|bpOrientation|BP_RESTORATION)\b)");
  for (const auto& file : shaders())
  {
    EXPECT_FALSE(std::regex_search(file.second, groupSize))
      << file.first << ": a work group's size is a named constant (BP_PASS_GROUP_SIZE, ...)";
    EXPECT_FALSE(std::regex_search(file.second, enumDigit))
      << file.first << ": compare an enum with its BP_* value, not a digit";
  }
}

TEST(KernelConstants, EveryRowForTheKernelsIsNamedByOne)
{
  std::string all;
  for (const auto& file : shaders())
    all += file.second + "\n";
  for (const Row& r : rows())
  {
    const bool named = std::regex_search(all, std::regex("\\b" + r.name + "\\b"));
    if (r.use == bp::KernelConstantUse::Kernels)
    {
      EXPECT_TRUE(named) << r.name << " is a kernel constant that no file in Shaders/ names";
    }
    if (r.use == bp::KernelConstantUse::HostOnly)
    {
      // Not written into the kernels: a kernel naming it would not compile.
      EXPECT_FALSE(named) << r.name << " is C++ only (HostOnly), yet a kernel names it";
    }
  }
}

TEST(KernelConstants, RowsAreDistinctAndFloatsAreFinite)
{
  const std::vector<Row> all = rows();
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    EXPECT_TRUE(std::isfinite(all[i].value)) << all[i].name;
    for (std::size_t j = i + 1; j < all.size(); ++j)
      EXPECT_NE(all[i].name, all[j].name);
  }
}
