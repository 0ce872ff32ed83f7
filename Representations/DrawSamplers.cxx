// SPDX-License-Identifier: BSD-3-Clause
// The GPU draw's samplers on texture units of their own (DrawSamplers.h).
#include "DrawSamplers.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureUnitManager.h"
// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

namespace bpvtk
{

void DrawSamplers::bindAll(vtkOpenGLRenderWindow* window, const Textures& textures)
{
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  for (int k = 0; k < bp::DrawSamplerCount; ++k)
  {
    this->Units[std::size_t(k)] = units->Allocate();
    this->bind(window, Sampler(k), textures[std::size_t(k)]);
  }
}

void DrawSamplers::bind(vtkOpenGLRenderWindow* window, Sampler sampler, unsigned texture)
{
  window->GetState()->vtkglActiveTexture(GLenum(GL_TEXTURE0 + this->Units[std::size_t(sampler)]));
  glBindTexture(GL_TEXTURE_2D, texture);
}

void DrawSamplers::unbindAll(vtkOpenGLRenderWindow* window)
{
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  for (int k = 0; k < bp::DrawSamplerCount; ++k)
  {
    this->bind(window, Sampler(k), 0);
    units->Free(this->Units[std::size_t(k)]);
    this->Units[std::size_t(k)] = -1;
  }
}

void DrawSamplers::setUniforms(vtkShaderProgram* program) const
{
  for (int k = 0; k < bp::DrawSamplerCount; ++k)
  {
    program->SetUniformi(bp::drawSamplerName(Sampler(k)), this->Units[std::size_t(k)]);
  }
}

} // namespace bpvtk
