// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file RendererReport.h
 * @brief What a display tells the tracer about its renderer and its runs.
 *
 * Written by the display alone, through the RendererReportWriter it got with
 * its queue (WorkQueue.h); read by the tracer (WorkQueue::report()).
 */
#ifndef BoundParticles_RendererReport_h
#define BoundParticles_RendererReport_h

#include "Checkpoints.h"
#include "RendererKind.h"

#include <cstdint>
#include <string>

namespace bp
{

/**
 * What the renderer did to the engine state its queue's calls lead to, which
 * the tracer's cursor (Stepper::cursor) must follow: the display records it
 * (RendererReportWriter::stoppedAt, stateLost) and the tracer takes it into
 * its cursor at the start of its next decision (WorkQueue::settleCursor).
 * Counts rather than flags, so that the tracer reads them without writing.
 */
class EngineStateNews
{
public:
  /// How many runs stopped short of the calls they were given (the user aborted).
  std::uint64_t stops() const { return this->Stops; }
  /// The step boundary the engine stood on after the last stop.
  double stoppedAt() const { return this->StoppedAt; }
  /// The steps from the start to stoppedAt() (TraceCursor::steps).
  long long stoppedSteps() const { return this->StoppedSteps; }
  /// The checkpoints the renderer's engine held after the last stop.
  const CheckpointIndex& heldAtStop() const { return this->HeldAtStop; }
  /// How many times the state the recorded calls lead to was lost (released
  /// with the GL context, or calls dropped): the tracer replays.
  std::uint64_t losses() const { return this->Losses; }

private:
  friend class RendererReportWriter;
  std::uint64_t Stops = 0;
  double StoppedAt = 0.0;
  long long StoppedSteps = 0;
  CheckpointIndex HeldAtStop;
  std::uint64_t Losses = 0;
};

/**
 * What a display tells the tracer about its renderer and its runs: written
 * by the display alone (RendererReportWriter), read by the tracer
 * (WorkQueue::report()).
 */
struct RendererReport
{
  /// The largest texture the renderer's GPU takes (0: not known yet), so the
  /// filter can refuse a system before recording it.
  int maxTextureSize = 0;

  /// What draws: Unknown until the renderer first ran; Software for a CPU
  /// rasterizer (llvmpipe, softpipe, swrast), on which the GPU engine is
  /// slower than the CPU engine.
  RendererKind renderer = RendererKind::Unknown;
  /// The renderer's GL_RENDERER string, for messages.
  std::string rendererName;

  /// The engine's rate on this renderer as the last long run measured it
  /// (particle-steps per second; 0 until one was measured), so the filter can
  /// say before recording a long replay how long the view will wait.
  double particleStepsPerSecond = 0.0;

  /// The renderer's last failure, if any (empty when the engine ran).
  std::string failure;

  /// Whether the filter reads the next field time step ahead of need and the
  /// renderer uploads it a slab of z layers per frame (the display's choice);
  /// otherwise a time step is uploaded whole when a step first needs it.
  bool streamTimeSteps = true;

  /// Where the renderer stopped or lost the engine state (recorded through
  /// the writer's stoppedAt() and stateLost() only).
  EngineStateNews engineState;
};

} // namespace bp

#endif
