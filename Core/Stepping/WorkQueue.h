// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file WorkQueue.h
 * @brief The GPU engine's work as the filter records it and a renderer runs it.
 *
 * The third kind of Stepper (Stepper.h): with the GPU engine the tracer
 * makes every decision it makes for the CPU engine (when to replay, which
 * field time steps, which steps along the schedule, the short last step
 * shown and taken back) but its stepper records the calls here instead of
 * making them. The renderer that owns the GL context drains the queue before
 * it draws and applies each call to its own stepper (Gpu/GpuStepper.h). The
 * queue holds the field time steps its pending calls need (shared, not
 * copied) and nothing else; `cursor` is where the engine stands once every
 * recorded call has run, which is what the tracer's next decision starts
 * from.
 *
 * A queue has an id, a plain integer a renderer can put into a pipeline
 * request; the filter's module keeps the one registry of ids (a static here
 * would be copied into every shared library that links Core).
 */
#ifndef BoundParticles_WorkQueue_h
#define BoundParticles_WorkQueue_h

#include "BoundParticlesChoices.h"
#include "ElementTemplate.h"
#include "Engine.h"
#include "Stepper.h"
#include "VectorField.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bp
{

/// The kind of OpenGL renderer a display draws with.
enum class RendererKind
{
  Unknown,
  Hardware,
  Software
};

/// The kind of renderer a GL_RENDERER string names: Software for Mesa's
/// llvmpipe, softpipe and swrast, and other CPU rasterizers.
RendererKind rendererKind(const std::string& glRenderer);

/// Whether a trace a display asked for runs on the GPU engine: always with
/// Gpu; with Automatic only on a hardware renderer (an unknown one, before
/// the display first drew, gets the CPU engine).
bool usesGpuEngine(EngineChoice choice, RendererKind renderer);

/// What a display says, once, when Engine Automatic traces on the CPU engine
/// because it draws with the software renderer `rendererName`.
std::string automaticOnCpuNote(const std::string& rendererName);

/// One recorded engine call.
struct EngineCall
{
  enum class Kind
  {
    Configure,  ///< shape, parameters
    SetField,   ///< field
    Initialize, ///< place every element
    Step,       ///< t, h
    Save,       ///< keep a copy of the state
    Restore,    ///< go back to the copy
    SetEmitter  ///< parameters.emitterMin, emitterMax
  };
  Kind kind = Kind::Step;
  double t = 0.0, h = 0.0;
  std::shared_ptr<const ElementTemplate> shape;
  Parameters parameters;
  std::shared_ptr<const VectorField> field;

  /// Makes this call on `target`; empty on success, otherwise its error.
  std::string applyTo(Stepper& target) const;
};

/// What a renderer needs to draw the state the queue leads to.
struct DrawSettings
{
  double time = 0.0;                          ///< the simulation time shown
  std::array<double, 3> offset = { 0, 0, 0 }; ///< world position of the grid-local origin
  std::array<double, 6> bounds = { 0, -1, 0, -1, 0, -1 }; ///< the field's world bounds
  int coloringAxis = 2;                                   ///< for Layer and Radius
  std::array<double, 2> radialCenter = { 0, 0 };          ///< grid-local, the other two axes
  std::uint64_t serial = 0; ///< changes with every update of the filter
};

/**
 * What a display tells the tracer about its renderer and its runs: written
 * by the display alone (its representation and its mapper), read by the
 * tracer (WorkQueue::report()).
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
};

/**
 * The requests: the engine calls the tracer records, what to draw and the
 * next time step, written by the tracer; the renderer drains the calls
 * (take(), stoppedAt()). The renderer's side comes back in report().
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
  bool readsAhead() const override { return this->Report.streamTimeSteps; }
  void offerUpcoming(const FieldSlice& slice) override { this->upcoming = slice; }
  /// Drops every pending call (a replay makes them moot).
  void clear() { this->Pending.clear(); }
  /// Whether calls wait for the renderer.
  bool hasPending() const { return !this->Pending.empty(); }

  // Running (the renderer).
  std::vector<EngineCall> take();
  /**
   * The renderer ran the calls take() gave only up to a Step call from
   * `committed` (the user aborted, ReplayProgress.h): the engine stands on
   * that step boundary, showing no short step, and the next update continues
   * from there. Calls recorded meanwhile (an update inside the run) continue
   * from where every taken call would have led: they are dropped and the
   * next update replays.
   */
  void stoppedAt(double committed);

  /// What the renderer reported, as the tracer reads it.
  const RendererReport& report() const { return this->Report; }
  /// The report, for the display that owns this queue: the one writer.
  RendererReport& reportFromDisplay() { return this->Report; }

  DrawSettings draw;

  /// The tracer's Engine is Automatic and its last update for this display
  /// traced on the CPU engine: the renderer is a software one, or was not
  /// known yet. The display says why once it knows its renderer.
  bool automaticOnCpu = false;

  /// The time step the next update forward will need, once the filter has it
  /// (empty otherwise).
  FieldSlice upcoming;

private:
  int Id = 0;
  std::vector<EngineCall> Pending;
  RendererReport Report;
};

} // namespace bp

#endif
