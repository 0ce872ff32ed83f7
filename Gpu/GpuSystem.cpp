// SPDX-License-Identifier: BSD-3-Clause
#include "GpuSystem.h"

#include "SuperSet.h"

#include <algorithm>
#include <sstream>

namespace bp
{

std::string GpuSystem::make(const ElementTemplate& elementTemplate,
  const Parameters& systemParameters, int textureSizeLimit, bool generatedSprings)
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
  if (!error.empty())
  {
    return error;
  }
  this->shapeTables.upload(this->shape, p.elementSize, generatedSprings);
  error = this->passes.compile(this->shapeTables.springSumCode);
  if (!error.empty())
  {
    return error;
  }
  // The super set's lattice, the same table the CPU engine builds.
  this->state.make(this->layout,
    makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax),
    p.trailLength);
  // Release centres of a seed source (bp_common.glsl: 256 a row); one texel
  // when there is none, since the reset pass binds it.
  std::vector<float> seeds(4 * std::max<std::size_t>(p.seedPoints.size() / 3, 1), 0.0f);
  for (std::size_t k = 0; k < p.seedPoints.size() / 3; ++k)
  {
    std::copy_n(&p.seedPoints[3 * k], 3, &seeds[4 * k]);
  }
  this->SeedPoints = makeListTexture(seeds, 256);
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

void GpuSystem::initialize(double startTime)
{
  // Place every element as generation 0 ...
  this->reset(true, releasesAt(this->parameters, startTime, 0.0), startTime);
  this->advect(true, 0.0, 0.0);
  // ... with no flag set and zero force, as Engine::initialize leaves them.
  const GLuint placed = this->state.advected.get();
  this->test(placed, true, 0.0, 0.0f);
  this->finalize(placed, true);
  // Every spin 0 (the reset pass placed every pose), and no trail yet.
  const float zero[4] = { 0, 0, 0, 0 };
  this->passes.clearTexture(this->state.spins.get(), zero);
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
  // 1. Reset.
  this->reset(false, releasesAt(this->parameters, t, h), t);
  // 2. Advect.
  this->advect(false, t, h);
  // 3. Restore: K iterations of the elements' own restoration, each followed,
  // in a super set, by one pass over the links (Engine::stepLinked).
  GLuint positions = this->state.advected.get();
  int restorationPass = 0;
  for (int k = 0; k < this->parameters.iterations; ++k)
  {
    positions = this->restoreOnce(positions, restorationPass);
  }
  // 5. Reposition test, then the new state.
  const VectorField* field = this->fieldCache.field();
  const float endWeight = field ? field->timeWeight(t + h) : 0.0f;
  this->test(positions, false, h, endWeight);
  this->finalize(positions, false);
  // 6. Poses and spins.
  if (this->parameters.trackPoses)
  {
    this->updatePoses(h, endWeight);
  }
}

void GpuSystem::updateNormals()
{
  GpuPass pass = this->begin(this->passes.programs.normals);
  pass.texture("bpState", this->state.particles.current());
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

GpuPass GpuSystem::begin(const GlProgram& program) const
{
  SharedPassInputs shared;
  shared.layout = &this->layout;
  shared.parameters = &this->parameters;
  shared.linked = this->state.linked;
  shared.latticeSites = this->state.latticeSites.get();
  shared.fieldCache = &this->fieldCache;
  return this->passes.begin(program, shared);
}

/// The reset pass: places flagged (or, initialising, all) elements at time t.
void GpuSystem::reset(bool initialize, bool releasing, double t)
{
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.reset);
  pass.texture("bpElementState", s.elements.current());
  pass.texture("bpCenters", s.centers.current());
  pass.texture("bpOrientations", s.orientations.current());
  pass.texture("bpPoses", s.poses.current());
  pass.setInt("bpInitialize", initialize ? 1 : 0);
  pass.setInt("bpReleasing", releasing ? 1 : 0);
  pass.setVec4("bpFrameQuaternion", this->FrameQuaternion.data());
  pass.setVec3("bpLongAxis", this->LongAxis.data());
  pass.setInt("bpPlaneAxis", this->parameters.planeAxis);
  // Along Flow samples the flow at the release centre at t (Engine::alignToFlow).
  const VectorField* field = this->fieldCache.field();
  pass.setInt("bpAlongFlow", field && this->parameters.orientation == Orientation::AlongFlow);
  pass.setFloat("bpReleaseWeight", field ? field->timeWeight(t) : 0.0f);
  this->fieldCache.applyReleaseMaskTo(pass, this->parameters.releaseMinSpeed);
  pass.setInt("bpSeedCount", int(this->parameters.seedPoints.size() / 3));
  pass.texture("bpSeedPoints", this->SeedPoints.get());
  pass.runPerElement(
    { s.elements.next(), s.centers.next(), s.orientations.next(), s.poses.next() });
  s.elements.flip();
  s.centers.flip();
  s.orientations.flip();
  s.poses.flip();
}

/// The advect pass: positions before the step (placed anew where reset) and
/// after advection from t by h, or only the placed ones.
void GpuSystem::advect(bool placeOnly, double t, double h)
{
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.advect);
  pass.texture("bpState", s.particles.current());
  pass.texture("bpElementState", s.elements.current());
  pass.texture("bpCenters", s.centers.current());
  pass.texture("bpOrientations", s.orientations.current());
  pass.texture("bpRest", this->shapeTables.rest.get());
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.setInt("bpPlaceOnly", placeOnly ? 1 : 0);
  pass.setInt("bpIntegrator", int(this->parameters.integrator));
  pass.setFloat("bpStep", float(h));
  if (const VectorField* field = this->fieldCache.field())
  {
    // The time weights at the integrators' sample times.
    const float weights[3] = { field->timeWeight(t), field->timeWeight(t + 0.5 * h),
      field->timeWeight(t + h) };
    pass.setVec3("bpWeights", weights);
  }
  pass.runPerParticle({ s.advected.get(), s.before.get() });
}

/// One restoration iteration from `positions`; returns the texture it ends in.
GLuint GpuSystem::restoreOnce(GLuint positions, int& restorationPass)
{
  const Restoration restoration = this->parameters.restoration;
  const bool springs = !this->shape.springs.empty();
  if (restoration == Restoration::ShapeMatching)
  {
    positions = this->matchShapes(positions, restorationPass);
  }
  else if (restoration == Restoration::GaussSeidel && springs)
  {
    positions = this->gaussSeidel(positions, restorationPass);
  }
  else if (springs)
  {
    positions = this->jacobi(positions, restorationPass);
  }
  if (this->state.linked)
  {
    positions = this->link(positions, restorationPass);
  }
  return positions;
}

/// Shape matching: a fit per element, then a move per particle.
GLuint GpuSystem::matchShapes(GLuint positions, int& restorationPass)
{
  GpuState& s = this->state;
  const GpuTemplate& t = this->shapeTables;
  const Parameters& p = this->parameters;
  GpuPass fit = this->begin(this->passes.programs.match);
  fit.texture("bpPositions", positions);
  fit.texture("bpRest", t.rest.get());
  fit.texture("bpOrientations", s.orientations.current());
  fit.setInt("bpLinearMatching", p.linearShapeMatching ? 1 : 0);
  fit.setFloat("bpLinearBlend", p.linearBlend);
  fit.setVec3("bpRestMomentInverse0", t.restMomentInverse.data());
  fit.setVec3("bpRestMomentInverse1", t.restMomentInverse.data() + 3);
  fit.setVec3("bpRestMomentInverse2", t.restMomentInverse.data() + 6);
  fit.runPerElement({ s.matchCenters.get(), s.orientations.next(), s.matchLinear[0].get(),
    s.matchLinear[1].get() });
  s.orientations.flip();
  GpuPass move = this->begin(this->passes.programs.matchApply);
  move.texture("bpPositions", positions);
  move.texture("bpRest", t.rest.get());
  move.texture("bpParticleInfo", t.particleInfo.get());
  move.texture("bpMatchCenters", s.matchCenters.get());
  move.texture("bpOrientations", s.orientations.current());
  move.texture("bpMatchLinear0", s.matchLinear[0].get());
  move.texture("bpMatchLinear1", s.matchLinear[1].get());
  move.setInt("bpLinearMatching", p.linearShapeMatching ? 1 : 0);
  move.setFloat("bpShapeStiffness", p.shapeStiffness);
  return this->runRestorationPass(move, restorationPass);
}

/// Gauss-Seidel: a pass per colour of springs.
GLuint GpuSystem::gaussSeidel(GLuint positions, int& restorationPass)
{
  for (int c = 0; c < this->shapeTables.colourCount; ++c)
  {
    GpuPass pass = this->begin(this->passes.programs.gaussSeidel);
    pass.texture("bpPositions", positions);
    pass.texture("bpColouredSprings", this->shapeTables.colouredSprings.get());
    pass.setInt("bpColour", c);
    positions = this->runRestorationPass(pass, restorationPass);
  }
  return positions;
}

/// Jacobi or averaged Jacobi: a gather over each particle's springs.
GLuint GpuSystem::jacobi(GLuint positions, int& restorationPass)
{
  const Parameters& p = this->parameters;
  GpuPass pass = this->begin(this->passes.programs.restore);
  pass.texture("bpPositions", positions);
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.texture("bpSprings", this->shapeTables.springs.get());
  pass.setInt("bpSpringsWidth", this->shapeTables.springsWidth);
  pass.setInt("bpAveraged", p.restoration == Restoration::AveragedJacobi ? 1 : 0);
  pass.setFloat("bpRelaxation", p.relaxation);
  return this->runRestorationPass(pass, restorationPass);
}

/// A super set's links: one pass after each iteration (Engine::stepLinked).
GLuint GpuSystem::link(GLuint positions, int& restorationPass)
{
  GpuPass pass = this->begin(this->passes.programs.link);
  pass.texture("bpPositions", positions);
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.texture("bpLinkNeighbours", this->state.linkNeighbours.get());
  pass.texture("bpLinkRest", this->state.linkRest.get());
  pass.setFloat("bpLinkStiffness", this->parameters.linkStiffness);
  return this->runRestorationPass(pass, restorationPass);
}

/// Runs a restoration pass into the restored texture it returns. A step's
/// restoration passes write the two in turn, so none writes what it reads.
GLuint GpuSystem::runRestorationPass(const GpuPass& pass, int& restorationPass)
{
  const GLuint target = this->state.restored[restorationPass++ % 2].get();
  pass.runPerParticle({ target });
  return target;
}

/// The reposition test on the restored `positions`; settling only clears
/// the placed-now marks after initialisation.
void GpuSystem::test(GLuint positions, bool settleOnly, double h, float endWeight)
{
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.test);
  pass.texture("bpElementState", s.elements.current());
  pass.texture("bpPositions", positions);
  pass.setInt("bpSettleOnly", settleOnly ? 1 : 0);
  if (!settleOnly)
  {
    const bool any = this->parameters.resetWhen == ResetWhen::AnyParticleLeaves;
    pass.setInt("bpAnyParticle", any ? 1 : 0);
    pass.setFloat("bpStep", float(h));
    pass.setFloat("bpReleaseMinSpeed", this->parameters.releaseMinSpeed);
    pass.texture("bpCenters", s.centers.current());
    pass.setFloat("bpEndWeight", endWeight);
  }
  if (this->anchored(settleOnly))
  {
    // Anchor = Centre: the test also writes each element's move to its anchor.
    pass.setInt("bpAnchored", 1);
    pass.runPerElement({ s.elements.next(), s.anchorShifts.get() });
  }
  else
  {
    pass.runPerElement({ s.elements.next() });
  }
  s.elements.flip();
}

/// The new particle state from the restored positions (anchored elements
/// moved back to their anchors, unless `placed`: after initialisation).
void GpuSystem::finalize(GLuint restored, bool placed)
{
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.finalize);
  pass.texture("bpRestored", restored);
  pass.texture("bpAdvected", s.advected.get());
  pass.texture("bpBefore", s.before.get());
  pass.texture("bpElementState", s.elements.current());
  if (this->anchored(placed))
  {
    pass.setInt("bpAnchored", 1);
    pass.texture("bpShifts", s.anchorShifts.get());
  }
  pass.runPerParticle({ s.particles.next() });
  s.particles.flip();
}

/// The pose pass: every element's pose fitted to its particles after the
/// step and its spin over the step (Engine::updatePose).
void GpuSystem::updatePoses(double h, float endWeight)
{
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.pose);
  pass.texture("bpState", s.particles.current());
  pass.texture("bpElementState", s.elements.current());
  pass.texture("bpPoses", s.poses.current());
  pass.texture("bpRest", this->shapeTables.rest.get());
  pass.setFloat("bpStep", float(h));
  pass.setFloat("bpEndWeight", endWeight);
  // No pass reads the spins before the step: they need no pair.
  pass.runPerElement({ s.poses.next(), s.spins.get() });
  s.poses.flip();
}

} // namespace bp
