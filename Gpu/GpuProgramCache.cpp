// SPDX-License-Identifier: BSD-3-Clause
#include "GpuProgramCache.h"

#include <algorithm>
#include <utility>

namespace bp
{
namespace
{
/// Sets `count` uniforms of `type` from `at` on to 0, where `type` is one a
/// fresh program starts at 0 (every default-block type but images, whose
/// layout binds their unit, and any this engine does not declare).
void zeroUniform(GLint at, GLenum type, GLsizei count)
{
  static const GLfloat floats[16 * 64] = {};
  static const GLint ints[4 * 64] = {};
  static const GLuint uints[4 * 64] = {};
  count = std::min<GLsizei>(count, 64);
  switch (type)
  {
    case GL_FLOAT:
      glUniform1fv(at, count, floats);
      break;
    case GL_FLOAT_VEC2:
      glUniform2fv(at, count, floats);
      break;
    case GL_FLOAT_VEC3:
      glUniform3fv(at, count, floats);
      break;
    case GL_FLOAT_VEC4:
      glUniform4fv(at, count, floats);
      break;
    case GL_FLOAT_MAT2:
      glUniformMatrix2fv(at, count, GL_FALSE, floats);
      break;
    case GL_FLOAT_MAT3:
      glUniformMatrix3fv(at, count, GL_FALSE, floats);
      break;
    case GL_FLOAT_MAT4:
      glUniformMatrix4fv(at, count, GL_FALSE, floats);
      break;
    case GL_INT:
    case GL_BOOL:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
      glUniform1iv(at, count, ints);
      break;
    case GL_INT_VEC2:
    case GL_BOOL_VEC2:
      glUniform2iv(at, count, ints);
      break;
    case GL_INT_VEC3:
    case GL_BOOL_VEC3:
      glUniform3iv(at, count, ints);
      break;
    case GL_INT_VEC4:
    case GL_BOOL_VEC4:
      glUniform4iv(at, count, ints);
      break;
    case GL_UNSIGNED_INT:
      glUniform1uiv(at, count, uints);
      break;
    case GL_UNSIGNED_INT_VEC2:
      glUniform2uiv(at, count, uints);
      break;
    case GL_UNSIGNED_INT_VEC3:
      glUniform3uiv(at, count, uints);
      break;
    case GL_UNSIGNED_INT_VEC4:
      glUniform4uiv(at, count, uints);
      break;
    default:
      break; // images keep their layout's units
  }
}

/// Every uniform of `program`'s default block back to 0, as linking left
/// it: a program taken from the cache holds what its last system set, and a
/// sampler left on a unit could meet another type's there (GL then refuses
/// to draw).
void zeroUniforms(GLuint program)
{
  GLint previous = 0, count = 0, longest = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::vector<GLchar> name(std::size_t(std::max(longest, 1)) + 1, 0);
  glUseProgram(program);
  for (GLint k = 0; k < count; ++k)
  {
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(
      program, GLuint(k), GLsizei(name.size()), nullptr, &size, &type, name.data());
    const GLint at = glGetUniformLocation(program, name.data());
    if (at >= 0) // -1: a block's member
    {
      zeroUniform(at, type, size);
    }
  }
  // The program in use before, unless it was deleted while in use (a
  // released engine's last pass), which switching away has freed.
  glUseProgram(glIsProgram(GLuint(previous)) ? GLuint(previous) : 0);
}
} // namespace

std::string GpuProgramCache::build(GpuPath path, const std::string& name,
  const std::string& defines, const std::vector<ShaderPiece>& pieces, GLuint& out, bool images)
{
  // The whole source: what buildProgram() puts together from these, and
  // the refusal it adds for a test (GpuPath.h).
  std::string key = std::string(gpuPathName(path)) + '\n' + name + '\n' +
    (images ? "images\n" : "\n") + (computeCompileFailureForTesting() ? "refused\n" : "\n") +
    defines;
  for (const ShaderPiece& piece : pieces)
  {
    key += '\n' + std::to_string(piece.number) + '\n' + piece.text;
  }
  const auto known = this->Programs.find(key);
  if (known != this->Programs.end())
  {
    known->second.lastUse = ++this->Clock;
    out = known->second.program.get();
    zeroUniforms(out);
    return std::string();
  }
  GlProgram program;
  const std::string error = buildProgram(path, name, defines, pieces, program, images);
  ++this->Compiles;
  if (!error.empty())
  {
    program.reset();
    out = 0;
    return error;
  }
  out = program.get();
  Entry& entry = this->Programs[std::move(key)];
  entry.program = std::move(program);
  entry.lastUse = ++this->Clock;
  return std::string();
}

void GpuProgramCache::beginUse()
{
  while (this->Programs.size() > MostKept)
  {
    const auto oldest = std::min_element(this->Programs.begin(), this->Programs.end(),
      [](const auto& a, const auto& b) { return a.second.lastUse < b.second.lastUse; });
    oldest->second.program.reset();
    this->Programs.erase(oldest);
  }
}

void GpuProgramCache::clear()
{
  for (auto& entry : this->Programs)
  {
    entry.second.program.reset();
  }
  this->Programs.clear();
  this->Compiles = 0;
}

} // namespace bp
