// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuStepper.h
 * @brief The GPU engine behind the stepper verbs (Core/Stepping/Stepper.h).
 *
 * What a renderer holds in its own GL context: it replays the calls the
 * tracer recorded into a bp::WorkQueue (EngineCall::applyTo) onto this
 * stepper, then draws from engine().drawInputs(). Every verb needs the GL
 * context current, as GpuEngine's do. The particles live in the engine's
 * textures, so particles() is null; engine() reads them back where needed.
 */
#ifndef BoundParticles_GpuStepper_h
#define BoundParticles_GpuStepper_h

#include "GpuEngine.h"
#include "Stepper.h"

#include <string>

namespace bp
{

class GpuStepper : public Stepper
{
public:
  /// GpuEngine::configure() with Parameters::trackPoses on.
  std::string configure(const ElementTemplate& shape, const Parameters& parameters) override;
  std::string setField(const VectorField& field) override;
  void initialize(double startTime) override;
  void step(double t, double h) override;
  /// GpuEngine::saveState(): a copy in textures.
  void save() override;
  /// GpuEngine::restoreState().
  void restore() override;
  /// GpuEngine::setEmitter().
  void setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max) override;
  /// GpuEngine::keepCheckpoint(): copies on the GPU.
  bool keepsCheckpoints() const override { return true; }
  void keepCheckpoint(long long steps, double time) override;
  void resumeCheckpoint(long long steps) override;
  void dropCheckpoints() override;
  double checkpointBytes() const override { return this->Gpu.checkpointBytes(); }
  /// GpuEngine::readState() of the committed boundary (save()'s copy while
  /// cursor.showsPartialStep, as CpuStepper): a read-back. The stepper keeps
  /// cursor.showsPartialStep itself, as a display's replay of a queue's
  /// calls has it: save() sets it (the tracer saves only to show a short
  /// step), restore(), initialize(), loadState(), configure() and a
  /// checkpoint's resume clear it.
  bool committedState(EngineState& state) override;
  /// The same, with why not.
  std::string readCommittedState(EngineState& state) const;
  /// GpuEngine::loadState(): an upload.
  std::string loadState(const EngineState& state) override;
  /// Null: the state lives in GPU textures (engine().read() fetches it).
  const Engine* particles() override { return nullptr; }

  GpuEngine& engine() { return this->Gpu; }
  const GpuEngine& engine() const { return this->Gpu; }

private:
  GpuEngine Gpu;
};

} // namespace bp

#endif
