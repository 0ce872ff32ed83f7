// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ReplayProgress.h
 * @brief Progress and abort while a renderer runs the calls of a WorkQueue.
 *
 * With the GPU engine the tracer records the engine's work and the renderer
 * runs it inside a render (WorkQueue.h). A replay from the start of a long
 * trace is thousands of calls there and can take many seconds, so the
 * renderer tells its owner how far it is and asks whether to stop:
 *  - the progress is the share of the calls run, from 0 to 1, never going
 *    back;
 *  - a report is made at most every `interval` seconds, the first only once
 *    the run has lasted that long: the few calls of a Play frame report
 *    nothing, so nothing else runs inside such a render;
 *  - before each report the work issued so far is finished (`settle`), so
 *    that a GPU which queues commands does not report work it has not done,
 *    and the first report of a stop comes when the work stops; after it the
 *    renderer's GL context is made current again (`resume`), since whatever
 *    listens to the progress may have drawn in another window meanwhile;
 *  - whether to stop is asked after each report, and a run stops only
 *    before a Step call. The engine then stands on the step boundary that
 *    call starts from, a time the tracer's schedule lands on, so that the
 *    next update continues from there (RendererReportWriter::stoppedAt,
 *    WorkQueue::settleCursor) to the bits of a run that never stopped.
 */
#ifndef BoundParticles_ReplayProgress_h
#define BoundParticles_ReplayProgress_h

#include "EngineCall.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace bp
{
class WorkQueue;

class ReplayProgress
{
public:
  /// What the renderer does around a report; any may be empty.
  struct Hooks
  {
    std::function<void()> settle;             ///< finish the GL work issued so far
    std::function<void(double share)> report; ///< the share of the calls run
    std::function<bool()> stop;               ///< whether the user asked to stop
    std::function<void()> resume;             ///< make the GL context current again
    std::function<double()> clock;            ///< seconds (a steady clock when empty)
  };

  /// `calls` must outlive this object.
  ReplayProgress(const std::vector<EngineCall>& calls, Hooks hooks, double interval = 0.1);

  /// Before running call `k` (in order, from 0): false when the run stops
  /// there. Reports and asks only before a Step call, when a report is due.
  bool beforeCall(std::size_t k);

  /// After the run: a last report of 1 when any report was made and the run
  /// did not stop, so that a progress bar shown for it completes.
  void finish();

  bool stopped() const { return this->Stopped; }
  /// After a stop: the time the engine stands at, the start time of the Step
  /// call the run stopped before.
  double stoppedAt() const { return this->StoppedAt; }
  /// After a stop: the steps from the start to stoppedAt() (the Step call's EngineCall::steps).
  long long stoppedSteps() const { return this->StoppedSteps; }
  /// After a stop: the index of the call the run stopped before.
  std::size_t stoppedBefore() const { return this->StoppedBefore; }
  /// How many reports were made.
  std::size_t reports() const { return this->Reports; }

private:
  double now() const;
  /// settle, report, stop, resume; whether to stop.
  bool reportShare(double share, bool askToStop);

  const std::vector<EngineCall>& Calls;
  Hooks H;
  double Interval;
  double LastReport; ///< when the last report ended, or the run started
  std::size_t Reports = 0;
  bool Stopped = false;
  double StoppedAt = 0.0;
  std::size_t StoppedBefore = 0;
  long long StoppedSteps = 0;
};

/// The engine's rates assumed where the renderer has measured none yet
/// (RendererReport::particleStepsPerSecond): what llvmpipe reaches on a few cores,
/// and the low end of GPUs (an H200 runs hundreds of times faster).
constexpr double AssumedSoftwareRate = 2.0e7;
constexpr double AssumedHardwareRate = 1.0e9;
/// A replay the view waits longer for is said before it is recorded.
constexpr double LongReplaySeconds = 5.0;

/**
 * What to tell the user before a GPU run of `steps` steps of `particles`
 * particles from t = `from` to `to`, on `queue`'s renderer at its measured
 * rate (or the assumed one for its kind): a note that the view will wait
 * about that long, and what shortens the wait, when that is longer than
 * LongReplaySeconds; empty otherwise.
 */
std::string longReplayNote(
  double steps, double particles, double from, double to, const WorkQueue& queue);

} // namespace bp

#endif
