// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file QueueReplay.h
 * @brief Runs a work queue's recorded engine calls on the display's GPU
 * engine, and keeps what a failure means for the calls after it.
 *
 * vtkBoundParticleTracer records engine calls (configure, setField,
 * initialize, step, save, restore, load a saved state) into the display's
 * bp::WorkQueue; vtkOpenGLBoundParticleMapper hands each render's calls to
 * this replay, with the render window's context current. Only configure,
 * setField and a state's load can fail (the system or the field does not
 * fit the GPU; the tracer checked the state first): the calls after a
 * failure would continue from nothing, so they are skipped until the next
 * configure starts over. The mapper hears of each configure that succeeded
 * (to make its draw tables) and of each failure (to report it and make the
 * display draw the CPU result).
 */
#ifndef BoundParticles_QueueReplay_h
#define BoundParticles_QueueReplay_h

#include "GpuStepper.h"

#include <functional>
#include <string>
#include <vector>

namespace bp
{
class ReplayProgress;
struct EngineCall;
}

namespace bpvtk
{

class QueueReplay
{
public:
  /// What the replay tells the mapper while it runs.
  struct Listener
  {
    std::function<void(const bp::EngineCall&)> configured; ///< a configure that succeeded
    std::function<void(const std::string&)> failed;        ///< a failure, in words for the user
  };

  bp::GpuEngine& engine() { return this->Stepper.engine(); }
  /// The checkpoints the engine holds (GpuStepper::checkpoints()).
  const bp::CheckpointIndex& checkpoints() const { return this->Stepper.checkpoints(); }

  /**
   * Applies `calls` in order, asking `progress` before each whether to go on
   * (it reports progress and takes an abort request between two steps). A
   * configure clears an earlier failure; a failure marks the replay failed.
   */
  void run(const std::vector<bp::EngineCall>& calls, bp::ReplayProgress& progress,
    const Listener& listener);

  /// The engine's state at its committed step boundary, read back (the
  /// context current): save()'s copy while a short step is shown
  /// (bp::GpuStepper::readCommittedState). Empty on success.
  std::string readState(bp::EngineState& state) const
  {
    return this->ready() ? this->Stepper.readCommittedState(state)
                         : std::string("the display's GPU engine holds no trace");
  }

  /// The engine holds a system and nothing since its configure failed: its state can be drawn.
  bool ready() const { return this->Configured && !this->Failed; }
  /// The engine holds a system (its GL objects need releasing).
  bool configured() const { return this->Configured; }
  /// Inside a Running scope: a render asked for from inside a progress
  /// report must return at once.
  bool replaying() const { return this->Replaying; }

  /// Marks the replay as running for its lifetime: the mapper holds one over
  /// the whole of a render's replay, its last progress report included.
  class Running
  {
  public:
    explicit Running(QueueReplay& replay)
      : Replay(replay)
    {
      replay.Replaying = true;
    }
    ~Running() { this->Replay.Replaying = false; }
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;

  private:
    QueueReplay& Replay;
  };

  /// The engine failed outside a call (an OpenGL error): draw nothing until the next configure.
  void fail() { this->Failed = true; }
  /// The engine's state is gone with its context: it holds no system.
  void forget() { this->Configured = false; }

private:
  bp::GpuStepper Stepper;
  bool Configured = false; // the engine holds a system
  bool Failed = false;     // the queued work failed: draw nothing until the next configure
  bool Replaying = false;  // inside a Running scope
};

} // namespace bpvtk

#endif
