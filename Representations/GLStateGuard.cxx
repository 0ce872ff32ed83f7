// SPDX-License-Identifier: BSD-3-Clause
// Saves and restores the GL state around the GPU engine's passes (GLStateGuard.h).
#include "GLStateGuard.h"

#include "vtkOpenGLState.h"

// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <algorithm>
#include <type_traits>

namespace bpvtk
{
namespace
{
static_assert(std::is_same<GLint, int>::value && std::is_same<GLboolean, unsigned char>::value,
  "GLStateGuard.h stores GLint as int and GLboolean as unsigned char");

constexpr GLenum CapabilityList[GLStateGuard::Capabilities] = { GL_BLEND, GL_DEPTH_TEST,
  GL_SCISSOR_TEST, GL_CULL_FACE, GL_STENCIL_TEST };
} // namespace

GLStateGuard::GLStateGuard()
{
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &this->DrawFbo);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &this->ReadFbo);
  glGetIntegerv(GL_VIEWPORT, this->Viewport);
  glGetIntegerv(GL_CURRENT_PROGRAM, &this->Program);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &this->ActiveTexture);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &this->Vao);
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &this->UnitCount);
  this->UnitCount = std::min(this->UnitCount, Units);
  for (int u = 0; u < this->UnitCount; ++u)
  {
    glActiveTexture(GLenum(GL_TEXTURE0 + u));
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &this->Texture2D[u]);
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &this->Texture3D[u]);
  }
  glActiveTexture(GLenum(this->ActiveTexture));
  for (int k = 0; k < Capabilities; ++k)
  {
    this->Enabled[k] = glIsEnabled(CapabilityList[k]);
  }
  glGetBooleanv(GL_COLOR_WRITEMASK, this->ColorMask);
}

GLStateGuard::~GLStateGuard()
{
  for (int k = 0; k < Capabilities; ++k)
  {
    if (this->Enabled[k])
      glEnable(CapabilityList[k]);
    else
      glDisable(CapabilityList[k]);
  }
  glColorMask(this->ColorMask[0], this->ColorMask[1], this->ColorMask[2], this->ColorMask[3]);
  for (int u = 0; u < this->UnitCount; ++u)
  {
    glActiveTexture(GLenum(GL_TEXTURE0 + u));
    glBindTexture(GL_TEXTURE_2D, GLuint(this->Texture2D[u]));
    glBindTexture(GL_TEXTURE_3D, GLuint(this->Texture3D[u]));
  }
  glActiveTexture(GLenum(this->ActiveTexture));
  glBindVertexArray(GLuint(this->Vao));
  glUseProgram(GLuint(this->Program));
  glViewport(this->Viewport[0], this->Viewport[1], this->Viewport[2], this->Viewport[3]);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(this->DrawFbo));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(this->ReadFbo));
  if (this->Cache)
  {
    this->Cache->Reset();
  }
}

} // namespace bpvtk
