// SPDX-License-Identifier: BSD-3-Clause
#include "element_draw.h"

#include "BoundParticlesShaders.h" // generated from Shaders/
#include "GpuDrawSamplers.h"
#include "OutputArrays.h"
#include "ShaderSource.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace bench
{
namespace
{
/// ParaView's default background, the colour every frame is cleared to.
constexpr float Clear[4] = { 0.32f, 0.34f, 0.43f, 1.0f };
/// The colour table's entries (bpColorTableSize).
constexpr int TableSize = 256;
/// The colour table's unit: after the draw samplers' (units 0 to DrawSamplerCount - 1).
constexpr int TableUnit = bp::DrawSamplerCount;

/// The vertex shader: the display's declarations and fetch (bp_draw_vs_*.glsl,
/// with bp_shared.glsl in front) where VTK's polydata shader would have its
/// own, then what VTK's main does with the fetched vertex and normal, then
/// the clipping of hidden elements after the position, as the mapper splices it.
std::string vertexShader(const std::string& definitions)
{
  return "#version 330 core\n" + definitions + bpShaderDrawVSDec +
    "\nuniform mat4 bpViewProjection; // the engine's coordinates to clip coordinates\n"
    "uniform mat3 bpNormalMatrix;     // to view coordinates\n"
    "out vec3 bpNormalVC;\n"
    "void main()\n{\n" +
    bpShaderDrawVSImpl +
    "  gl_Position = bpViewProjection * bpVertexMC;\n"
    "  bpNormalVC = bpNormalMatrix * bpNormalMC;\n"
    "  bpClipHidden();\n}\n";
}

/// The fragment shader: what the display's colour code needs from VTK's
/// (the property's colours, intensities and opacity: a Surface's white,
/// ambient 0.2, diffuse 0.8), the code itself (bp_draw_fs_*.glsl), then a
/// headlight on both faces.
std::string fragmentShader(const std::string& definitions)
{
  return "#version 330 core\n" + definitions + bpShaderDrawFSDec +
    "\nin vec3 bpNormalVC;\n"
    "out vec4 bpFragment;\n"
    "void main()\n{\n"
    "  float ambientIntensity = 0.2;\n"
    "  float diffuseIntensity = 0.8;\n"
    "  vec3 ambientColor = ambientIntensity * vec3(1.0);\n"
    "  vec3 diffuseColor = diffuseIntensity * vec3(1.0);\n"
    "  float opacity = 1.0;\n" +
    bpShaderDrawFSImpl +
    "\n  float lit = length(bpNormalVC) > 0.0 ? abs(normalize(bpNormalVC).z) : 1.0;\n"
    "  bpFragment = vec4(ambientColor + diffuseColor * lit, opacity);\n}\n";
}

GLuint compile(GLenum stage, const std::string& text, std::string& error)
{
  const GLuint shader = glCreateShader(stage);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    char log[8192] = "";
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    error += std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
      " shader: " + bp::describeShaderLog(log);
  }
  return shader;
}

/// Column-major 4x4 product a b.
std::array<float, 16> multiply(const std::array<float, 16>& a, const std::array<float, 16>& b)
{
  std::array<float, 16> m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k)
        m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
}

std::array<float, 3> normalized(std::array<float, 3> v)
{
  const float n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (float& x : v)
    x /= n > 0.0f ? n : 1.0f;
  return v;
}

std::array<float, 3> cross(const std::array<float, 3>& a, const std::array<float, 3>& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

/// A blue to red table through white, as ParaView's Cool to Warm.
std::vector<std::uint8_t> colorTable()
{
  std::vector<std::uint8_t> rgba;
  for (int k = 0; k < TableSize; ++k)
  {
    const float t = float(k) / float(TableSize - 1);
    const float r = t < 0.5f ? 0.23f + 1.5f * t : 0.98f - 0.2f * (t - 0.5f);
    const float g = t < 0.5f ? 0.30f + 1.2f * t : 0.90f - 1.6f * (t - 0.5f);
    const float b = t < 0.5f ? 0.75f + 0.4f * t : 0.95f - 1.6f * (t - 0.5f);
    for (float c : { r, g, b, 1.0f })
      rgba.push_back(std::uint8_t(std::lround(255.0f * std::fmin(std::fmax(c, 0.0f), 1.0f))));
  }
  return rgba;
}
} // namespace

std::string ElementDraw::create(const bp::ElementTemplate& shape, int width, int height)
{
  if (shape.triangles.empty())
    return "the template " + shape.name + " has no triangles to draw";
  const std::string definitions = bp::colorSourceDefinitions() + bp::engineConstantDefinitions();
  std::string error;
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexShader(definitions), error);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentShader(definitions), error);
  this->Program = glCreateProgram();
  glAttachShader(this->Program, vs);
  glAttachShader(this->Program, fs);
  glLinkProgram(this->Program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint linked = 0;
  glGetProgramiv(this->Program, GL_LINK_STATUS, &linked);
  if (error.empty() && !linked)
  {
    char log[8192] = "";
    glGetProgramInfoLog(this->Program, sizeof(log), nullptr, log);
    error = std::string("link: ") + log;
  }
  if (!error.empty())
    return "the draw program: " + error;
  this->setConstantUniforms();

  std::vector<std::uint32_t> indices;
  for (const auto& t : shape.triangles)
    indices.insert(indices.end(), t.begin(), t.end());
  this->IndexCount = int(indices.size());
  glGenVertexArrays(1, &this->VertexArray);
  glBindVertexArray(this->VertexArray);
  glGenBuffers(1, &this->Indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, this->Indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)),
    indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);

  const std::vector<std::uint8_t> table = colorTable();
  glGenTextures(1, &this->ColorTable);
  glBindTexture(GL_TEXTURE_2D, this->ColorTable);
  glTexImage2D(
    GL_TEXTURE_2D, 0, GL_RGBA8, TableSize, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, table.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);

  this->Width = width;
  this->Height = height;
  glGenRenderbuffers(1, &this->Color);
  glBindRenderbuffer(GL_RENDERBUFFER, this->Color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &this->Depth);
  glBindRenderbuffer(GL_RENDERBUFFER, this->Depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &this->Framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, this->Color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, this->Depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    return "the " + std::to_string(width) + "x" + std::to_string(height) +
      " framebuffer is incomplete (status " + std::to_string(status) + ")";
  const GLenum glError = glGetError();
  return glError == GL_NO_ERROR ? ""
                                : "OpenGL error " + std::to_string(glError) + " making the draw";
}

void ElementDraw::setConstantUniforms()
{
  // What no frame changes, set once (as the mapper's element draw sets them,
  // SetMapperShaderParameters); the frame's own uniforms' locations kept.
  const GLuint p = this->Program;
  const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
  glUseProgram(p);
  for (int k = 0; k < bp::DrawSamplerCount; ++k)
    glUniform1i(at(bp::drawSamplerName(bp::DrawSampler(k))), k);
  glUniform1i(at("bpColorTable"), TableUnit);
  glUniform1f(at("bpColorTableSize"), float(TableSize));
  glUniform1i(at("bpLinksPerRow"), 1);
  glUniform1i(at("bpDrawLinks"), 0);
  glUniform1i(at("bpAdjacencyWidth"), 1);
  glUniform1i(at("bpTrail"), 0);
  glUniform1f(at("bpTrailAge"), 0.0f);
  glUniform1f(at("bpFade"), 1.0f);
  glUniform1i(at("bpScalarMode"), int(bp::ColorSource::Force));
  glUniform1i(at("bpComponent"), -1);
  glUniform1i(at("bpColoringAxis"), 0);
  glUniform2f(at("bpRadialCenter"), 0.0f, 0.0f);
  glUniform1f(at("bpVelocitySign"), 1.0f);
  glUseProgram(0);
  this->Locations = { at("bpViewProjection"), at("bpNormalMatrix"), at("bpElementGrid"),
    at("bpBlocksPerRow"), at("bpTrailHalfPeriods"), at("bpScalarRange") };
}

void ElementDraw::setCamera(const std::array<float, 3>& eye, const std::array<float, 3>& center)
{
  const std::array<float, 3> f =
    normalized({ center[0] - eye[0], center[1] - eye[1], center[2] - eye[2] });
  const std::array<float, 3> s = normalized(cross(f, { 0.0f, 1.0f, 0.0f }));
  const std::array<float, 3> u = cross(s, f);
  std::array<float, 16> view{};
  for (int k = 0; k < 3; ++k)
  {
    view[k * 4 + 0] = s[std::size_t(k)];
    view[k * 4 + 1] = u[std::size_t(k)];
    view[k * 4 + 2] = -f[std::size_t(k)];
  }
  for (int r = 0; r < 3; ++r)
  {
    const std::array<float, 3>& axis = r == 0 ? s : r == 1 ? u : f;
    const float d = axis[0] * eye[0] + axis[1] * eye[1] + axis[2] * eye[2];
    view[12 + r] = r == 2 ? d : -d;
  }
  view[15] = 1.0f;
  const float distance = std::sqrt((center[0] - eye[0]) * (center[0] - eye[0]) +
    (center[1] - eye[1]) * (center[1] - eye[1]) + (center[2] - eye[2]) * (center[2] - eye[2]));
  const float nearPlane = 0.05f * distance, farPlane = 4.0f * distance;
  const float focal = 1.0f / std::tan(0.5f * 30.0f * 3.14159265f / 180.0f);
  std::array<float, 16> projection{};
  projection[0] = focal * float(this->Height) / float(this->Width);
  projection[5] = focal;
  projection[10] = (farPlane + nearPlane) / (nearPlane - farPlane);
  projection[11] = -1.0f;
  projection[14] = 2.0f * farPlane * nearPlane / (nearPlane - farPlane);
  this->ViewProjection = multiply(projection, view);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      this->NormalMatrix[std::size_t(c * 3 + r)] = view[std::size_t(c * 4 + r)];
}

void ElementDraw::draw(const bp::GpuEngine::DrawInputs& inputs, float forceMax)
{
  glBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer);
  glViewport(0, 0, this->Width, this->Height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glClearColor(Clear[0], Clear[1], Clear[2], Clear[3]);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(this->Program);
  const auto textures = bp::drawSamplerTextures(inputs, {});
  for (int k = 0; k < bp::DrawSamplerCount; ++k)
  {
    glActiveTexture(GLenum(GL_TEXTURE0 + k));
    glBindTexture(GL_TEXTURE_2D, textures[std::size_t(k)]);
  }
  glActiveTexture(GLenum(GL_TEXTURE0 + TableUnit));
  glBindTexture(GL_TEXTURE_2D, this->ColorTable);
  const FrameLocations& at = this->Locations;
  glUniformMatrix4fv(at.viewProjection, 1, GL_FALSE, this->ViewProjection.data());
  glUniformMatrix3fv(at.normalMatrix, 1, GL_FALSE, this->NormalMatrix.data());
  glUniform2i(at.elementGrid, inputs.elementGrid[0], inputs.elementGrid[1]);
  glUniform1i(at.blocksPerRow, inputs.blocksPerRow);
  glUniform3fv(at.trailHalfPeriods, 1, inputs.trailHalfPeriods);
  glUniform2f(at.scalarRange, 0.0f, forceMax);
  glBindVertexArray(this->VertexArray);
  glDrawElementsInstanced(
    GL_TRIANGLES, this->IndexCount, GL_UNSIGNED_INT, nullptr, GLsizei(inputs.elementCount));
  glBindVertexArray(0);
  glUseProgram(0);
  for (int k = 0; k <= TableUnit; ++k)
  {
    glActiveTexture(GLenum(GL_TEXTURE0 + k));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::size_t ElementDraw::drawnPixels() const
{
  std::vector<std::uint8_t> rgba(std::size_t(this->Width) * std::size_t(this->Height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, this->Framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, this->Width, this->Height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  std::size_t drawn = 0;
  for (std::size_t k = 0; k < rgba.size(); k += 4)
  {
    bool differs = false;
    for (std::size_t c = 0; c < 3; ++c)
      differs = differs || std::abs(int(rgba[k + c]) - int(std::lround(255.0f * Clear[c]))) > 1;
    drawn += differs ? 1 : 0;
  }
  return drawn;
}

void ElementDraw::release()
{
  glDeleteFramebuffers(1, &this->Framebuffer);
  glDeleteRenderbuffers(1, &this->Color);
  glDeleteRenderbuffers(1, &this->Depth);
  glDeleteTextures(1, &this->ColorTable);
  glDeleteBuffers(1, &this->Indices);
  glDeleteVertexArrays(1, &this->VertexArray);
  glDeleteProgram(this->Program);
  *this = ElementDraw();
}

} // namespace bench
