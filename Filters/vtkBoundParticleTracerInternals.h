// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkBoundParticleTracerInternals.h
 * @brief What a vtkBoundParticleTracer keeps between pipeline passes, and
 * the steps of one update.
 *
 * An update runs over one or more pipeline passes: each pass brings one field
 * time step from upstream (CONTINUE_EXECUTING asks for the next). Its steps:
 *  1. begin(): take the decision RequestUpdateExtent made (bp::TracePlan);
 *     take back a short step shown last time;
 *  2. takeTimeStep(): read the time step this pass brought, if the work needs it;
 *  3. replay(): resolve the settings and configure the stepper from the start;
 *  4. stepToTarget(): step one data interval at a time up to the target;
 *  5. readAhead(): for a display that wants it, the next time step ahead of need;
 *  6. show(): finish with a short step shown, and build the output.
 * Steps 3 to 5 may end the pass asking for another time step.
 *
 * The filter fills a bpvtk::TracerConfig from its properties for each call;
 * the internals read nothing else of it, and it changes their state only
 * through their methods. The members are defined by role:
 * vtkBoundParticleTracerInternals.cxx (the update's bookkeeping, stepping and
 * the output), TracerTimeStep.cxx (reading a time step), TracerReplay.cxx
 * (resolving the settings and configuring a new trace) and TracerSeeds.cxx
 * (the release points).
 */
#ifndef vtkBoundParticleTracerInternals_h
#define vtkBoundParticleTracerInternals_h

#include "Engine.h"
#include "FieldCache.h"
#include "OutputArrays.h"
#include "StreamTimeLine.h"
#include "TracePlan.h"
#include "TraceSettings.h"
#include "TracerConfig.h"
#include "TracerInteractions.h"
#include "TracerOutput.h"
#include "TracerParallel.h"
#include "TracerResample.h"
#include "TracerSaidOnce.h"
#include "TracerState.h"
#include "TracerSteppers.h"

#include "vtkAlgorithm.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h"
#include "vtkType.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

class vtkDataArray;
class vtkDataObject;
class vtkImageData;
class vtkInformation;
class vtkInformationVector;

namespace bpvtk
{
/// How a step of an update ended.
struct TracerPass
{
  enum Kind
  {
    Done,     ///< go on to the next step
    NeedStep, ///< end this pass asking upstream for time step `index`
    Failed,   ///< stop with `message` as the error
    Aborted,  ///< the user aborted: stop quietly
    Skipped   ///< in situ, a step not taken: `message` as the error, the trace kept
  };
  Kind kind = Done;
  int index = -1;
  std::string message;

  static TracerPass need(int index) { return { NeedStep, index, std::string() }; }
  static TracerPass fail(const std::string& message) { return { Failed, -1, message }; }
};

/// The release points of a new trace: a Seed Source's or a Seed Type's.
struct TracerSeeds
{
  std::vector<double> xyz; ///< world coordinates, 3 doubles a point
  /// How many points the seeds have (a Seed Type's xyz stops at bp::MaxSeedPoints).
  std::size_t total = 0;
  std::string name = "Seed Source"; ///< what messages call them
  /// What to do when elements crowd on too few points.
  std::string advice = "Give the seeds more points (e.g. a Line's Resolution), or fewer elements.";
};

/// The input a pass brought on port 0, as the filter found it: the data
/// object, and the Vectors property's array in it when it is a dataset.
struct TracerInputStep
{
  vtkDataObject* data = nullptr;
  vtkDataArray* vectors = nullptr;
  int association = 0; ///< of `vectors`: vtkDataObject::FIELD_ASSOCIATION_POINTS or _CELLS
  /// ParaView made the point Vectors of a cell array (bpvtk::cellVectorsMadePoints): what to say.
  std::string vectorsFromCells;
};
/// The field's time steps the tracer holds (TracerTimeStep.cxx), the grid
/// they share, and which input time step upstream was asked for and holds.
struct HeldSteps
{
  bp::FieldCache cache;
  /// Any input but an image or a rectilinear grid, on a uniform grid; its
  /// located cells and weights are kept while the mesh stays the same.
  bpvtk::FieldResampler resampler;
  bool resampled = false; ///< the field came through the resampler
  // The field, in grid-local coordinates (floats keep their precision far
  // from the world origin), and where its local origin lies in the world.
  bp::GridGeometry grid;
  std::array<double, 3> offset = { 0, 0, 0 };
  int requestIndex = 0;        ///< the input time step this pass asked for
  int lastRequested = -1;      ///< the input time step upstream holds
  bool readThisUpdate = false; ///< a time step came from upstream in this update
};

/// The update in progress over its passes, and what the last update did.
struct UpdatePass
{
  bp::TracePlan::Update decision; ///< made in RequestUpdateExtent
  bool continuing = false;        ///< a later pass of the same update
  int intervalAtStart = -1;       ///< the data interval shown before it (-1: a replay)
  double progressFrom = 0.0;      ///< where the update's stepping starts
  double progressAt = 0.0;        ///< where it stands
  vtkIdType stepsInLastUpdate = 0;
  bool lastUpdateReplayed = false;
  bool forState = false; ///< an update for the State output (its steps are not reported)
  /// A State update whose stepper, the GPU display's queue, stands on the
  /// boundary of the time shown: read back as it is, nothing recorded.
  bool readsShownState = false;
  /// An update for the Interactions output alone whose CPU engine already
  /// stands at the time asked, as shown (decideInteractionsOnly): its events
  /// are filled, nothing stepped, the other outputs left as they are.
  bool interactionsOnly = false;
};

/// In situ: the times given since the trace started (TracerInSitu.cxx),
/// the filter's MTime they were given under, and the grid the last step
/// announced (announcedGrid).
struct InSituTimeLine
{
  bp::StreamTimeLine stream;
  vtkMTimeType settingsTime = 0;
  std::vector<double> grid;
  /// The Initial State File a restart tried (TracerResume.cxx): in this run
  /// it is not tried again.
  bpvtk::StateFileStamp stateTried;
  bool restart = false; ///< this replay goes on from the Initial State File
};

/// In parallel, the element exchange of the last steps.
struct ExchangeReport
{
  long long migrated = 0;                    ///< elements this process sent away
  std::vector<long long> elementsPerProcess; ///< every process's, after the last steps
};

/// What the last replay resolved (TracerReplay.cxx).
struct ResolvedTrace
{
  bp::Parameters parameters;
  bp::TraceSettings settings; ///< what it resolved them from (releaseIntoGrid)
  double dt = 0.0;
  double elementSize = 0.0;
  std::size_t particlesPerElement = 1;
  double traceBytes = 0.0;    ///< the whole trace's size (bp::traceBytes)
  double startMaxSpeed = 0.0; ///< the field's largest speed at the start (bp::FieldFacts)
  /// The step schedule's start: the trace's start, or in situ the start of
  /// the trace a restart's Initial State was saved by (restartInSitu).
  double scheduleStart = 0.0;
  bp::RangeFacts rangeFacts; ///< for the GPU display's output
};

} // namespace bpvtk

class vtkBoundParticleTracerInternals
{
public:
  using Pass = bpvtk::TracerPass;
  using Config = bpvtk::TracerConfig;

  /// `owner` is the filter: the internals use it only to report (messages,
  /// progress) and to hear an abort, never to read its properties (they come
  /// in a bpvtk::TracerConfig).
  explicit vtkBoundParticleTracerInternals(vtkAlgorithm* owner);

  // What the filter asks of its trace.
  bool hasTimes() const { return this->Plan.hasTimes(); }
  /// The trace's start in the data's time (backward: the data's end).
  double startTime() const { return bp::traceTime(this->Plan.direction(), this->Plan.startTime()); }
  /// The output's time steps (both ports share them).
  /// The times offered to the animation: the data's (TracePlan::offeredTimes).
  const std::vector<double>& outputTimes() const { return this->Plan.offeredTimes(); }
  vtkIdType stepsInLastUpdate() const { return this->Update.stepsInLastUpdate; }
  /// When the elements were last shown (or the trace forgotten): the State
  /// output, which saves the time shown, is out of date since.
  vtkMTimeType shownMTime() const { return this->Shown.stamp.GetMTime(); }
  bool lastUpdateReplayed() const { return this->Update.lastUpdateReplayed; }
  /// Steps between two checkpoints of the trace; 0: none kept.
  long long checkpointEvery() const { return this->Spacing.every; }
  int timeStepsHeld() const { return int(this->Held.cache.size()); }
  double resolvedDt() const { return this->Resolved.dt; }
  double resolvedElementSize() const { return this->Resolved.elementSize; }
  /// Asked for pieces: this process's piece and the whole extent.
  bool idle() const { return this->Layout.idle(); }
  bool tooSmallToSplit() const { return this->Layout.tooSmallToSplit(); }

  /// Post hoc RequestInformation: the time line follows the input's
  /// `inputTimes` (TracePlan::setTimes). Returns the error, if any.
  std::string setTimes(const std::vector<double>& inputTimes, double duration,
    int numberOfTimeSteps, int framesPerInterval, bp::TimeDirection direction);
  /// In situ RequestInformation (TracerInSitu.cxx): the present step's `time`
  /// offered to the time line; a change of the filter's settings (its MTime
  /// `settingsTime`) starts the trace again. Returns the error when the
  /// step cannot start a trace (there are then no times); `warning` says a
  /// refused step.
  /// Under MPI a change of the announced `grid` (bpvtk::announcedGrid) starts
  /// it again too, with the warning.
  std::string offerStreamTime(
    vtkMTimeType settingsTime, double time, const std::vector<double>& grid, std::string& warning);
  /// RequestUpdateExtent: the pieces this output asks for (a change of them,
  /// or under MPI of the `periodic` axes, along which a piece spans the whole
  /// axis, is a change of input: every trace is stale), then what the input
  /// is asked for (`mesh`: an input the resampler takes whole).
  void requestPieces(vtkInformation* outInfo, vtkInformation* inInfo, bool mesh,
    const std::array<bool, 3>& periodic);

  /// The share of the update's stepping done, over all its passes.
  double progress() const
  {
    const double span = this->target() - this->Update.progressFrom;
    return span > 0.0
      ? std::min(1.0, std::max(0.0, (this->Update.progressAt - this->Update.progressFrom) / span))
      : 0.0;
  }

  bp::Stepper& stepper() { return this->Steppers.active(); }
  double target() const { return this->Update.decision.target; }
  /// target() in the data's time (TimeDirection.h): what the output is stamped with.
  double dataTarget() const { return bp::traceTime(this->Plan.direction(), this->target()); }
  /// Where the work still to do starts: the start time for a replay not yet
  /// configured, else where the stepper stands (it moves as passes step).
  double steppingFrom()
  {
    return this->ReplayPending ? this->Plan.startTime() : this->stepper().cursor.committed;
  }

  /// After a change of the filter, its input or the pieces: every trace and
  /// held time step is stale, and upstream holds nothing known.
  void forgetTrace();
  /// After a failed or aborted update: the trace and the held time steps
  /// are dropped, so the next update replays from what upstream gives;
  /// after a skipped in situ step (skipPresentStep) they are kept.
  void endFailedUpdate(bool skipped = false);
  /// In situ, the present step's data could not be taken (`error`): the step
  /// leaves the time line and the trace keeps its elements, so the next step
  /// goes on from the last good one (a Skipped pass). A failure as post hoc
  /// where there is no trace to keep (the first step).
  Pass skipPresentStep(const std::string& error);
  /// In situ, the present step's grid (in the engine's frame) differs from
  /// the held steps': they are resampled onto it, and the elements keep
  /// their places. Warns of the first change.
  void relocate(const bp::GridGeometry& grid, const bp::FieldSlice& slice);
  /// In situ, after relocate(): releases from now on land in the new `grid`
  /// (bp::emitterInChangedField), on the stepper and in the kept Parameters;
  /// warns once where the emitter box misses it.
  void releaseIntoGrid(const bp::GridGeometry& grid);

  /// The decision for a request (RequestUpdateExtent): picks the stepper
  /// for this request, then replay or continue and the first time step.
  /// Only for a new update (not a later pass of one), with times offered.
  /// `gpuQueue`: the work queue a Bound Particles display asked for (0: none);
  /// `forState`: the request is the State output's, which saves the trace
  /// at the time the elements were last shown (a writer asks for the time
  /// the pipeline last asked of that output: in the GUI, when it was applied),
  /// with the stepper that showed them (the GPU display's queue, whatever
  /// `gpuQueue` the elements' output holds now: the display takes its
  /// request back once it drew), or, with none shown, at the time asked
  /// for; the elements' report of what the last update did is kept.
  void decide(const Config& config, vtkInformation* outInfo, int gpuQueue, bool forState = false);
  /// The decision in situ: go on from the kept step to the present one, or
  /// start again at the present one when a step the work needs is gone.
  void decideInSitu(double target);
  /// The input time step this pass asks upstream for (RequestUpdateExtent),
  /// none for a steady input.
  void requestTimeStep(vtkInformation* inInfo);
  /// This pass ends asking upstream for `index`: the next pass continues
  /// the same update.
  void continueWith(int index);
  /// The update's last pass ends here.
  void finishPasses() { this->Update.continuing = false; }
  /// A later pass of the same update.
  bool continuing() const { return this->Update.continuing; }
  /// This update replays from the start, and has not yet configured.
  bool replayPending() const { return this->ReplayPending; }

  void begin(const Config& config);
  std::string takeTimeStep(const Config& config, const bpvtk::TracerInputStep& input);
  /// Resolves the settings from the start's field, then configures the stepper.
  Pass replay(const Config& config, vtkInformationVector** inputVector);
  Pass stepToTarget();
  /// Keeps a checkpoint of the state on the boundary t when one is due there.
  void keepCheckpointIfDue(bp::Stepper& stepper, double t);
  Pass readAhead();
  /// Steps the short last step to the target (taken back at the next
  /// update; collective in parallel, as every step), then builds the output.
  Pass show(const Config& config, vtkPolyData* output);
  /// The second output after show(): the FTLE map of a lattice release
  /// (TracerFtleMap.cxx; collective in a distributed run).
  void showFtleMap(vtkImageData* image);
  /// The fourth output after show(): the events at the field's sides so far
  /// (TracerInteractions.cxx; collective in a distributed run).
  void showInteractions(vtkPolyData* out);
  /// After decide(), for a request of the Interactions output: whether the
  /// CPU engine already stands at the target as the elements were shown
  /// there (the same trace, no replay or checkpoint), so that filling the
  /// events is the whole update (interactionsOnly()).
  void decideInteractionsOnly();
  bool interactionsOnly() const { return this->Update.interactionsOnly; }
  /// Such an update: the short step to the target taken again where a State
  /// update took it back (its failure said, the output empty), then
  /// showInteractions.
  void showInteractionsAlone(vtkPolyData* out);
  /// The third output, when asked for: the state at the committed step
  /// boundary (TracerResume.cxx; collective in a distributed run: process
  /// 0's holds every element).
  Pass showState(const Config& config, vtkPolyData* out);
  /// An update for the State output (decide's `forState`).
  bool forState() const { return this->Update.forState; }
  /// An update for the State output that reads the GPU display's engine
  /// back where it stands, on the boundary of the time it shows: no step,
  /// no call recorded, the picture unchanged (showState alone).
  bool readsShownState() const { return this->Update.readsShownState; }

  /// For the time line's probe: `data` (a mesh) resampled whole on every
  /// process (collective over the global controller) into `grid`; its vectors.
  vtkDataArray* probeGrid(
    const Config& config, vtkDataObject* data, vtkSmartPointer<vtkDataObject>& grid);

private:
  bp::TracePlan Plan;
  bpvtk::InSituTimeLine InSitu; ///< in situ, the times given since the trace started
  bpvtk::HeldSteps Held;        ///< the field's time steps held, and which one upstream has
  bpvtk::TracerSteppers Steppers;
  bpvtk::PieceLayout Layout;
  bpvtk::OutputStorage Storage; ///< the output's cells and array memory, kept between frames
  std::unique_ptr<bp::StepSchedule> Schedule;
  bp::CheckpointSpacing Spacing; ///< every how many steps the trace keeps a checkpoint
  /// Bumped whenever the filter or its input changes: a trace made for an
  /// older configuration replays.
  std::uint64_t Configuration = 1;
  bpvtk::SaidOnce Said; ///< the warnings said for this configuration (forgotten by invalidate())
  const std::uint64_t ProducerId;

  bpvtk::UpdatePass Update;       ///< the update in progress, and what the last one did
  bpvtk::ResolvedTrace Resolved;  ///< what the last replay resolved
  bpvtk::ExchangeReport Exchange; ///< the element exchange of the last steps

  vtkNew<vtkImageData> FtleMap; ///< the last one gathered, in a distributed run
  /// The events last gathered in a distributed run, and where the trace
  /// stood then (its cursor's steps, short step shown, target).
  vtkNew<vtkPolyData> Interactions;
  /// The Interactions output between updates (appended to while the log grows).
  bpvtk::InteractionsOutput InteractionsOut;
  std::array<double, 3> InteractionsAt = { -1.0, 0.0, 0.0 };
  /// The time the elements were last shown at (trace time), which the State
  /// output saves, and when it was shown.
  struct ShownTime
  {
    bool valid = false;
    double target = 0.0;
    /// The GPU display's queue that showed them at `target` (0: only the
    /// CPU output did), kept when the CPU output shows the same time after it.
    int queue = 0;
    vtkTimeStamp stamp;
  } Shown;

  vtkAlgorithm* const Owner;  ///< for messages, progress and abort only
  bool ReplayPending = false; ///< this update replays from the start (startTrace clears it)

  /// Forgets every trace: each stepper's cursor, and pending GPU work.
  void invalidate();
  /// Drops the active trace and the held time steps.
  void clear();

  // Reading a time step (TracerTimeStep.cxx).
  /// Whether this pass's time step is one the work needs and not yet held.
  bool wantsTimeStep();
  /// `input` (a mesh) resampled (collective in parallel): `piece` gets this
  /// process's piece of the grid. Returns the error, if any.
  std::string resampleInput(
    const Config& config, vtkDataObject* input, vtkSmartPointer<vtkImageData>& piece);
  /// Release Weights for `slice` from `input` (TracerReleaseWeights.h), and
  /// their warning once per configuration.
  void takeReleaseWeights(const Config& config, vtkDataObject* input, bp::FieldSlice& slice);
  /// Says which of the input's 3-component arrays is traced and why
  /// (bpvtk::describeVectorsChoice), once for each new choice.
  void noteVectors(const Config& config, vtkDataObject* input);
  std::string SaidVectors; ///< the last note said (or found empty)
  /// On a flat field, drops the velocity's components across its plane
  /// (bp::dropFlatComponents), and says so once per configuration.
  void keepInPlane(const bp::GridGeometry& grid, bp::FieldSlice& slice);
  /// The mask's and the NaNs' warnings, once per configuration.
  void warnOfSlice(const std::string& maskProblem, std::size_t nonFinite, std::size_t points);
  /// The time this pass's slice stands for; warns when upstream delivered another.
  double sliceTime(vtkDataObject* input);
  /// The grid check and the cache insert for a time step just read.
  std::string keepTimeStep(
    bp::GridGeometry grid, std::array<double, 3> offset, const bp::FieldSlice& slice);
  /// A time step's grid and offset against the held steps': empty when they
  /// match. In situ a changed grid is put in the held steps' frame and
  /// re-located (relocate); post hoc, and in situ under MPI, it is an error.
  std::string matchHeldGrid(
    bp::GridGeometry& grid, std::array<double, 3>& offset, const bp::FieldSlice& slice);

  // Replaying: resolving the settings and configuring (TracerReplay.cxx).
  /// The Seed Source's or the Seed Type's points, with their warnings.
  std::string gatherSeeds(const Config& config, vtkInformationVector** inputVector,
    const bp::VectorField& field, bpvtk::TracerSeeds& seeds);
  /// The field's facts for parameter resolution (collective in parallel).
  bp::FieldFacts fieldFacts(const bp::VectorField& field);
  /// In parallel: more ghost layers when the resolved step needs them;
  /// true when the time step must be read again with them.
  bool needMoreGhostLayers(const bp::Resolution& resolved, const bp::FieldFacts& facts);
  /// The stepper set up for a new trace: the checks of checkConfiguration()
  /// (agreed between processes), then the field and the placement.
  Pass configureStepper(const Config& config, vtkInformationVector** inputVector,
    const bp::VectorField& field, const bp::Resolution& resolved, const bpvtk::TracerSeeds& seeds);
  /// Periodic's refusals: an axis of one point, Linking.
  std::string checkPeriodic(const Config& config, const bp::VectorField& field) const;
  /// A warning for each periodic axis whose last plane is not a copy of its
  /// first (bp::periodicSeamMismatch): traced, with a jump at the seam.
  void warnOfPeriodicSeams(const Config& config, const bp::VectorField& field) const;
  /// This process's checks of a new trace: the template, the seeds, the
  /// engine's limits, memory, a stable relaxation, the GPU's limits; then
  /// the stepper configured. Returns the error, if any.
  std::string checkConfiguration(const Config& config, vtkInformationVector** inputVector,
    const bp::VectorField& field, const bpvtk::TracerSeeds& seeds, bp::ElementTemplate& shape,
    bp::Parameters& p);
  /// Warns when stretch is asked of a template that cannot stretch (one particle).
  void warnOfDeformation(
    const Config& config, const bp::ElementTemplate& shape, const bp::Parameters& p);
  /// Warns when Release Weights are above 0 only where releases may not
  /// land (the engines then release uniformly, bp::releaseWeightsOf).
  void warnOfUnreachableWeights(
    const Config& config, const bp::VectorField& field, const bp::Parameters& p);
  /// Warns when the Release Window releases nothing in the offered times.
  void warnOfReleaseWindow(const bp::Parameters& p);
  /// The element template: the built-in shape or the template input.
  std::string elementTemplate(
    const Config& config, vtkInformationVector** inputVector, bp::ElementTemplate& shape);
  /// Points the stepper at the start of a new trace, or at the Initial
  /// State it resumed, its checkpoints spaced within the config's budget.
  void startTrace(const Config& config);

  // Saving and resuming (TracerResume.cxx).
  /// After the stepper placed its elements: with an Initial State File and a
  /// target at or after its time, the state's elements instead, once it is
  /// checked against this trace (agreed between processes). Empty on success.
  std::string resumeFromState(
    const Config& config, const bp::ElementTemplate& shape, const bp::Parameters& p);
  /// Whether work that starts at `from` (trace time) reaches the Initial
  /// State's time without passing it: the state, read, is then gone on from.
  bool resumesFromState(const Config& config, double from);
  /// In situ, whether the Initial State stands at the first time step handed
  /// (a simulation restarted from its checkpoint): the trace goes on from it.
  bool restartsAtState() const;
  /// Before the settings are resolved, in situ: with a restart's Initial
  /// State, the facts its trace was resolved with (the largest speed at its
  /// start, its schedule's start) stand in for the present step's; an
  /// Initial State at another time is not used, and said so (once).
  void restartInSitu(const Config& config, bp::FieldFacts& facts);
  /// What of `state` differs from this trace, said by name; empty when nothing.
  std::string stateMismatch(const Config& config, const bp::TraceState& state,
    const bp::ElementTemplate& shape, const bp::Parameters& p);
  /// The facts of the field a state must match (the grid and its bounds,
  /// the arrays traced, its time steps, its largest speed at the start, the
  /// time direction, the number of processes), as named values.
  std::vector<bp::NamedValue> fieldValues(const Config& config);
  bpvtk::InitialState Initial; ///< the Initial State File as last read
  /// The state resumed by the last replay: its step count (-1: none) and time.
  long long ResumedSteps = -1;
  double ResumedTime = 0.0;
  /// Every how many steps a new trace keeps a checkpoint (Checkpoints.h):
  /// Checkpoint Memory (automatic: half the trace's own size), at most half
  /// of what this process can allocate, over the whole system's state; the
  /// same on every process.
  bp::CheckpointSpacing checkpointSpacing(const Config& config);

  // The seeds (TracerSeeds.cxx).
  /// The Seed Source's points (input 2), world coordinates, 3 doubles each:
  /// the same on every process (collective in parallel). Returns the error.
  std::string readSeeds(
    const Config& config, vtkInformationVector** inputVector, std::vector<double>& xyz) const;
  /// The Seed Type's points (none for the emitter box), computed alike on
  /// every process; along the field's flat axes they lie on its plane.
  void seedTypePoints(
    const Config& config, const bp::VectorField& field, bpvtk::TracerSeeds& seeds) const;
  /// `seeds` emptied and named after `type` (its name, its point count, the
  /// advice when elements share points): shared by every Seed Type.
  static void nameSeeds(vtkBoundParticleSeedType* type, bpvtk::TracerSeeds& seeds);
  /// Puts the points `xyz` (world coordinates) on the field's plane along
  /// its flat axes (`domain`, the whole field's), as the emitter box is.
  void putOnFlatAxes(const bp::Domain& domain, std::vector<double>& xyz) const;
  /// The Seed Type's DescribeUnusableParameters, warned once (as the seeds'
  /// other warnings); nothing when it has nothing to say.
  void warnOfUnusableSeeds(vtkBoundParticleSeedType* type);
  /// Seed Type Surface: its points drawn over the Seed Source's surface by
  /// the flux through it at the trace's start (TracerSurfaceSeeds.cxx,
  /// collective in parallel); an error when nothing can be released.
  std::string surfaceSeedPoints(const Config& config, vtkInformationVector** inputVector,
    const bp::VectorField& field, bpvtk::TracerSeeds& seeds);
  /// The Surfaces input (input 3) as the engine's gates and outlets in
  /// `p.surfaces` (null where none acts; TracerSurfaces.cxx), with a warning
  /// (once) for what is left out.
  void gatherSurfaces(const Config& config, vtkInformationVector** inputVector,
    const bp::VectorField& field, bp::Parameters& p);
  /// The seed points in the field, as release centres in engine coordinates;
  /// an error when none lies in the flow.
  std::string seedPoints(
    const bpvtk::TracerSeeds& seeds, const bp::VectorField& field, bp::Parameters& p);

  // The output (vtkBoundParticleTracerInternals.cxx).
  /// In parallel: the balance, the migrations and exchange errors of the steps.
  void gatherExchange();
  void addSettingsFieldData(vtkPolyData* output);
  /// For a GPU display: hands it the draw settings (a new serial: the
  /// display samples the field again), and fills the output with the
  /// arrays' expected ranges on two points spanning the field.
  void handToDisplay(const Config& config, vtkPolyData* output);
  /// The short step from the committed boundary to the target, shown and
  /// taken back at the next update (show(); after a State update that
  /// recorded steps for the GPU display, so that it draws the time shown);
  /// `fieldSet`: the stepper holds the target's field already.
  Pass stepShort(bool fieldSet);
};

#endif
