// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuSystem.h
 * @brief A system of bound particles on the GPU, and the passes of its step.
 *
 * What GpuEngine::configure() makes: the template's tables, the passes
 * for the path the context allows (GpuPath.h) and the parameters'
 * integrator, poses and inertia (KernelSpecialisation, GpuPasses.h), taken
 * from the engine's GpuProgramCache, and the state textures, with the
 * field's resident time steps. A step runs the kernels in
 * the order of docs/engine-specification.md, as the CPU engine
 * (Core/Engine/Engine.h) runs its stages: the trail's record (a copy, when the step
 * starts on the trail's interval), reset, advect, K restoration iterations
 * (each followed, in a super set, by a pass over the links), the reposition
 * test, finalize, and with Parameters::trackPoses the pose. On the compute
 * path a system whose elements fit a workgroup runs them all in one
 * dispatch, the fused step; otherwise each kernel is a pass of its own.
 * Nothing in a step waits for the GPU or reads from it.
 *
 * Needs the GL context current. Assigning an empty system over one deletes
 * every GL object it holds (GlObjects.h); its programs are the cache's, which
 * GpuEngine::release() clears after.
 */
#ifndef BoundParticles_GpuSystem_h
#define BoundParticles_GpuSystem_h

#include "ElementTemplate.h"
#include "Engine.h"
#include "GpuFieldCache.h"
#include "GpuPasses.h"
#include "GpuState.h"
#include "GpuTemplate.h"
#include "ParticleLayout.h"

#include <array>
#include <initializer_list>
#include <string>

namespace bp
{

class GpuSystem
{
public:
  /// Makes the system for a template and parameters the CPU engine accepts
  /// (Engine::validate), its textures at most `textureSizeLimit` texels wide,
  /// with the Jacobi pass's springs as code if `generatedSprings`, its step
  /// fused on the compute path as `fusedSteps` says, its programs taken from
  /// `programs` (compiled there for the parameters' KernelSpecialisation
  /// where it has none yet). Empty on success, otherwise why the GPU cannot
  /// run it (the system is then partly made: assign an empty one over it).
  std::string make(const ElementTemplate& elementTemplate, const Parameters& systemParameters,
    int textureSizeLimit, bool generatedSprings, FusedSteps fusedSteps, GpuProgramCache& programs);

  /// Places every element (generation 0), as Engine::initialize leaves them.
  void initialize(double startTime);
  /// One step of size h from time t, on the field last set.
  void step(double t, double h);
  /// Recomputes the normals texture from the positions.
  void updateNormals();
  /// Samples the field at every particle at time t into the samples texture.
  void updateFieldSamples(double t);

  ElementTemplate shape;
  Parameters parameters;
  GpuLayout layout;
  GpuPasses passes;
  GpuTemplate shapeTables;
  GpuFieldCache fieldCache;
  GpuState state;

private:
  GpuPass begin(GLuint program) const;
  std::string checkTextureSize(const ParticleLayout& wanted, int textureSizeLimit) const;
  /// The fused step this system can run on the compute path (FusedStep::of).
  FusedStep fusedStep() const;

  /// @name The passes of a step, each a kernel's pass of its own
  ///@{
  /// `releasing`: the step overlaps the release window (releasesAt).
  void reset(bool initialize, bool releasing, double t);
  void advect(bool placeOnly, double t, double h);
  /// Heavy particles: the slip pass (new slips and their displacements),
  /// and after the test the share pass (a restored element's mean slip).
  void stepSlips(double t, double h);
  void shareSlips(double t, double h, float endWeight);
  GLuint wallRestored(GLuint positions, float endWeight, int& restorationPass);
  GLuint restoreOnce(GLuint positions, int& restorationPass);
  GLuint matchShapes(GLuint positions, int& restorationPass);
  GLuint gaussSeidel(GLuint positions, int& restorationPass);
  GLuint jacobi(GLuint positions, int& restorationPass);
  GLuint link(GLuint positions, int& restorationPass);
  GLuint runRestorationPass(const GpuPass& pass, int& restorationPass);
  /// `endWeight`: the second time step's weight at the step's end.
  void test(GLuint positions, bool settleOnly, double h, float endWeight);
  void finalize(GLuint restored, bool placed);
  /// `endWeight`: as test()'s, for the curl at the centres.
  void updatePoses(double h, float endWeight);
  ///@}
  /// The compute path's fused step: the same kernels in one dispatch.
  void runFusedStep(double t, double h, float endWeight);

  /// @name Each kernel's inputs, for its pass or the fused step
  ///@{
  void resetInputs(GpuPass& pass, bool initialize, bool releasing, double t);
  void advectInputs(GpuPass& pass, bool placeOnly, double t, double h) const;
  void slipInputs(GpuPass& pass, double t, double h) const;
  void jacobiInputs(GpuPass& pass, GLuint positions) const;
  void matchInputs(GpuPass& pass, GLuint positions) const;
  void testInputs(
    GpuPass& pass, GLuint positions, bool settleOnly, double h, float endWeight) const;
  void finalizeInputs(GpuPass& pass, GLuint restored, bool placed) const;
  void poseInputs(GpuPass& pass, double h, float endWeight) const;
  /// bpWallCount, bpWalls and bpWallOffset (the Walls of the Surfaces).
  void surfaceWallInputs(GpuPass& pass) const;
  ///@}
  /// Binds the current textures of the per-element state's `rows` to their samplers.
  void bindCurrent(GpuPass& pass, std::initializer_list<ElementTexture> rows) const;

  /// Whether a step (not the placing at initialisation) anchors elements.
  bool anchored(bool placing) const
  {
    return !placing && this->parameters.anchor == Anchor::Centre;
  }

  /// Whether a step (not the placing) moves elements across a periodic side:
  /// the test pass writes each element's shift, the finalize pass applies it.
  bool shiftsPeriodic(bool placing) const { return !placing && this->fieldCache.periodic(); }

  /// parameters.frame as a quaternion, for the reset pass.
  std::array<float, 4> FrameQuaternion = { 0, 0, 0, 1 };
  std::array<float, 3> LongAxis = { 1, 0, 0 }; ///< longAxis() of the template
  /// parameters.seedPoints, SeedPointsPerRow texels a row (one texel when there are none).
  GlTexture SeedPoints;
  /// The Surfaces' Outlet triangles (SurfaceSet::outletCorners), 3 texels
  /// each, OutletsPerRow triangles a row (one texel when there are none),
  /// and how many there are (the test kernel's bpOutletCount).
  GlTexture Outlets;
  int OutletCount = 0;
  /// The Surfaces' Wall triangles (SurfaceSet::wallCorners), laid out as
  /// the Outlets, and how many there are (bpWallCount).
  GlTexture Walls;
  int WallCount = 0;
};

} // namespace bp

#endif
