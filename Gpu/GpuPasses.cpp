// SPDX-License-Identifier: BSD-3-Clause
#include "GpuPasses.h"

#include "BoundParticlesShaders.h" // generated from Shaders/
#include "GpuFieldCache.h"
#include "ShaderSource.h"

#include <algorithm>
#include <utility>

namespace bp
{
namespace
{
/// bp_restore.frag with the template's springs as code (thesis §3.5) in
/// place of its reads from the springs buffer (with BP_GENERATED_SPRINGS).
std::string generatedRestoreSource(const std::string& springSumCode)
{
  return spliceCode(bpShaderRestoreFrag, bpShaderRestoreFragNumber, "//BP::GeneratedSprings",
    springSumCode, GeneratedSpringsSource);
}

/// Attaches `texture` (0: none) as colour attachment k of the bound framebuffer.
void attach(GLenum framebuffer, int k, GLuint texture)
{
  glFramebufferTexture2D(framebuffer, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D, texture, 0);
}
} // namespace

GpuLayout::GpuLayout(const ParticleLayout& layout, std::size_t elements, std::size_t particles)
  : elementCount(int(elements))
  , particlesPerElement(int(particles))
  , elementGrid{ int(layout.elementGrid[0]), int(layout.elementGrid[1]) }
  , blocksPerRow(int(layout.blocksPerRow))
  , particleTextureWidth(int(layout.width))
  , particleTextureHeight(int(layout.height))
{
}

std::size_t GpuLayout::particleTexel(int e, int i) const
{
  const int bx = i % this->blocksPerRow, by = i / this->blocksPerRow;
  const int x = bx * this->elementGrid[0] + e % this->elementGrid[0];
  const int y = by * this->elementGrid[1] + e / this->elementGrid[0];
  return std::size_t(y) * this->particleTextureWidth + x;
}

int GpuPass::location(const char* name) const
{
  return glGetUniformLocation(this->Program, name);
}

GpuPass& GpuPass::texture(const char* name, GLuint texture, GLenum target)
{
  glActiveTexture(GLenum(GL_TEXTURE0 + this->Unit));
  glBindTexture(target, texture);
  this->setInt(name, this->Unit);
  ++this->Unit;
  return *this;
}

void GpuPass::setInt(const char* name, int value) const
{
  glUniform1i(this->location(name), value);
}

void GpuPass::setUnsigned(const char* name, unsigned value) const
{
  glUniform1ui(this->location(name), value);
}

void GpuPass::setFloat(const char* name, float value) const
{
  glUniform1f(this->location(name), value);
}

void GpuPass::setVec3(const char* name, const float* value) const
{
  glUniform3f(this->location(name), value[0], value[1], value[2]);
}

void GpuPass::setVec4(const char* name, const float* value) const
{
  glUniform4fv(this->location(name), 1, value);
}

void GpuPass::setIVec2(const char* name, int x, int y) const
{
  glUniform2i(this->location(name), x, y);
}

void GpuPass::setIVec3(const char* name, int x, int y, int z) const
{
  glUniform3i(this->location(name), x, y, z);
}

void GpuPass::run(std::initializer_list<GLuint> targets, int width, int height) const
{
  glBindFramebuffer(GL_FRAMEBUFFER, this->Passes.Framebuffer.get());
  GLenum buffers[4];
  int k = 0;
  for (GLuint target : targets)
  {
    attach(GL_FRAMEBUFFER, k, target);
    buffers[k] = GLenum(GL_COLOR_ATTACHMENT0 + k);
    ++k;
  }
  for (int j = k; j < 4; ++j)
  {
    attach(GL_FRAMEBUFFER, j, 0);
  }
  glDrawBuffers(k, buffers);
  glViewport(0, 0, width, height);
  // A render window's state may be anything: the passes need none of it.
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBindVertexArray(this->Passes.Triangle.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GpuPass::runPerElement(std::initializer_list<GLuint> targets) const
{
  this->run(targets, this->Layout.elementGrid[0], this->Layout.elementGrid[1]);
}

void GpuPass::runPerParticle(std::initializer_list<GLuint> targets) const
{
  this->run(targets, this->Layout.particleTextureWidth, this->Layout.particleTextureHeight);
}

std::string GpuPasses::compile(const std::string& springSumCode)
{
  Programs& p = this->programs;
  const bool generated = !springSumCode.empty();
  const std::string restore =
    generated ? generatedRestoreSource(springSumCode) : std::string(bpShaderRestoreFrag);
  const std::pair<ShaderPiece, GlProgram*> passes[] = {
    { { bpShaderResetFragNumber, bpShaderResetFrag }, &p.reset },
    { { bpShaderAdvectFragNumber, bpShaderAdvectFrag }, &p.advect },
    { { bpShaderRestoreFragNumber, restore }, &p.restore },
    { { bpShaderMatchFragNumber, bpShaderMatchFrag }, &p.match },
    { { bpShaderMatchApplyFragNumber, bpShaderMatchApplyFrag }, &p.matchApply },
    { { bpShaderGaussSeidelFragNumber, bpShaderGaussSeidelFrag }, &p.gaussSeidel },
    { { bpShaderTestFragNumber, bpShaderTestFrag }, &p.test },
    { { bpShaderFinalizeFragNumber, bpShaderFinalizeFrag }, &p.finalize },
    { { bpShaderNormalsFragNumber, bpShaderNormalsFrag }, &p.normals },
    { { bpShaderSamplesFragNumber, bpShaderSamplesFrag }, &p.samples },
    { { bpShaderLinkFragNumber, bpShaderLinkFrag }, &p.link },
    { { bpShaderPoseFragNumber, bpShaderPoseFrag }, &p.pose }
  };
  for (const auto& pass : passes)
  {
    const bool restorePass = pass.second == &p.restore;
    const std::string error = buildPassProgram(
      pass.first, restorePass && generated ? "#define BP_GENERATED_SPRINGS\n" : "", *pass.second);
    if (!error.empty())
    {
      return error;
    }
  }
  this->Triangle = makeVertexArray();
  this->Framebuffer = makeFramebuffer();
  this->CopyTarget = makeFramebuffer();
  return std::string();
}

GpuPass GpuPasses::begin(const GlProgram& program, const SharedPassInputs& shared) const
{
  glUseProgram(program.get());
  const GpuLayout& layout = *shared.layout;
  GpuPass pass(*this, layout, program.get());
  const Parameters& p = *shared.parameters;
  pass.setIVec2("bpElementGrid", layout.elementGrid[0], layout.elementGrid[1]);
  pass.setInt("bpBlocksPerRow", layout.blocksPerRow);
  pass.setInt("bpElements", layout.elementCount);
  pass.setInt("bpParticles", layout.particlesPerElement);
  pass.setUnsigned("bpSeed", p.seed);
  pass.setVec3("bpEmitterMin", p.emitterMin.data());
  pass.setVec3("bpEmitterMax", p.emitterMax.data());
  pass.setFloat("bpElementSize", p.elementSize);
  pass.setInt("bpOrientation", int(p.orientation));
  pass.setVec3("bpFrameRow0", p.frame.data());
  pass.setVec3("bpFrameRow1", p.frame.data() + 3);
  pass.setVec3("bpFrameRow2", p.frame.data() + 6);
  pass.setFloat("bpLifetimeMin", p.lifetimeMin);
  pass.setFloat("bpLifetimeMax", p.lifetimeMax);
  pass.setInt("bpLinked", shared.linked ? 1 : 0);
  const bool lattice = p.releasePattern == ReleasePattern::Lattice;
  pass.setInt("bpLattice", lattice ? 1 : 0);
  pass.setIVec3("bpLatticeCounts", p.lattice.counts[0], p.lattice.counts[1], p.lattice.counts[2]);
  pass.setVec3("bpLatticeOrigin", p.lattice.origin.data());
  pass.setVec3("bpLatticeSpacing", p.lattice.spacing.data());
  // Bound even when unused: an unbound sampler would share unit 0 with
  // samplers of other types, and GL refuses to draw.
  pass.texture("bpLatticeSites", shared.latticeSites);
  if (shared.fieldCache && shared.fieldCache->field())
  {
    shared.fieldCache->applyTo(pass);
  }
  return pass;
}

void GpuPasses::readTexture(GLuint texture, int width, int height, std::vector<float>& out) const
{
  glBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer.get());
  attach(GL_FRAMEBUFFER, 0, texture);
  for (int j = 1; j < 4; ++j)
  {
    attach(GL_FRAMEBUFFER, j, 0);
  }
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  out.resize(std::size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out.data());
}

void GpuPasses::readParticles(
  GLuint texture, const GpuLayout& layout, std::vector<float>* xyz, std::vector<float>* w) const
{
  std::vector<float> texels;
  this->readTexture(texture, layout.particleTextureWidth, layout.particleTextureHeight, texels);
  const int elements = layout.elementCount, n = layout.particlesPerElement;
  const std::size_t count = std::size_t(elements) * n;
  if (xyz)
    xyz->resize(3 * count);
  if (w)
    w->resize(count);
  for (int e = 0; e < elements; ++e)
    for (int i = 0; i < n; ++i)
    {
      const float* t = &texels[4 * layout.particleTexel(e, i)];
      const std::size_t id = std::size_t(e) * n + i;
      if (xyz)
        std::copy(t, t + 3, xyz->begin() + 3 * id);
      if (w)
        (*w)[id] = t[3];
    }
}

void GpuPasses::clearTexture(GLuint texture, const float* value) const
{
  glBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer.get());
  attach(GL_FRAMEBUFFER, 0, texture);
  for (int j = 1; j < 4; ++j)
  {
    attach(GL_FRAMEBUFFER, j, 0);
  }
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &buffer);
  // A clear obeys the scissor test and the colour mask: a render window's
  // state may be anything.
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearBufferfv(GL_COLOR, 0, value);
}

void GpuPasses::copyTexture(GLuint from, GLuint to, int width, int height) const
{
  glBindFramebuffer(GL_READ_FRAMEBUFFER, this->Framebuffer.get());
  attach(GL_READ_FRAMEBUFFER, 0, from);
  // A framebuffer is as large as its smallest attachment: a per-element
  // texture left attached by the last pass would crop a particle texture.
  for (int j = 1; j < 4; ++j)
  {
    attach(GL_READ_FRAMEBUFFER, j, 0);
  }
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->CopyTarget.get());
  attach(GL_DRAW_FRAMEBUFFER, 0, to);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glDisable(GL_SCISSOR_TEST);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

} // namespace bp
