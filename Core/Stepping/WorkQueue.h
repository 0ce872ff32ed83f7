// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file WorkQueue.h
 * @brief The GPU engine's work as the filter records it and a renderer runs it.
 *
 * The third kind of Stepper (Stepper.h): with the GPU engine the tracer
 * makes every decision it makes for the CPU engine (when to replay, which
 * field time steps, which steps along the schedule, the short last step
 * shown and taken back) but its stepper records the calls (EngineCall.h)
 * here instead of making them. The renderer that owns the GL context drains
 * the queue before it draws and applies each call to its own stepper
 * (Gpu/GpuStepper.h). The queue holds the field time steps its pending calls
 * need (shared, not copied) and nothing else; `cursor` is where the engine
 * stands once every recorded call has run, which is what the tracer's next
 * decision starts from.
 *
 * Two sides, each with its own handle:
 *  - the tracer holds the queue (bpvtk::FindWorkQueue): it records, sets
 *    what to draw, and reads the renderer's report `const`;
 *  - the display that made the queue holds it `const` plus its
 *    RendererReportWriter, made with the queue and never copied: the one
 *    path that writes the report, takes the calls, records where a run
 *    stopped or that the state was lost, and lends the queue the display's
 *    read-back of its engine's state (setStateReader), which the tracer's
 *    State output calls (readState). The tracer settles its own cursor
 *    from that record at the start of its next decision (settleCursor()); the
 *    renderer never writes the cursor.
 *
 * A queue has an id, a plain integer a renderer can put into a pipeline
 * request; the filter's module keeps the one registry of ids (a static here
 * would be copied into every shared library that links Core).
 */
#ifndef BoundParticles_WorkQueue_h
#define BoundParticles_WorkQueue_h

#include "DrawSettings.h"
#include "ElementTemplate.h"
#include "Engine.h"
#include "EngineCall.h"
#include "RendererReport.h"
#include "Stepper.h"
#include "VectorField.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bp
{

/**
 * The requests: the engine calls the tracer records, what to draw and the
 * next time step, written by the tracer; the renderer drains the calls
 * (RendererReportWriter::take). The renderer's side comes back in report().
 */
class WorkQueue : public Stepper
{
public:
  explicit WorkQueue(int id)
    : Id(id)
  {
  }
  WorkQueue(const WorkQueue&) = delete;
  WorkQueue& operator=(const WorkQueue&) = delete;

  int id() const { return this->Id; }

  // Recording (the tracer). configure() makes the CPU engine's checks, so a
  // system no engine could run is refused before it is recorded.
  std::string configure(const ElementTemplate& shape, const Parameters& parameters) override;
  std::string setField(const VectorField& field) override;
  void initialize(double startTime) override;
  void step(double t, double h) override;
  void save() override;
  void restore() override;
  void setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max) override;
  /// Checks that the state loads into the engine last configured, the GPU
  /// engine's limits included (bp::gpuStateRefusal), so that a refusal is the
  /// tracer's to say, then records the call (EngineCall::Kind::LoadState)
  /// that the renderer's GPU engine uploads.
  std::string loadState(const EngineState& state) override;

  /// @name The GPU engine's state, read back by the display that runs it
  ///@{
  /**
   * The renderer's engine state at its committed step boundary (the copy of
   * save() while a short step is shown), read back in the renderer's GL
   * context once every pending call has run there: the display's state
   * reader (RendererReportWriter::setStateReader). Empty on success,
   * otherwise why not (no display reads it back, the display has not drawn,
   * its run was stopped or failed). On success the engine stands where the
   * cursor says: the state is the trace at cursor.committed, cursor.steps.
   */
  std::string readState(EngineState& state);
  /// readState() succeeded (false where no display reads it back).
  bool committedState(EngineState& state) override { return this->readState(state).empty(); }
  /// The template of the system last configured (null before any).
  const ElementTemplate* configuredShape() const { return this->ConfiguredShape.get(); }
  ///@}
  bool readsAhead() const override { return this->Report.streamTimeSteps; }
  void offerUpcoming(const FieldSlice& slice) override { this->Upcoming = slice; }

  /// @name Checkpoints, recorded as calls (EngineCall::Kind::KeepCheckpoint,
  /// ResumeCheckpoint, DropCheckpoints) that the renderer's GPU engine runs
  /// on copies of its state textures, on the GPU (GpuEngine::keepCheckpoint).
  /// checkpoints() is what the GPU holds once every recorded call has run.
  ///@{
  bool keepsCheckpoints() const override { return true; }
  void keepCheckpoint(long long steps, double time) override;
  /// Records the call and moves the cursor to the checkpoint, as the
  /// renderer's engine will stand once it runs.
  void resumeCheckpoint(long long steps) override;
  void dropCheckpoints() override;
  /// The larger of the GPU engine's checkpoint (its textures, padding
  /// included: bp::gpuCheckpointBytes) and the CPU engine's state
  /// (Engine::recordWords), for the system last configured.
  double checkpointBytes() const override { return this->CheckpointBytes; }
  ///@}

  /// Drops every pending call (a replay makes them moot).
  void clear() { this->Pending.clear(); }
  /// Whether calls wait for the renderer.
  bool hasPending() const { return !this->Pending.empty(); }

  /**
   * The tracer, at the start of its decision: takes into `cursor` what the
   * display recorded since the last time (RendererReportWriter::stoppedAt,
   * stateLost). After a stop the engine stands on that step boundary,
   * showing no short step, the steps from the start that the stop reported,
   * holding the checkpoints the renderer's engine holds, and the next update
   * continues from there; after a loss (or a stop that dropped calls
   * recorded meanwhile) the cursor holds no trace and the queue no
   * checkpoints (they went with the GPU state), and the next update replays.
   */
  void settleCursor();

  /// All the calls recorded since the last take, in order, leaving none.
  /// The display drains through its writer (RendererReportWriter::take);
  /// tests that play the renderer drain here.
  std::vector<EngineCall> take();

  /// What the renderer reported, as the tracer reads it.
  const RendererReport& report() const { return this->Report; }

  /// What to draw, set by the tracer at every update it records for the display.
  const DrawSettings& draw() const { return this->Draw; }
  void setDraw(const DrawSettings& draw) { this->Draw = draw; }

  /// The tracer's Engine is Automatic and its last update for this display
  /// traced on the CPU engine: the renderer is a software one, or was not
  /// known yet. The display says why once it knows its renderer.
  bool automaticOnCpu() const { return this->AutomaticOnCpu; }
  void setAutomaticOnCpu(bool onCpu) { this->AutomaticOnCpu = onCpu; }

  /// The time step the next update forward will need, once the filter has it
  /// (empty otherwise; set through offerUpcoming()).
  const FieldSlice& upcoming() const { return this->Upcoming; }

private:
  friend class RendererReportWriter;
  int Id = 0;
  std::vector<EngineCall> Pending;
  RendererReport Report;
  DrawSettings Draw;
  bool AutomaticOnCpu = false;
  FieldSlice Upcoming;
  double CheckpointBytes = 0.0;
  /// The system last configured, as the GPU engine runs it (trackPoses on):
  /// what loadState() checks a state against.
  Parameters Configured;
  std::vector<StateArray> ConfiguredLayout;
  std::shared_ptr<const ElementTemplate> ConfiguredShape;
  /// The display's read-back (RendererReportWriter::setStateReader).
  std::function<std::string(EngineState&)> StateReader;
  /// The engineState counts this queue's cursor has taken in (settleCursor).
  std::uint64_t SettledStops = 0;
  std::uint64_t SettledLosses = 0;
};

struct DisplayWorkQueue;
/// A new queue with this id, as the display that makes it holds it (the
/// queue read-only, and its report's one writer); `recorder` is the same
/// queue, writable, for the registry that hands it to the tracer.
DisplayWorkQueue newDisplayWorkQueue(int id, std::shared_ptr<WorkQueue>& recorder);

/**
 * The display's hold on the queue it made: the one writer of its report, and
 * the renderer's side of the queue. Made only with a new queue
 * (newDisplayWorkQueue) and never copied, so each queue has one.
 */
class RendererReportWriter
{
public:
  RendererReportWriter(const RendererReportWriter&) = delete;
  RendererReportWriter& operator=(const RendererReportWriter&) = delete;
  RendererReportWriter(RendererReportWriter&&) = default;
  RendererReportWriter& operator=(RendererReportWriter&&) = default;

  /// The report, to write (and to read back).
  RendererReport& report() { return this->Queue->Report; }
  const RendererReport& report() const { return this->Queue->Report; }

  /// The calls to run, taken from the queue (WorkQueue::take).
  std::vector<EngineCall> take() { return this->Queue->take(); }

  /**
   * The renderer ran the calls take() gave only up to a Step call from
   * `committed` (the user aborted, ReplayProgress.h), `steps` steps from the
   * start (the call's EngineCall::steps), its engine holding the checkpoints
   * `held` (GpuStepper::checkpoints(): those recorded after the stop never
   * ran): the engine stands on that step boundary, and the tracer's next
   * decision continues from there (WorkQueue::settleCursor). Calls
   * recorded meanwhile (an update inside the run) continue from where every
   * taken call would have led: they are dropped here, so no render runs
   * them, and the next update replays.
   */
  void stoppedAt(double committed, long long steps, const CheckpointIndex& held);

  /// The engine state the recorded calls lead to is gone (the renderer
  /// released its GL resources): what is queued continues from it, so it is
  /// dropped, and the tracer's next update replays into this queue.
  void stateLost();

  /**
   * How the tracer reads the renderer's engine state back (WorkQueue::readState):
   * `reader` makes the renderer's GL context current, runs the calls pending
   * (take()) as a render would, and reads the state at the committed step
   * boundary; empty on success, otherwise why not. A null reader (the
   * display going away) leaves none: set it back to null before whatever
   * it calls goes.
   */
  void setStateReader(std::function<std::string(EngineState&)> reader)
  {
    this->Queue->StateReader = std::move(reader);
  }

private:
  friend DisplayWorkQueue newDisplayWorkQueue(int id, std::shared_ptr<WorkQueue>& recorder);
  explicit RendererReportWriter(std::shared_ptr<WorkQueue> queue)
    : Queue(std::move(queue))
  {
  }
  std::shared_ptr<WorkQueue> Queue;
};

/// A queue as the display that made it holds it: read-only, and its
/// report's one writer (newDisplayWorkQueue).
struct DisplayWorkQueue
{
  std::shared_ptr<const WorkQueue> queue;
  RendererReportWriter writer;
};

} // namespace bp

#endif
