// SPDX-License-Identifier: BSD-3-Clause
#include "GpuPasses.h"

#include "BoundParticlesShaders.h" // generated from Shaders/
#include "GpuStateLayout.h"
#include "KernelConstants.h"
#include "ShaderSource.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace bp
{
namespace
{
/// What a compute dispatch's writes must be visible to: the next dispatch's
/// image loads and texel fetches (a draw's too), copies, reads and clears.
constexpr GLbitfield AfterShaderWrites = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
  GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT;

/// The most workgroups a dispatch takes along x (OpenGL 4.3 promises 65,535).
constexpr std::size_t MostGroupsAlongX = 65535;

/// Elements a fused step's workgroup holds: a SIMD group's worth (a warp of
/// 32 on NVIDIA, a wavefront of 32 or 64 on AMD, 8 lanes on llvmpipe) runs
/// the per-element phases, and a small template fills at least 128 threads.
int fusedGroupElements(int particles, int maxThreads)
{
  const int elements = std::max(32, 128 / std::max(particles, 1));
  return std::max(1, std::min(elements, maxThreads / std::max(particles, 1)));
}

/// A kernel run as a pass of its own (bp_pass.glsl): its file, its pass
/// function, its domain and targets, the program it becomes and what the
/// timer calls it.
struct PassKernel
{
  ShaderPiece kernel;
  const char* function;
  bool perElement;
  int targets;
  GLuint GpuPasses::Programs::*program;
  const char* name;
};

/// Every kernel run as a pass of its own, `restore` the Jacobi kernel.
std::vector<PassKernel> passKernels(const ShaderPiece& restore)
{
  using P = GpuPasses::Programs;
  return { { { bpShaderResetNumber, bpShaderReset }, "bpResetPass", true, 4, &P::reset, "reset" },
    { { bpShaderSlipNumber, bpShaderSlip }, "bpSlipPass", false, 2, &P::slip, "slip" },
    { { bpShaderSlipNumber, bpShaderSlip }, "bpSlipSharePass", false, 1, &P::slipShare,
      "slip share" },
    { { bpShaderAdvectNumber, bpShaderAdvect }, "bpAdvectPass", false, 2, &P::advect, "advect" },
    { restore, "bpRestorePass", false, 1, &P::restore, "restore" },
    { { bpShaderMatchNumber, bpShaderMatch }, "bpMatchPass", true, 4, &P::match, "match" },
    { { bpShaderMatchNumber, bpShaderMatch }, "bpMatchApplyPass", false, 1, &P::matchApply,
      "match apply" },
    { { bpShaderGaussSeidelNumber, bpShaderGaussSeidel }, "bpGaussSeidelPass", false, 1,
      &P::gaussSeidel, "gauss-seidel" },
    { { bpShaderTestNumber, bpShaderTest }, "bpTestPass", true, 2, &P::test, "test" },
    { { bpShaderFinalizeNumber, bpShaderFinalize }, "bpFinalizePass", false, 1, &P::finalize,
      "finalize" },
    { { bpShaderFinalizeNumber, bpShaderFinalize }, "bpWallPass", false, 1, &P::wall, "wall" },
    { { bpShaderNormalsNumber, bpShaderNormals }, "bpNormalsPass", false, 1, &P::normals,
      "normals" },
    { { bpShaderSamplesNumber, bpShaderSamples }, "bpSamplesPass", false, 1, &P::samples,
      "samples" },
    { { bpShaderLinkNumber, bpShaderLink }, "bpLinkPass", false, 1, &P::link, "link" },
    { { bpShaderPoseNumber, bpShaderPose }, "bpPosePass", true, 2, &P::pose, "pose" } };
}

/// bp_restore.glsl with the template's springs as code (thesis §3.5) in
/// place of its reads from the springs buffer (with BP_GENERATED_SPRINGS).
ShaderPiece restoreKernel(const std::string& springSumCode)
{
  if (springSumCode.empty())
  {
    return { bpShaderRestoreNumber, bpShaderRestore };
  }
  return { bpShaderRestoreNumber,
    spliceCode(bpShaderRestore, bpShaderRestoreNumber, "//BP::GeneratedSprings", springSumCode,
      GeneratedSpringsSource) };
}

/// The bytes of a texel of a sized internal format the engine uses.
std::size_t texelBytes(GLint format)
{
  switch (format)
  {
    case GL_R32F:
    case GL_R32I:
    case GL_R32UI:
    case GL_RGBA8:
      return 4;
    case GL_RG32F:
    case GL_RGBA16F:
      return 8;
    case GL_RGB32F:
      return 12;
    default:
      return 16; // RGBA32F, the state's format
  }
}

/// The bytes of level 0 of the texture bound to `target` on the active unit.
std::size_t boundTextureBytes(GLenum target)
{
  GLint width = 0, height = 0, depth = 0, format = 0;
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_WIDTH, &width);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_HEIGHT, &height);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_DEPTH, &depth);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 1)) *
    std::size_t(std::max(depth, 1)) * texelBytes(format);
}

/// The bytes of level 0 of a 2D texture, its binding on the active unit kept.
std::size_t textureBytes(GLuint texture)
{
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glBindTexture(GL_TEXTURE_2D, texture);
  const std::size_t bytes = boundTextureBytes(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, GLuint(previous));
  return bytes;
}

/// Attaches `texture` (0: none) as colour attachment k of the bound framebuffer.
void attach(GLenum framebuffer, int k, GLuint texture)
{
  glFramebufferTexture2D(framebuffer, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D, texture, 0);
}
} // namespace

int FusedStep::imagesBound(bool inertial)
{
  return 1 + ElementTextureCount + (inertial ? 1 : 0);
}

FusedStep FusedStep::of(const Parameters& parameters, int particles, bool springs,
  const ComputeLimits& limits, int wantedElements)
{
  FusedStep fused;
  fused.particles = particles;
  const int maxThreads = limits.threads;
  int elements = wantedElements > 0
    ? std::max(1, std::min(wantedElements, maxThreads / std::max(particles, 1)))
    : fusedGroupElements(particles, maxThreads);
  // Shared memory: a position per thread (and a slip, for heavy particles),
  // six values per element (bp_step.comp).
  fused.inertial = carriesInertia(parameters);
  const long perElement = 16L * particles * (fused.inertial ? 2 : 1) + 6L * 16;
  if (wantedElements > 0)
  {
    elements = int(std::max(1L, std::min(long(elements), limits.sharedBytes / perElement)));
  }
  const long bytes = perElement * elements;
  // Links join elements, which a workgroup cannot hold; a GPU with fewer
  // image units than the step stores into cannot compile it.
  if (parameters.linking != Linking::None || particles > maxThreads || bytes > limits.sharedBytes ||
    imagesBound(fused.inertial) > limits.images)
  {
    return fused;
  }
  fused.groupElements = elements;
  const Restoration r = parameters.restoration;
  fused.restoration = r == Restoration::ShapeMatching ? FusedRestore::ShapeMatching
    : !springs                                        ? FusedRestore::None
    : r == Restoration::GaussSeidel                   ? FusedRestore::GaussSeidel
                                                      : FusedRestore::Jacobi;
  return fused;
}

KernelSpecialisation KernelSpecialisation::of(const Parameters& parameters)
{
  KernelSpecialisation s;
  s.integrator = parameters.integrator;
  s.trackPoses = parameters.trackPoses;
  s.inertial = carriesInertia(parameters);
  return s;
}

std::string KernelSpecialisation::defines(bool inertia, bool poses) const
{
  const char* integrator = this->integrator == Integrator::RK4 ? "BP_INTEGRATOR_RK4"
    : this->integrator == Integrator::RK2                      ? "BP_INTEGRATOR_RK2"
                                                               : "BP_INTEGRATOR_EULER";
  return std::string("#define BP_INTEGRATOR ") + integrator + "\n" +
    (inertia && this->inertial ? "#define BP_INERTIAL\n" : "") +
    (poses && this->trackPoses ? "#define BP_TRACK_POSES\n" : "");
}

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
  return this->Passes.uniformLocation(this->Program, name);
}

int GpuPasses::uniformLocation(GLuint program, const char* name) const
{
  // Asked of the driver once per program and name: a pass sets its uniforms
  // every step, and glGetUniformLocation hashes the name each time.
  std::unordered_map<std::string, int>& names = this->Locations[program];
  const auto known = names.find(name);
  if (known != names.end())
  {
    return known->second;
  }
  ++this->LocationLookups;
  const int at = glGetUniformLocation(program, name);
  names.emplace(name, at);
  return at;
}

GpuPass& GpuPass::texture(const char* name, GLuint texture, GLenum target)
{
  const int at = this->location(name);
  if (at < 0)
  {
    return *this; // a sampler the program does not use
  }
  const auto known = std::find_if(this->Units.begin(), this->Units.end(),
    [&](const std::pair<std::string, int>& bound) { return bound.first == name; });
  const int unit = known != this->Units.end() ? known->second : this->Unit++;
  if (known == this->Units.end())
  {
    this->Units.push_back({ name, unit });
  }
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(target, texture);
  glUniform1i(at, unit);
  // The traffic counts the state, not the field's samples (3D textures):
  // neighbouring particles read the same cells, from cache, and how much of
  // the field a step touches is not known here.
  if (this->Passes.Observer && target == GL_TEXTURE_2D)
  {
    this->UnitBytes.resize(std::max<std::size_t>(this->UnitBytes.size(), unit + 1), 0);
    this->UnitBytes[unit] = boundTextureBytes(target);
  }
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
  PassObserver* const observer = this->Passes.Observer;
  if (observer)
  {
    observer->begin(this->Passes.nameOf(this->Program));
  }
  if (this->Passes.Path == GpuPath::Compute)
  {
    this->dispatch(targets, width, height);
  }
  else
  {
    this->draw(targets, width, height);
  }
  if (observer)
  {
    std::size_t written = 0;
    for (GLuint target : targets)
    {
      written += textureBytes(target); // each target is the pass's domain
    }
    this->tellTraffic(written);
    observer->end();
  }
}

void GpuPass::tellTraffic(std::size_t written) const
{
  std::size_t read = 0;
  for (std::size_t bytes : this->UnitBytes)
  {
    read += bytes;
  }
  this->Passes.Observer->traffic(read, written);
}

void GpuPass::dispatch(std::initializer_list<GLuint> targets, int width, int height) const
{
  GLuint k = 0;
  for (GLuint target : targets)
  {
    glBindImageTexture(k++, target, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  }
  this->setIVec2("bpDomainSize", width, height);
  this->setInt("bpTargetCount", int(k));
  glDispatchCompute(GLuint(width + PassGroupSize - 1) / PassGroupSize,
    GLuint(height + PassGroupSize - 1) / PassGroupSize, 1);
  glMemoryBarrier(AfterShaderWrites);
}

void GpuPass::runGroups(std::size_t groups, std::initializer_list<GLuint> images) const
{
  PassObserver* const observer = this->Passes.Observer;
  if (observer)
  {
    observer->begin(this->Passes.nameOf(this->Program));
  }
  GLuint k = 0;
  for (GLuint image : images)
  {
    glBindImageTexture(k++, image, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  }
  // Workgroups along x, then rows of them along y (bp_step.comp numbers them so).
  const std::size_t x = std::max<std::size_t>(1, std::min(groups, MostGroupsAlongX));
  glDispatchCompute(GLuint(x), GLuint((groups + x - 1) / x), 1);
  glMemoryBarrier(AfterShaderWrites);
  if (observer)
  {
    std::size_t written = 0;
    for (GLuint image : images)
    {
      written += image ? textureBytes(image) : 0;
    }
    this->tellTraffic(written);
    observer->end();
  }
}

void GpuPass::draw(std::initializer_list<GLuint> targets, int width, int height) const
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

std::string GpuPasses::compile(GpuPath path, const std::string& springSumCode,
  const FusedStep& fusedStep, const KernelSpecialisation& specialisation, GpuProgramCache& cache)
{
  this->Path = path;
  this->fused = fusedStep;
  this->Specialisation = specialisation;
  this->Locations.clear(); // a program's name may be a deleted one's
  this->LocationLookups = 0;
  const ShaderPiece restore = restoreKernel(springSumCode);
  const bool compute = path == GpuPath::Compute;
  const ShaderPiece main = compute ? ShaderPiece{ bpShaderPassCompNumber, bpShaderPassComp }
                                   : ShaderPiece{ bpShaderPassFragNumber, bpShaderPassFrag };
  const std::string generated = springSumCode.empty() ? "" : "#define BP_GENERATED_SPRINGS\n";
  this->Names.clear();
  for (const PassKernel& k : passKernels(restore))
  {
    // The advect kernel's program is built for the integrator and inertia;
    // the slip kernels' take the advect kernel (bp_slip.glsl's
    // bpWalledSlipOf finds, with Walls of the Surfaces, where the advect
    // pass's walls left a particle), and so the integrator.
    const bool slips = k.program == &Programs::slip || k.program == &Programs::slipShare;
    const bool advects = k.program == &Programs::advect;
    const std::string defines = std::string("#define BP_PASS ") + k.function + "\n" +
      "#define BP_TARGETS " + std::to_string(k.targets) + "\n" +
      (k.perElement ? "#define BP_PER_ELEMENT\n" : "") + generated +
      (advects || slips ? specialisation.defines(advects, false) : std::string());
    GLuint& program = this->programs.*(k.program);
    const ShaderPiece advect{ bpShaderAdvectNumber, bpShaderAdvect };
    const std::string name =
      shaderFileName(k.kernel.number) + " (" + k.function + ", " + gpuPathName(path) + " path)";
    const ShaderPiece pass{ bpShaderPassNumber, bpShaderPass };
    const std::string error = slips
      ? cache.build(path, name, defines, { advect, k.kernel, pass, main }, program)
      : cache.build(path, name, defines, { k.kernel, pass, main }, program);
    if (!error.empty())
    {
      return error;
    }
    this->Names.push_back({ program, k.name });
  }
  this->programs.step = 0;
  if (compute && this->fused.groupElements > 0)
  {
    const std::string error = this->compileFusedStep(restore, generated, cache);
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

std::string GpuPasses::compileFusedStep(
  const ShaderPiece& restore, const std::string& generated, GpuProgramCache& cache)
{
  const FusedStep& f = this->fused;
  const std::string defines = "#define BP_N " + std::to_string(f.particles) +
    "\n#define BP_GROUP_ELEMENTS " + std::to_string(f.groupElements) +
    "\n#define BP_GROUP_THREADS " + std::to_string(f.groupElements * f.particles) +
    "\n#define BP_FUSED_NONE " + std::to_string(int(FusedRestore::None)) +
    "\n#define BP_FUSED_JACOBI " + std::to_string(int(FusedRestore::Jacobi)) +
    "\n#define BP_FUSED_GAUSS_SEIDEL " + std::to_string(int(FusedRestore::GaussSeidel)) +
    "\n#define BP_FUSED_SHAPE_MATCHING " + std::to_string(int(FusedRestore::ShapeMatching)) +
    "\n#define BP_RESTORATION " + std::to_string(int(f.restoration)) + "\n" + generated +
    this->Specialisation.defines(true, true) +
    "layout(rgba32f, binding = 0) uniform writeonly image2D bpParticlesOut;\n" +
    (f.inertial ? "layout(rgba32f, binding = " + std::to_string(1 + ElementTextureCount) +
          ") uniform writeonly image2D bpSlipsOut;\n"
                : std::string());
  const std::string error = cache.build(GpuPath::Compute, "bp_step.comp (the fused step)", defines,
    { { bpShaderResetNumber, bpShaderReset }, { bpShaderSlipNumber, bpShaderSlip },
      { bpShaderAdvectNumber, bpShaderAdvect }, restore,
      { bpShaderGaussSeidelNumber, bpShaderGaussSeidel }, { bpShaderMatchNumber, bpShaderMatch },
      { bpShaderTestNumber, bpShaderTest }, { bpShaderFinalizeNumber, bpShaderFinalize },
      { bpShaderPoseNumber, bpShaderPose }, { bpShaderStepCompNumber, bpShaderStepComp } },
    this->programs.step, true);
  this->Names.push_back({ this->programs.step, "step (fused)" });
  return error;
}

const std::string& GpuPasses::nameOf(GLuint program) const
{
  static const std::string unknown = "pass";
  for (const auto& name : this->Names)
  {
    if (name.first == program)
    {
      return name.second;
    }
  }
  return unknown;
}

GpuPass GpuPasses::begin(GLuint program, const SharedPassInputs& shared) const
{
  glUseProgram(program);
  const GpuLayout& layout = *shared.layout;
  GpuPass pass(*this, layout, program);
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
  // The walls (Boundary Stick, Slip, Bounce; bp_common.glsl), read by
  // several kernels.
  pass.setInt("bpBoundary", int(p.boundary));
  pass.setFloat("bpRestitution", p.restitution);
  const bool lattice = p.releasePattern == ReleasePattern::Lattice;
  pass.setInt("bpLattice", lattice ? 1 : 0);
  pass.setIVec3("bpLatticeCounts", p.lattice.counts[0], p.lattice.counts[1], p.lattice.counts[2]);
  pass.setVec3("bpLatticeOrigin", p.lattice.origin.data());
  pass.setVec3("bpLatticeSpacing", p.lattice.spacing.data());
  // Bound even when unused: an unbound sampler would share unit 0 with
  // samplers of other types, and GL refuses to draw.
  pass.texture("bpLatticeSites", shared.latticeSites);
  if (shared.bindField)
  {
    shared.bindField(pass);
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

void GpuPasses::writeTexture(
  GLuint texture, int width, int height, const std::vector<float>& texels) const
{
  // A render window's context may have any texture bound on its active unit.
  GLint bound = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  glBindTexture(GL_TEXTURE_2D, texture);
  TightUnpack unpack;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
  glBindTexture(GL_TEXTURE_2D, GLuint(bound));
}

void GpuPasses::writeParticles(GLuint texture, const GpuLayout& layout,
  const std::vector<float>& xyz, const std::vector<float>* w) const
{
  std::vector<float> texels;
  this->readTexture(texture, layout.particleTextureWidth, layout.particleTextureHeight, texels);
  const int elements = layout.elementCount, n = layout.particlesPerElement;
  for (int e = 0; e < elements; ++e)
    for (int i = 0; i < n; ++i)
    {
      float* t = &texels[4 * layout.particleTexel(e, i)];
      const std::size_t id = std::size_t(e) * n + i;
      std::copy(xyz.begin() + std::ptrdiff_t(3 * id), xyz.begin() + std::ptrdiff_t(3 * id + 3), t);
      t[3] = w ? (*w)[id] : 0.0f;
    }
  this->writeTexture(texture, layout.particleTextureWidth, layout.particleTextureHeight, texels);
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
  static const std::string copy = "copy";
  if (this->Observer)
  {
    this->Observer->begin(copy);
  }
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
  if (this->Observer)
  {
    const std::size_t bytes = std::size_t(width) * std::size_t(height) * 16;
    this->Observer->traffic(bytes, bytes);
    this->Observer->end();
  }
}

} // namespace bp
