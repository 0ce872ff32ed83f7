// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file EngineCall.h
 * @brief One engine call as a WorkQueue (WorkQueue.h) records it and a
 * renderer runs it on its own stepper.
 */
#ifndef BoundParticles_EngineCall_h
#define BoundParticles_EngineCall_h

#include "ElementTemplate.h"
#include "Engine.h"
#include "Stepper.h"
#include "VectorField.h"

#include <memory>
#include <string>

namespace bp
{

/// One recorded engine call.
struct EngineCall
{
  enum class Kind
  {
    Configure,        ///< shape, parameters
    SetField,         ///< field
    Initialize,       ///< place every element
    Step,             ///< t, h
    Save,             ///< keep a copy of the state
    Restore,          ///< go back to the copy
    SetEmitter,       ///< parameters.emitterMin, emitterMax
    KeepCheckpoint,   ///< steps, t: keep a checkpoint of the state (Stepper::keepCheckpoint)
    ResumeCheckpoint, ///< steps: go back to that checkpoint
    DropCheckpoints,  ///< drop every checkpoint
    LoadState         ///< state: replace the elements by a saved state's (Stepper::loadState)
  };
  Kind kind = Kind::Step;
  double t = 0.0, h = 0.0;
  /// Step: the steps from the start before this one (TraceCursor::steps), so
  /// a run stopped before it knows where the engine stands; KeepCheckpoint,
  /// ResumeCheckpoint: the checkpoint's step count.
  long long steps = 0;
  std::shared_ptr<const ElementTemplate> shape;
  Parameters parameters;
  std::shared_ptr<const VectorField> field;
  std::shared_ptr<const EngineState> state;

  /// Makes this call on `target`; empty on success, otherwise its error.
  std::string applyTo(Stepper& target) const;
};

} // namespace bp

#endif
