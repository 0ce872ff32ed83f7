// SPDX-License-Identifier: BSD-3-Clause
// The stretch fit's template side and the lifetime draw's settings for the
// draw shader (DrawDeformation.h).
#include "DrawDeformation.h"

#include "ElementStretch.h"
#include "ElementTemplate.h"
#include "Engine.h"
#include "SuperSet.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <algorithm>

namespace bpvtk
{

DeformationTable::DeformationTable() = default;
DeformationTable::~DeformationTable() = default;

void DeformationTable::set(const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  // The CPU output's fit (Filters/TracerOutputArrays.cxx): the same template
  // moments, so the two engines' colours differ only by the float arithmetic.
  const bp::StretchFit fit(shape.rest, p.elementSize);
  this->Rest.assign(4 * fit.centred().size(), 0.0f);
  for (std::size_t i = 0; i < fit.centred().size(); ++i)
  {
    std::copy_n(fit.centred()[i].begin(), 3, this->Rest.begin() + std::ptrdiff_t(4 * i));
  }
  std::copy_n(fit.restMomentPseudoInverse(), 9, this->Inverse);
  this->Span = fit.span();
  // The lifetime draw's settings (Gpu/GpuPasses.cpp sets the same for the engine).
  this->Seed = p.seed;
  this->LifetimeMin = p.lifetimeMin;
  this->LifetimeMax = p.lifetimeMax;
  this->FtleMinimumAge = float(p.ftleMinimumAge);
  this->Linked =
    !bp::makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax)
       .empty();
  this->Lattice = p.releasePattern == bp::ReleasePattern::Lattice;
  this->Uploaded = false;
  this->Width = 0;
}

void DeformationTable::upload(vtkOpenGLRenderWindow* window, int maxSize)
{
  // Tried once per configuration (and again after the context lost it).
  if (this->Rest.empty() || (this->Uploaded && (this->Width == 0 || this->Texture->GetHandle())))
  {
    return;
  }
  this->Uploaded = true;
  const std::size_t texels = this->Rest.size() / 4;
  const int width = int(std::min(texels, std::size_t(std::max(maxSize, 1))));
  const std::size_t rows = (texels + std::size_t(width) - 1) / std::size_t(width);
  if (rows > std::size_t(maxSize))
  {
    this->Width = 0; // more particles than a texture holds: the colouring reads (1, 1)
    return;
  }
  std::vector<float> padded(4 * std::size_t(width) * rows, 0.0f);
  std::copy(this->Rest.begin(), this->Rest.end(), padded.begin());
  this->Texture->SetContext(window);
  this->Texture->SetInternalFormat(GL_RGBA32F);
  this->Texture->SetFormat(GL_RGBA);
  this->Texture->Create2DFromRaw(unsigned(width), unsigned(rows), 4, VTK_FLOAT, padded.data());
  this->Width = width;
}

unsigned DeformationTable::handle() const
{
  return this->Width > 0 ? this->Texture->GetHandle() : 0u;
}

void DeformationTable::setUniforms(vtkShaderProgram* program) const
{
  // Without the texture (too many particles) the colouring reads (1, 1).
  const bool fits = this->Width > 0;
  program->SetUniformi("bpStretchRestWidth", std::max(this->Width, 1));
  program->SetUniformi("bpStretchSpan", fits ? this->Span : 0);
  program->SetUniformi("bpStretchParticles", int(this->Rest.size() / 4));
  float m[9];
  std::copy_n(this->Inverse, 9, m); // symmetric: row- or column-major alike
  program->SetUniformMatrix3x3("bpStretchInverse", m);
  program->SetUniformf("bpLifetimeMin", this->LifetimeMin);
  program->SetUniformf("bpLifetimeMax", this->LifetimeMax);
  program->SetUniformf("bpFtleMinimumAge", this->FtleMinimumAge);
  program->SetUniformi("bpLinked", this->Linked ? 1 : 0);
  program->SetUniformi("bpLattice", this->Lattice ? 1 : 0);
  // VTK sets no unsigned uniforms; the program is bound.
  const GLint seed = glGetUniformLocation(GLuint(program->GetHandle()), "bpSeed");
  if (seed >= 0)
  {
    glUniform1ui(seed, GLuint(this->Seed));
  }
}

void DeformationTable::release(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Uploaded = false;
  this->Width = 0;
}

} // namespace bpvtk
