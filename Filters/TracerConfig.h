// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerConfig.h
 * @brief The tracer's properties as its internals read them: a plain struct
 * the filter fills (vtkBoundParticleTracer::Config()) on every request.
 *
 * The internals never read the filter's members: what they need of the
 * properties is here, so the state flows one way, from the filter into the
 * internals, and the internals can be read without the filter's header.
 */
#ifndef BoundParticles_TracerConfig_h
#define BoundParticles_TracerConfig_h

#include "BoundParticlesChoices.h"
#include "ElementTemplate.h"
#include "OutputArrays.h"
#include "TraceSettings.h"
#include "TracerResample.h"

#include <array>
#include <cstddef>
#include <string>

class vtkBoundParticleSeedType;

namespace bpvtk
{

struct TracerConfig
{
  bp::TraceSettings trace; ///< what the core resolves (bp::resolveSettings)
  bp::EngineChoice engine = bp::EngineChoice::Automatic;
  bp::BuiltinShape shape = bp::BuiltinShape::Strip8; ///< when no template input
  bp::MeshSprings templateSprings = bp::MeshSprings::EdgesAndDiagonals;
  std::array<int, 3> resampleDimensions = { 0, 0, 0 }; ///< 0: chosen (TracerResample.h)
  /// Periodic axes (the Periodic property; Periodic.h): set on the held grid.
  std::array<bool, 3> periodic = { false, false, false };
  int coloringAxis = 2;
  /// The output arrays to compute, by bp::OutputArrayId.
  std::array<bool, std::size_t(bp::OutputArrayId::Count)> wanted{};
  /// The Seed Type's points; null for the emitter box. The filter holds it.
  vtkBoundParticleSeedType* seedType = nullptr;
  bool templateInput = false; ///< a template is connected (input 1)
  bool seedSource = false;    ///< a Seed Source is connected (input 2)
  bool surfaces = false;      ///< Surfaces are connected (input 3)
  /// What every surface cell does, unless surfaceInteractionArray names a
  /// cell array of the Surfaces that says it per cell (empty: none).
  bp::SurfaceInteraction surfaceInteraction = bp::SurfaceInteraction::Gate;
  std::string surfaceInteractionArray;
  VectorsChoice vectors;      ///< the Vectors property
  /// Why the Vectors default took this array for its units (the time line's
  /// check, bpvtk::TracerTimeLine::reasonFor); empty when it did not.
  std::string vectorsUnitsReason;
  /// Release Weights: the input's array to weigh releases by; empty for none.
  std::string releaseWeights;
  /// Its association (vtkDataObject::FIELD_ASSOCIATION_POINTS or _CELLS).
  int releaseWeightsAssociation = 0;
  /// Checkpoint Memory: MiB the trace's checkpoints may take (0: none kept;
  /// -1: half the trace's own size, bp::traceBytes).
  double checkpointMemory = -1.0;
  /// Initial State File: a saved state to go on from (TracerState.h); empty for none.
  std::string initialStateFile;

  bool linking() const { return this->trace.engine.linking != bp::Linking::None; }
  bool wants(bp::OutputArrayId id) const { return this->wanted[std::size_t(id)]; }
};

} // namespace bpvtk

#endif
