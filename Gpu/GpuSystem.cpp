// SPDX-License-Identifier: BSD-3-Clause
// A system's making and its step (GpuSystem.h); each kernel's inputs and its
// own pass are in GpuSystemPasses.cpp.
#include "GpuSystem.h"

#include "KernelConstants.h"
#include "Quaternion.h"
#include "SuperSet.h"
#include "Surfaces.h"
#include "Walls.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace bp
{

namespace
{
/// Triangles (9 floats each) as a list texture, a corner a texel,
/// OutletsPerRow triangles a row; one texel when there are none, since the
/// passes bind it.
GlTexture triangleListTexture(const std::vector<float>& triangles)
{
  std::vector<float> corners(4 * 3 * std::max<std::size_t>(triangles.size() / 9, 1), 0.0f);
  for (std::size_t c = 0; c < triangles.size() / 3; ++c)
  {
    std::copy_n(&triangles[3 * c], 3, &corners[4 * c]);
  }
  return makeListTexture(corners, 3 * OutletsPerRow);
}
} // namespace

std::string GpuSystem::make(const ElementTemplate& elementTemplate,
  const Parameters& systemParameters, int textureSizeLimit, bool generatedSprings,
  FusedSteps fusedSteps, GpuProgramCache& programs)
{
  this->shape = elementTemplate;
  this->parameters = systemParameters;
  const Parameters& p = this->parameters;
  const std::size_t n = this->shape.particleCount();
  const ParticleLayout wanted = ParticleLayout::of(p.numberOfElements, n);
  this->layout = GpuLayout(wanted, p.numberOfElements, n);
  this->FrameQuaternion = quaternionFromRotation(p.frame);
  this->LongAxis = longAxis(this->shape);
  std::string error = this->checkTextureSize(wanted, textureSizeLimit);
  const std::vector<float> noOutlets;
  const std::vector<float>& outlets = p.surfaces ? p.surfaces->outletCorners() : noOutlets;
  const std::vector<float>& walls = p.surfaces ? p.surfaces->wallCorners() : noOutlets;
  if (error.empty())
  {
    error = gpuOutletError(outlets.size() / 9);
  }
  if (error.empty())
  {
    error = gpuWallError(walls.size() / 9);
  }
  if (!error.empty())
  {
    return error;
  }
  GpuPathChoice path = currentGpuPath();
  const bool compute = path.path == GpuPath::Compute;
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  // The variable is read on either path, so a value it does not know is said
  // wherever it is set.
  std::string unknown;
  const bool fuses =
    fusesSteps(fusedSteps, renderer ? renderer : "", std::getenv(FusedStepVariable), &unknown) &&
    compute;
  if (!unknown.empty())
  {
    path.warning += (path.warning.empty() ? "" : "\n") + unknown;
  }
  const char* group = std::getenv(FusedGroupVariable);
  if (group && *group && fusedGroupValue(group) == 0)
  {
    path.warning += (path.warning.empty() ? "" : "\n") + std::string(FusedGroupVariable) + "=" +
      group +
      " is not a whole number of elements from 1 to 1024: the fused step takes a SIMD "
      "group's worth.";
  }
  if (compute)
  {
    path.note += fuses
      ? " A system's step is one fused dispatch where its elements fit a workgroup."
      : " Each kernel is a dispatch of its own.";
  }
  this->shapeTables.upload(this->shape, p.elementSize, generatedSprings);
  const KernelSpecialisation specialisation = KernelSpecialisation::of(p);
  error = this->passes.compile(path.path, this->shapeTables.springSumCode,
    fuses ? this->fusedStep() : FusedStep(), specialisation, programs);
  if (!error.empty() && compute)
  {
    // A compute program the driver refuses: the fragment path, same kernels.
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    fallBackToFragmentPath(path, error, version ? version : "?");
    error = this->passes.compile(
      GpuPath::Fragment, this->shapeTables.springSumCode, FusedStep(), specialisation, programs);
  }
  sayGpuPathOnce(path);
  if (!error.empty())
  {
    return error;
  }
  // The super set's lattice, the same table the CPU engine builds.
  this->state.make(this->layout,
    makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax),
    p.trailLength, carriesInertia(p));
  // Release centres of a seed source (SeedPointsPerRow a row); one texel
  // when there is none, since the reset pass binds it.
  std::vector<float> seeds(4 * std::max<std::size_t>(p.seedPoints.size() / 3, 1), 0.0f);
  for (std::size_t k = 0; k < p.seedPoints.size() / 3; ++k)
  {
    std::copy_n(&p.seedPoints[3 * k], 3, &seeds[4 * k]);
  }
  this->SeedPoints = makeListTexture(seeds, SeedPointsPerRow);
  // The Outlet and Wall triangles (bpOutletCount, bpWallCount 0: none read).
  this->OutletCount = int(outlets.size() / 9);
  this->Outlets = triangleListTexture(outlets);
  this->WallCount = int(walls.size() / 9);
  this->Walls = triangleListTexture(walls);
  return glGetError() == GL_NO_ERROR
    ? std::string()
    : std::string("the GPU could not create the engine's float textures (RGBA32F render targets)");
}

std::string GpuSystem::checkTextureSize(const ParticleLayout&, int textureSizeLimit) const
{
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  maxSize = std::min<GLint>(maxSize, textureSizeLimit);
  return gpuTextureError(this->shape, this->parameters.numberOfElements, maxSize);
}

FusedStep GpuSystem::fusedStep() const
{
  GLint threads = 0, sizeX = 0, shared = 0, images = 0, units = 0;
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &threads);
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, 0, &sizeX);
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &shared);
  glGetIntegerv(GL_MAX_COMPUTE_IMAGE_UNIFORMS, &images);
  glGetIntegerv(GL_MAX_IMAGE_UNITS, &units);
  ComputeLimits limits;
  limits.threads = std::min(threads, sizeX);
  limits.sharedBytes = shared;
  limits.images = std::min(images, units);
  // BOUNDPARTICLES_FUSED_GROUP: elements a workgroup, for tuning on a GPU.
  const char* wanted = std::getenv(FusedGroupVariable);
  return FusedStep::of(this->parameters, this->layout.particlesPerElement,
    !this->shape.springs.empty(), limits, fusedGroupValue(wanted));
}

void GpuSystem::initialize(double startTime)
{
  // Place every element as generation 0 ...
  this->reset(true, releasesAt(this->parameters, startTime, 0.0), startTime);
  this->advect(true, 0.0, 0.0);
  // ... with no flag set and zero force, as Engine::initialize leaves them.
  const GLuint placed = this->state.advected.get();
  this->test(placed, true, 0.0, 0.0f);
  this->finalize(placed, true);
  // Released with the flow's velocity: no slip (Engine::place).
  const float none[4] = { 0, 0, 0, 0 };
  this->passes.clearTexture(this->state.slips.get(), none);
  // Every spin 0 (the reset pass placed every pose), and no trail yet.
  const float zero[4] = { 0, 0, 0, 0 };
  this->passes.clearTexture(this->state.current(ElementTexture::Spins), zero);
  this->state.clearTrail(this->passes);
  this->updateNormals();
}

void GpuSystem::step(double t, double h)
{
  // The trail's pose, recorded before anything moves (Engine::step).
  if (recordsTrailAt(this->parameters, t))
  {
    this->state.recordTrail(this->passes, this->layout, t);
  }
  const VectorField* field = this->fieldCache.field();
  const float endWeight = field ? field->timeWeight(t + h) : 0.0f;
  if (this->passes.programs.step)
  {
    this->runFusedStep(t, h, endWeight);
    return;
  }
  // 1. Reset.
  this->reset(false, releasesAt(this->parameters, t, h), t);
  // 2. Advect (heavy particles: their slip's step first).
  if (carriesInertia(this->parameters))
  {
    this->stepSlips(t, h);
  }
  this->advect(false, t, h);
  // 3. Restore: K iterations of the elements' own restoration, each followed,
  // in a super set, by one pass over the links (Engine::stepLinked).
  GLuint positions = this->state.advected.get();
  int restorationPass = 0;
  for (int k = 0; k < this->parameters.iterations; ++k)
  {
    positions = this->restoreOnce(positions, restorationPass);
  }
  // The walls after restoration: no particle pushed back through one.
  const bool restores =
    !this->shape.springs.empty() || this->parameters.restoration == Restoration::ShapeMatching;
  if (isWall(this->parameters.boundary) && restores)
  {
    positions = this->wallRestored(positions, endWeight, restorationPass);
  }
  // 5. Reposition test, then the new state.
  this->test(positions, false, h, endWeight);
  this->finalize(positions, false);
  if (carriesInertia(this->parameters))
  {
    this->shareSlips(t, h, endWeight);
  }
  // 6. Poses and spins.
  if (this->parameters.trackPoses)
  {
    this->updatePoses(h, endWeight);
  }
}

void GpuSystem::runFusedStep(double t, double h, float endWeight)
{
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.step);
  // Every kernel's inputs; what one kernel hands the next stays in the
  // workgroup (the samplers of the passes' intermediate textures are unused).
  this->resetInputs(pass, false, releasesAt(this->parameters, t, h), t);
  this->advectInputs(pass, false, t, h);
  this->jacobiInputs(pass, 0);
  this->matchInputs(pass, 0);
  pass.texture("bpColouredSprings", this->shapeTables.colouredSprings.get());
  this->testInputs(pass, 0, false, h, endWeight);
  this->finalizeInputs(pass, 0, false);
  this->poseInputs(pass, h, endWeight);
  this->slipInputs(pass, t, h);
  pass.setInt("bpIterations", this->parameters.iterations);
  pass.setInt("bpColourCount", this->shapeTables.colourCount);
  // Poses and spins are fitted in the program compiled with BP_TRACK_POSES.
  const bool poses = this->passes.specialisation().trackPoses;
  using E = ElementTexture;
  const int perGroup = this->passes.fused.groupElements;
  // Images: the particles', then each per-element row's (GpuStateLayout.h's order).
  const std::size_t groups = std::size_t((this->layout.elementCount + perGroup - 1) / perGroup);
  if (this->passes.fused.inertial)
  {
    // The slips' image last (GpuPasses::compileFusedStep); the new ones
    // become current.
    pass.runGroups(groups,
      { s.particles.next(), s.element(E::State).next(), s.element(E::Centers).next(),
        s.element(E::Orientations).next(), s.element(E::Poses).next(), s.element(E::Spins).next(),
        s.slipsNext.get() });
    std::swap(s.slips, s.slipsNext);
  }
  else
  {
    pass.runGroups(groups,
      { s.particles.next(), s.element(E::State).next(), s.element(E::Centers).next(),
        s.element(E::Orientations).next(), s.element(E::Poses).next(),
        s.element(E::Spins).next() });
  }
  s.particles.flip();
  for (E row : { E::State, E::Centers, E::Orientations, E::Poses })
  {
    s.element(row).flip();
  }
  if (poses)
  {
    s.element(E::Spins).flip();
  }
}

void GpuSystem::updateNormals()
{
  GpuPass pass = this->begin(this->passes.programs.normals);
  pass.texture("bpPositions", this->state.particles.current());
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.texture("bpTriangles", this->shapeTables.triangles.get());
  pass.setInt("bpTrianglesWidth", this->shapeTables.trianglesWidth);
  pass.runPerParticle({ this->state.normals.get() });
}

void GpuSystem::updateFieldSamples(double t)
{
  const VectorField* field = this->fieldCache.field();
  if (!field)
  {
    return;
  }
  GpuPass pass = this->begin(this->passes.programs.samples);
  pass.texture("bpState", this->state.particles.current());
  pass.setFloat("bpSampleWeight", field->timeWeight(t));
  pass.runPerParticle({ this->state.samples.get() });
}

GpuPass GpuSystem::begin(GLuint program) const
{
  SharedPassInputs shared;
  shared.layout = &this->layout;
  shared.parameters = &this->parameters;
  shared.linked = this->state.linked;
  shared.latticeSites = this->state.latticeSites.get();
  shared.bindField = [this](GpuPass& pass)
  {
    if (this->fieldCache.field())
    {
      this->fieldCache.applyTo(pass);
    }
  };
  return this->passes.begin(program, shared);
}

void GpuSystem::bindCurrent(GpuPass& pass, std::initializer_list<ElementTexture> rows) const
{
  for (ElementTexture row : rows)
  {
    pass.texture(ElementTextureSamplers[int(row)], this->state.current(row));
  }
}

} // namespace bp
