// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's shaders put together, compiled and linked, with errors
// that name the file (ShaderSource.h).
#include "ShaderSource.h"

#include "BoundParticlesShaders.h" // generated from Shaders/
#include "GpuStateLayout.h"
#include "KernelConstants.h"

#include <algorithm>
#include <initializer_list>
#include <locale>
#include <regex>
#include <sstream>

namespace bp
{
namespace
{
/// `value` as a GLSL float literal that reads back as the same float: the
/// fewest significant digits that do (9 always do).
std::string floatLiteral(float value)
{
  std::string text;
  for (int digits = 1; digits <= 9; ++digits)
  {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(digits);
    out << value;
    text = out.str();
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    float back = 0.0f;
    in >> back;
    if (back == value)
    {
      break;
    }
  }
  if (text.find_first_of(".e") == std::string::npos)
  {
    text += ".0"; // "2" would be an int
  }
  return text;
}

std::string define(const char* name, const std::string& value)
{
  return std::string("#define ") + name + " " + value + "\n";
}

/// Lines of source-string N are numbered from N * LineStride + 1: Mesa
/// (22.3) drops the source-string number from its log but keeps the line,
/// so the line alone must say which file it is in.
constexpr long LineStride = 100000;

/// The directive that numbers the next line as line `line` of source-string `number`.
std::string lineDirective(int number, long line)
{
  return "#line " + std::to_string(number * LineStride + line) + " " + std::to_string(number);
}

/// Labels a GL object for debuggers where the GL can (KHR_debug, core in 4.3).
void label(GLenum kind, GLuint object, const std::string& name)
{
  if (epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug"))
  {
    glObjectLabel(kind, object, GLsizei(name.size()), name.c_str());
  }
}

/// Compiles `source`; empty on success, otherwise the log with file names.
std::string compileShader(
  GLenum type, const std::string& source, const std::string& name, GLuint& shader)
{
  shader = glCreateShader(type);
  label(GL_SHADER, shader, name);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok)
  {
    return std::string();
  }
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, &log[0]);
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return describeShaderLog(log);
}

/// A row's value as a GLSL literal of its type (KernelConstants.h).
std::string glslInt(long long value)
{
  return std::to_string(value);
}

std::string glslUint(unsigned long long value)
{
  return std::to_string(value) + "u";
}

std::string glslFloat(double value)
{
  return floatLiteral(float(value));
}

} // namespace

std::string engineConstantDefinitions()
{
  std::string out;
#define BP_DEFINE(name, type, value, use)                                                          \
  if (KernelConstantUse::use != KernelConstantUse::HostOnly)                                       \
  {                                                                                                \
    out += define("BP_" #name, glsl##type(value));                                                 \
  }
  BP_KERNEL_CONSTANTS(BP_DEFINE)
#undef BP_DEFINE
  return out;
}

std::string shaderFileName(int number)
{
  const int files = int(sizeof(bpShaderFileNames) / sizeof(bpShaderFileNames[0]));
  if (number == GeneratedSpringsSource)
  {
    return "(springs as code, GpuTemplate)";
  }
  return number >= 0 && number < files ? bpShaderFileNames[number]
                                       : "(source " + std::to_string(number) + ")";
}

std::string assembleShader(
  GpuPath path, const std::string& preamble, const std::vector<ShaderPiece>& pieces)
{
  std::string source =
    std::string(path == GpuPath::Compute ? "#version 430 core\n" : "#version 330 core\n") +
    preamble;
  for (const ShaderPiece& piece : pieces)
  {
    // The newline ends a last line without one; #line numbers the next line.
    source += "\n" + lineDirective(piece.number, 1) + "\n" + piece.text;
  }
  return source;
}

std::string spliceCode(const std::string& text, int number, const std::string& tag,
  const std::string& code, int codeNumber)
{
  const std::size_t at = text.find(tag);
  if (at == std::string::npos)
  {
    return text;
  }
  const long tagLine = 1 + long(std::count(text.begin(), text.begin() + long(at), '\n'));
  std::string out = text;
  out.replace(at, tag.size(),
    lineDirective(codeNumber, 1) + "\n" + code + "\n" + lineDirective(number, tagLine + 1));
  return out;
}

std::string describeShaderLog(const std::string& log)
{
  static const std::regex message("^((?:ERROR|WARNING): )?([0-9]+)([:(])([0-9]+)(.*)$");
  std::istringstream lines(log);
  std::string line, out;
  while (std::getline(lines, line))
  {
    std::smatch m;
    if (std::regex_match(line, m, message))
    {
      const long number = std::stol(m[2].str()), at = std::stol(m[4].str());
      const long file = at > LineStride ? at / LineStride : number;
      line = m[1].str() + shaderFileName(int(file)) + m[3].str() +
        std::to_string(at > LineStride ? at % LineStride : at) + m[5].str();
    }
    out += line + "\n";
  }
  return out;
}

namespace
{
/// Links `shaders` (deleted after) into `out`; empty on success, otherwise the log.
std::string linkProgram(
  const std::string& name, std::initializer_list<GLuint> shaders, GlProgram& out)
{
  // Owned before linking, so a program that fails to link is deleted with the rest.
  out = GlProgram(glCreateProgram());
  label(GL_PROGRAM, out.get(), name);
  for (GLuint shader : shaders)
  {
    glAttachShader(out.get(), shader);
  }
  glLinkProgram(out.get());
  for (GLuint shader : shaders)
  {
    glDeleteShader(shader);
  }
  GLint ok = 0;
  glGetProgramiv(out.get(), GL_LINK_STATUS, &ok);
  if (!ok)
  {
    char log[2048] = { 0 };
    glGetProgramInfoLog(out.get(), sizeof(log) - 1, nullptr, log);
    return "a GPU engine program (" + name + ") does not link:\n" + describeShaderLog(log);
  }
  return std::string();
}
} // namespace

std::string buildProgram(GpuPath path, const std::string& name, const std::string& defines,
  const std::vector<ShaderPiece>& pieces, GlProgram& out, bool images)
{
  std::vector<ShaderPiece> all = { { bpShaderSharedNumber, bpShaderShared },
    { 0, elementStateDeclarations(images) }, { bpShaderInputsNumber, bpShaderInputs },
    { bpShaderCommonNumber, bpShaderCommon } };
  all.insert(all.end(), pieces.begin(), pieces.end());
  const std::string refused = path == GpuPath::Compute && computeCompileFailureForTesting()
    ? "#error compute programs refused (setComputeCompileFailureForTesting)\n"
    : "";
  const std::string source =
    assembleShader(path, engineConstantDefinitions() + defines + refused, all);
  GLuint vs = 0, main = 0;
  std::string error;
  if (path == GpuPath::Fragment)
  {
    error = compileShader(GL_VERTEX_SHADER,
      assembleShader(
        path, std::string(), { { bpShaderFullscreenVertNumber, bpShaderFullscreenVert } }),
      "bp_fullscreen.vert", vs);
  }
  if (error.empty())
  {
    error = compileShader(
      path == GpuPath::Compute ? GL_COMPUTE_SHADER : GL_FRAGMENT_SHADER, source, name, main);
  }
  if (!error.empty())
  {
    glDeleteShader(vs);
    glDeleteShader(main);
    return "a GPU engine shader (" + name + ") does not compile:\n" + error;
  }
  return path == GpuPath::Compute ? linkProgram(name, { main }, out)
                                  : linkProgram(name, { vs, main }, out);
}

} // namespace bp
