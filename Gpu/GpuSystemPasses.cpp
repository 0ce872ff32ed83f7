// SPDX-License-Identifier: BSD-3-Clause
// Each kernel's inputs, and the step's passes that run a kernel on its own
// (GpuSystem.h). The fused step (GpuSystem.cpp) sets the same inputs.
#include "GpuSystem.h"

#include "Surfaces.h"

namespace bp
{

void GpuSystem::resetInputs(GpuPass& pass, bool initialize, bool releasing, double t)
{
  using E = ElementTexture;
  this->bindCurrent(pass, { E::State, E::Centers, E::Orientations, E::Poses });
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
}

void GpuSystem::advectInputs(GpuPass& pass, bool placeOnly, double t, double h) const
{
  using E = ElementTexture;
  pass.texture("bpState", this->state.particles.current());
  this->bindCurrent(pass, { E::State, E::Centers, E::Orientations });
  pass.texture("bpRest", this->shapeTables.rest.get());
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.setInt("bpPlaceOnly", placeOnly ? 1 : 0);
  // The integrator and heavy particles' slip are the program's own
  // (KernelSpecialisation: BP_INTEGRATOR, BP_INERTIAL).
  pass.setFloat("bpStep", float(h));
  if (const VectorField* field = this->fieldCache.field())
  {
    // The time weights at the integrators' sample times.
    const float weights[3] = { field->timeWeight(t), field->timeWeight(t + 0.5 * h),
      field->timeWeight(t + h) };
    pass.setVec3("bpWeights", weights);
  }
  pass.texture("bpSlipMoves", this->state.slipMoves.get());
  this->surfaceWallInputs(pass);
}

void GpuSystem::slipInputs(GpuPass& pass, double t, double h) const
{
  using E = ElementTexture;
  const Parameters& p = this->parameters;
  pass.texture("bpState", this->state.particles.current());
  this->bindCurrent(pass, { E::State, E::Centers, E::Orientations });
  pass.texture("bpRest", this->shapeTables.rest.get());
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.texture("bpSlips", this->state.slips.get());
  pass.texture("bpSlipsNext", this->state.slipsNext.get());
  const InertiaStep k = inertiaStepOf(p, h);
  pass.setFloat("bpStep", k.h);
  pass.setFloat("bpSlipDecay", k.decay);
  pass.setFloat("bpSlipMemory", k.memory);
  pass.setFloat("bpSlipSettle", k.settle);
  pass.setFloat("bpSlipBuoyancy", k.buoyancy);
  pass.setVec3("bpSlipGravity", k.gravity);
  pass.setInt("bpShareSlip",
    !this->shape.springs.empty() || p.restoration == Restoration::ShapeMatching ||
      this->state.linked);
  const VectorField* field = this->fieldCache.field();
  const float weights[3] = { field ? field->timeWeight(t) : 0.0f, 0.0f, 0.0f };
  pass.setVec3("bpSlipWeights", weights);
  // A particle Stick holds on a Wall of the Surfaces keeps its slip (bpHeld).
  this->surfaceWallInputs(pass);
  // As VectorField::sampleAlong: in double, then float.
  const bool unsteady = field && !field->isSteady();
  pass.setFloat("bpTimeRate",
    unsteady ? float(1.0 / (field->secondSlice().time - field->firstSlice().time)) : 0.0f);
}

void GpuSystem::stepSlips(double t, double h)
{
  GpuPass pass = this->begin(this->passes.programs.slip);
  this->slipInputs(pass, t, h);
  pass.runPerParticle({ this->state.slipsNext.get(), this->state.slipMoves.get() });
}

void GpuSystem::shareSlips(double t, double h, float endWeight)
{
  GpuPass pass = this->begin(this->passes.programs.slipShare);
  this->slipInputs(pass, 0.0, 0.0);
  // The walls' rule on the velocity: where the advect pass left each
  // particle and what the walls did (.w), the flow at the step's end; with
  // Walls of the Surfaces, the Wall met (the positions before's .w) and the
  // advect pass's inputs, to find where the field's sides left a particle
  // that met both (bp_advect.glsl: bpWalledBySides).
  this->advectInputs(pass, false, t, h);
  pass.texture("bpBefore", this->state.before.get());
  pass.texture("bpAdvected", this->state.advected.get());
  pass.setFloat("bpEndWeight", endWeight);
  pass.runPerParticle({ this->state.slips.get() });
}

/// The walls after restoration (Boundary Stick, Slip, Bounce): the restored
/// `positions` kept in the box (Engine::wallAfterRestoration); returns the
/// texture they end in.
GLuint GpuSystem::wallRestored(GLuint positions, float endWeight, int& restorationPass)
{
  GpuPass pass = this->begin(this->passes.programs.wall);
  pass.texture("bpPositions", positions);
  pass.texture("bpAdvected", this->state.advected.get());
  pass.setFloat("bpEndWeight", endWeight);
  this->surfaceWallInputs(pass);
  return this->runRestorationPass(pass, restorationPass);
}

void GpuSystem::jacobiInputs(GpuPass& pass, GLuint positions) const
{
  const Parameters& p = this->parameters;
  pass.texture("bpPositions", positions);
  pass.texture("bpParticleInfo", this->shapeTables.particleInfo.get());
  pass.texture("bpSprings", this->shapeTables.springs.get());
  pass.setInt("bpSpringsWidth", this->shapeTables.springsWidth);
  pass.setInt("bpAveraged", p.restoration == Restoration::AveragedJacobi ? 1 : 0);
  pass.setFloat("bpRelaxation", p.relaxation);
}

void GpuSystem::matchInputs(GpuPass& pass, GLuint positions) const
{
  const GpuTemplate& t = this->shapeTables;
  const Parameters& p = this->parameters;
  pass.texture("bpPositions", positions);
  pass.texture("bpRest", t.rest.get());
  pass.texture("bpParticleInfo", t.particleInfo.get());
  this->bindCurrent(pass, { ElementTexture::Orientations });
  pass.setInt("bpLinearMatching", p.linearShapeMatching ? 1 : 0);
  pass.setFloat("bpLinearBlend", p.linearBlend);
  pass.setVec3("bpRestMomentInverse0", t.restMomentInverse.data());
  pass.setVec3("bpRestMomentInverse1", t.restMomentInverse.data() + 3);
  pass.setVec3("bpRestMomentInverse2", t.restMomentInverse.data() + 6);
  pass.setFloat("bpShapeStiffness", p.shapeStiffness);
  // The fit's own textures, for the move's pass.
  pass.texture("bpMatchCenters", this->state.matchCenters.get());
  pass.texture("bpMatchLinear0", this->state.matchLinear[0].get());
  pass.texture("bpMatchLinear1", this->state.matchLinear[1].get());
}

void GpuSystem::testInputs(
  GpuPass& pass, GLuint positions, bool settleOnly, double h, float endWeight) const
{
  this->bindCurrent(pass, { ElementTexture::State, ElementTexture::Centers });
  pass.texture("bpPositions", positions);
  pass.setInt("bpSettleOnly", settleOnly ? 1 : 0);
  const bool any = this->parameters.resetWhen == ResetWhen::AnyParticleLeaves;
  pass.setInt("bpAnyParticle", any ? 1 : 0);
  pass.setFloat("bpStep", float(h));
  pass.setFloat("bpReleaseMinSpeed", this->parameters.releaseMinSpeed);
  pass.setFloat("bpEndWeight", endWeight);
  // Anchor = Centre: the test also writes each element's move to its anchor.
  pass.setInt("bpAnchored", this->anchored(settleOnly) ? 1 : 0);
  // The Outlets (engine specification 2.10): each element's centre before
  // the step, from the positions before it, crossing any of the triangles.
  pass.setInt("bpOutletCount", settleOnly ? 0 : this->OutletCount);
  pass.texture("bpOutlets", this->Outlets.get());
  pass.texture("bpBefore", this->state.before.get());
  this->surfaceWallInputs(pass);
}

void GpuSystem::surfaceWallInputs(GpuPass& pass) const
{
  // The Walls of the Surfaces (engine specification 2.10): their triangles,
  // and the offset the CPU engine puts a particle off one (surfaceWallOffset
  // of the field's domain, the same float).
  const VectorField* field = this->fieldCache.field();
  pass.setInt("bpWallCount", this->WallCount);
  pass.texture("bpWalls", this->Walls.get());
  pass.setFloat("bpWallOffset", surfaceWallOffset(field ? field->domain() : Domain()));
}

void GpuSystem::finalizeInputs(GpuPass& pass, GLuint restored, bool placed) const
{
  pass.texture("bpRestored", restored);
  pass.texture("bpAdvected", this->state.advected.get());
  pass.texture("bpBefore", this->state.before.get());
  this->bindCurrent(pass, { ElementTexture::State });
  pass.setInt("bpAnchored", this->anchored(placed) ? 1 : 0);
  pass.setInt("bpShiftsPeriodic", this->shiftsPeriodic(placed) ? 1 : 0);
  pass.texture("bpShifts", this->state.anchorShifts.get());
}

void GpuSystem::poseInputs(GpuPass& pass, double h, float endWeight) const
{
  pass.texture("bpPositions", this->state.particles.current());
  this->bindCurrent(pass, { ElementTexture::State, ElementTexture::Poses });
  pass.texture("bpRest", this->shapeTables.rest.get());
  pass.setFloat("bpStep", float(h));
  pass.setFloat("bpEndWeight", endWeight);
}

/// The reset pass: places flagged (or, initialising, all) elements at time t.
void GpuSystem::reset(bool initialize, bool releasing, double t)
{
  using E = ElementTexture;
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.reset);
  this->resetInputs(pass, initialize, releasing, t);
  pass.runPerElement({ s.element(E::State).next(), s.element(E::Centers).next(),
    s.element(E::Orientations).next(), s.element(E::Poses).next() });
  for (E row : { E::State, E::Centers, E::Orientations, E::Poses })
  {
    s.element(row).flip();
  }
}

/// The advect pass: positions before the step (placed anew where reset) and
/// after advection from t by h, or only the placed ones.
void GpuSystem::advect(bool placeOnly, double t, double h)
{
  GpuPass pass = this->begin(this->passes.programs.advect);
  this->advectInputs(pass, placeOnly, t, h);
  pass.runPerParticle({ this->state.advected.get(), this->state.before.get() });
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
  TexturePair& orientations = s.element(ElementTexture::Orientations);
  GpuPass fit = this->begin(this->passes.programs.match);
  this->matchInputs(fit, positions);
  fit.runPerElement(
    { s.matchCenters.get(), orientations.next(), s.matchLinear[0].get(), s.matchLinear[1].get() });
  orientations.flip();
  GpuPass move = this->begin(this->passes.programs.matchApply);
  this->matchInputs(move, positions);
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
  GpuPass pass = this->begin(this->passes.programs.restore);
  this->jacobiInputs(pass, positions);
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
  TexturePair& elements = this->state.element(ElementTexture::State);
  GpuPass pass = this->begin(this->passes.programs.test);
  this->testInputs(pass, positions, settleOnly, h, endWeight);
  if (this->anchored(settleOnly) || this->shiftsPeriodic(settleOnly))
  {
    pass.runPerElement({ elements.next(), this->state.anchorShifts.get() });
  }
  else
  {
    pass.runPerElement({ elements.next() });
  }
  elements.flip();
}

/// The new particle state from the restored positions (anchored elements
/// moved back to their anchors, unless `placed`: after initialisation).
void GpuSystem::finalize(GLuint restored, bool placed)
{
  GpuPass pass = this->begin(this->passes.programs.finalize);
  this->finalizeInputs(pass, restored, placed);
  pass.runPerParticle({ this->state.particles.next() });
  this->state.particles.flip();
}

/// The pose pass: every element's pose fitted to its particles after the
/// step and its spin over the step (Engine::updatePose).
void GpuSystem::updatePoses(double h, float endWeight)
{
  using E = ElementTexture;
  GpuState& s = this->state;
  GpuPass pass = this->begin(this->passes.programs.pose);
  this->poseInputs(pass, h, endWeight);
  pass.runPerElement({ s.element(E::Poses).next(), s.element(E::Spins).next() });
  s.element(E::Poses).flip();
  s.element(E::Spins).flip();
}

} // namespace bp
