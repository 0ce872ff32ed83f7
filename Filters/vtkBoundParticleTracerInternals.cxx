// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, the update's bookkeeping: what a request decides,
// the start of an update, stepping to the target, reading ahead, and the
// output shown. See vtkBoundParticleTracerInternals.h.
#include "vtkBoundParticleTracerInternals.h"

#include "ReplayProgress.h"

#include "ElementTemplate.h"
#include "Memory.h"
#include "Partition.h"
#include "TraceSettings.h"
#include "TracerInput.h"
#include "VectorField.h"
#include "vtkBoundParticleSeedType.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>

namespace
{
std::uint64_t nextProducerId()
{
  static std::mutex m;
  static std::uint64_t next = 0;
  std::lock_guard<std::mutex> lock(m);
  return ++next;
}

} // namespace

vtkBoundParticleTracerInternals::vtkBoundParticleTracerInternals(vtkAlgorithm* owner)
  : ProducerId(nextProducerId())
  , Owner(owner)
{
}

std::string vtkBoundParticleTracerInternals::setTimes(const std::vector<double>& inputTimes,
  double duration, int numberOfTimeSteps, int framesPerInterval, bp::TimeDirection direction)
{
  return this->Plan.setTimes(inputTimes, duration, numberOfTimeSteps, framesPerInterval, direction);
}

void vtkBoundParticleTracerInternals::requestPieces(
  vtkInformation* outInfo, vtkInformation* inInfo, bool mesh, const std::array<bool, 3>& periodic)
{
  const bool pieces = this->Layout.takeRequest(outInfo, inInfo);
  // Both run: a periodic axis is read whole by every process.
  const bool periodicAxes = this->Layout.setPeriodic(periodic);
  if (pieces || periodicAxes)
  {
    // A change of pieces is a change of input: replay.
    this->forgetTrace();
  }
  this->Layout.requestInput(inInfo, mesh);
}

void vtkBoundParticleTracerInternals::invalidate()
{
  ++this->Configuration;
  this->Said.forget();
  this->Steppers.invalidate();
  this->Shown.valid = false;
  this->Shown.stamp.Modified();
}

void vtkBoundParticleTracerInternals::clear()
{
  this->Steppers.active().cursor.valid = false;
  this->Held.cache.clear();
  this->Update.continuing = false;
}

void vtkBoundParticleTracerInternals::forgetTrace()
{
  this->invalidate();
  this->clear();
  this->Held.lastRequested = -1;
}

void vtkBoundParticleTracerInternals::endFailedUpdate(bool skipped)
{
  if (skipped)
  {
    this->Update.continuing = false;
    return;
  }
  this->clear();
  this->invalidate();
}

void vtkBoundParticleTracerInternals::decide(
  const Config& config, vtkInformation* outInfo, int gpuQueue, bool forState)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  this->Update.forState = forState;
  this->Update.readsShownState = false;
  this->Update.interactionsOnly = false;
  // The State output saves what was shown last, from the stepper that
  // showed it: the display's request on the elements' output is taken back
  // once it drew, so it no longer says which.
  const int queueAsked = forState && this->Shown.valid ? this->Shown.queue : gpuQueue;
  this->Steppers.select(config.engine, queueAsked, this->Layout);
  // In situ the present step is the time shown, whatever time is asked for;
  // the State output saves the time shown.
  const double target = this->Plan.streaming() ? this->Plan.outputTimes().back()
    : forState && this->Shown.valid
    ? this->Shown.target
    : this->Plan.targetOf(
        outInfo->Has(SDDP::UPDATE_TIME_STEP()), outInfo->Get(SDDP::UPDATE_TIME_STEP()));
  const bp::Stepper& stepper = this->stepper();
  this->Update.decision = this->Plan.decide(target, stepper.cursor, this->ProducerId,
    this->Configuration, stepper.keepsCheckpoints() ? &stepper.checkpoints() : nullptr);
  if (this->Plan.streaming())
  {
    this->decideInSitu(target);
    return;
  }
  bp::TracePlan::Update& u = this->Update.decision;
  if (forState && this->Steppers.queue() && this->Shown.valid && this->Shown.target == target &&
    !u.replay && u.resume < 0 && this->Schedule &&
    this->Schedule->next(stepper.cursor.committed) > target + this->Schedule->epsilon())
  {
    // The display stands on the last boundary before the time it shows (and
    // shows the short step past it, or stands on the time itself).
    this->Update.readsShownState = true;
  }
  if (!u.replay && !this->Layout.distributed() && this->resumesFromState(config, u.from))
  {
    // An Initial State this trace has not used, and the work would pass its
    // time: it is gone on from instead (a replay loads it). Not under MPI,
    // where a process that read another file would part from the others; a
    // replay there uses it.
    u.replay = true;
    u.resume = -1;
    u.from = this->Plan.startTime();
  }
  this->Held.requestIndex =
    this->Plan.firstRequest(this->Update.decision, this->Held.cache, this->Held.lastRequested);
}

void vtkBoundParticleTracerInternals::decideInSitu(double target)
{
  if (!this->Plan.streamCanGoOn(this->Update.decision, this->Held.cache))
  {
    // The past steps are gone: a trace that must start again, or that lost
    // a step it needs, starts again at the present one.
    this->InSitu.stream.restartAtPresent();
    this->Plan.setStreamTimes(this->InSitu.stream.times());
    this->Held.cache.clear();
    this->stepper().cursor.valid = false;
    this->Update.decision =
      this->Plan.decide(target, this->stepper().cursor, this->ProducerId, this->Configuration);
  }
  // Upstream is only ever asked for the present.
  this->Held.requestIndex = int(this->Plan.inputTimes().size()) - 1;
}

void vtkBoundParticleTracerInternals::requestTimeStep(vtkInformation* inInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (this->Plan.unsteady())
  {
    inInfo->Set(SDDP::UPDATE_TIME_STEP(), this->Plan.dataTimeOf(this->Held.requestIndex));
    this->Held.lastRequested = this->Held.requestIndex;
  }
  else
  {
    inInfo->Remove(SDDP::UPDATE_TIME_STEP());
  }
}

void vtkBoundParticleTracerInternals::continueWith(int index)
{
  this->Held.requestIndex = index;
  this->Update.continuing = true;
}

void vtkBoundParticleTracerInternals::begin(const Config& config)
{
  bp::Stepper& stepper = this->stepper();
  const bool replay = this->Update.decision.replay;
  this->ReplayPending = replay;
  // Periodic belongs to the grid: the held time steps take a change at once.
  this->Held.grid.periodic = config.periodic;
  if (!this->Update.forState)
  {
    this->Update.stepsInLastUpdate = 0;
    this->Update.lastUpdateReplayed = replay;
    this->Exchange.migrated = 0;
  }
  this->Held.readThisUpdate = false;
  if (this->Update.decision.resume >= 0)
  {
    // Back to the latest checkpoint at or before the target: the same state
    // a replay from the start reaches there, bit for bit.
    stepper.resumeCheckpoint(this->Update.decision.resume);
  }
  else if (!replay && stepper.cursor.showsPartialStep)
  {
    // Take back the short step the last update showed: the trace stays on
    // the step boundaries, so a replay and a continued run agree bit for bit.
    stepper.restore();
  }
  stepper.cursor.showsPartialStep = false;
  this->Update.intervalAtStart = replay || !this->Plan.unsteady()
    ? -1
    : this->Plan.intervalAt(stepper.cursor.committed, false).front();
  // An abort ends the update it was asked in, not every later one: VTK 9.2
  // to 9.5 leave the request set (ParaView 6.1 clears it itself). Cleared
  // without Modified(), which would make this update's output look stale.
  this->Owner->AbortExecute = 0;
  // Progress runs over the whole update, across its passes.
  this->Update.progressFrom = replay ? this->Plan.startTime() : stepper.cursor.committed;
  this->Update.progressAt = this->Update.progressFrom;
  if (replay && this->Layout.distributed() && this->Layout.Piece == 0 &&
    config.engine == bp::EngineChoice::Gpu)
  {
    vtkWarningWithObjectMacro(this->Owner,
      "The GPU engine runs in one process; with "
        << this->Layout.Pieces
        << " processes the CPU engine traces and the Bound Particles display draws its "
           "particles on every process.");
  }
  if (replay)
  {
    stepper.cursor.valid = false;
    // A steady input's single time step is read again at every replay; an
    // unsteady input's stay valid (RequestInformation drops them when the
    // input changes).
    if (!this->Plan.unsteady())
    {
      this->Held.cache.clear();
    }
  }
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::stepToTarget()
{
  bp::Stepper& stepper = this->stepper();
  double& committed = stepper.cursor.committed;
  const double target = this->target();
  const std::string tooMuch = this->Plan.checkWork(committed, target, this->Schedule->dt());
  if (!tooMuch.empty())
  {
    return Pass::fail(tooMuch);
  }
  if (const bp::WorkQueue* queue = this->Steppers.queue())
  {
    // The GPU engine runs in the render, where ParaView 5.11 offers no Abort.
    const std::string note = bp::longReplayNote((target - committed) / this->Schedule->dt(),
      double(this->Resolved.parameters.numberOfElements) *
        double(this->Resolved.particlesPerElement),
      bp::traceTime(this->Plan.direction(), committed), this->dataTarget(), *queue);
    if (!note.empty())
    {
      vtkWarningWithObjectMacro(this->Owner, << note);
    }
  }
  bool aborted = false;
  auto keepGoing = [&](double t)
  {
    this->Update.stepsInLastUpdate += this->Update.forState ? 0 : 1;
    this->Update.progressAt = t;
    this->Owner->UpdateProgress(this->progress());
    // In parallel every process must take every step (each exchanges
    // elements with the others), so one process alone cannot stop.
    aborted = !this->Layout.distributed() && this->Owner->CheckAbort();
    return !aborted;
  };
  // One data interval at a time.
  while (true)
  {
    const std::vector<int> ids = this->Plan.needed(committed, target);
    const int missing = this->Held.cache.firstMissing(ids);
    if (missing >= 0)
    {
      // Drop what no later step needs before asking for the next time step.
      this->Held.cache.dropBefore(ids.front());
      return Pass::need(missing);
    }
    const double intervalEnd = ids.size() == 2 ? this->Plan.inputTimes()[ids[1]] : target;
    const double limit = std::min(target, intervalEnd);
    const double before = committed;
    const std::string fieldError = stepper.setField(this->Held.cache.field(this->Held.grid, ids));
    if (!fieldError.empty())
    {
      return Pass::fail(fieldError + ".");
    }
    committed = bp::advance(
      *this->Schedule, committed, limit,
      [&](double t, double h)
      {
        this->keepCheckpointIfDue(stepper, t);
        stepper.step(t, h);
        ++stepper.cursor.steps;
      },
      keepGoing);
    if (aborted)
    {
      return { Pass::Aborted, -1, std::string() };
    }
    if (committed < intervalEnd && intervalEnd - committed <= this->Schedule->epsilon())
    {
      // Input times closer than the schedule resolves (epsilon): no step
      // lands inside such an interval, so the trace stands at its end.
      committed = intervalEnd;
    }
    if (limit >= target || committed < intervalEnd - this->Schedule->epsilon())
    {
      return Pass();
    }
    if (committed == before)
    {
      // Never spin: the schedule lands on every data time step, so this is a bug.
      const double shown = bp::traceTime(this->Plan.direction(), before);
      return Pass::fail("Time stepping made no progress at t = " + std::to_string(shown) +
        "; please report this with the input's time steps.");
    }
  }
}

void vtkBoundParticleTracerInternals::keepCheckpointIfDue(bp::Stepper& stepper, double t)
{
  const long long steps = stepper.cursor.steps;
  if (this->Spacing.due(steps) && !stepper.checkpoints().has(steps))
  {
    stepper.keepCheckpoint(steps, t);
  }
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::readAhead()
{
  bp::Stepper& stepper = this->stepper();
  if (!stepper.readsAhead())
  {
    return Pass();
  }
  // Read the time step after this interval ahead of need, so the display can
  // upload it a slab per frame before a step crosses into it. Only in an
  // update that stays in its interval and read nothing: a frame that crosses
  // a time step has had its share.
  const int upcoming = this->Plan.readAheadIndex(this->target());
  const bool quietFrame = !this->Held.readThisUpdate &&
    this->Update.intervalAtStart == this->Plan.intervalAt(this->target(), false).front();
  if (upcoming >= 0 && !this->Held.cache.has(upcoming) && quietFrame)
  {
    return Pass::need(upcoming);
  }
  stepper.offerUpcoming(upcoming >= 0 && this->Held.cache.has(upcoming)
      ? this->Held.cache.at(upcoming)
      : bp::FieldSlice());
  return Pass();
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::show(const Config& config, vtkPolyData* output)
{
  // The output at the target: the committed state, finished with a shorter
  // step that the next update takes back, so the trace stays on the step
  // boundaries.
  bp::Stepper& stepper = this->stepper();
  const double target = this->target();
  const bp::VectorField field =
    this->Held.cache.field(this->Held.grid, this->Plan.intervalAt(target, false));
  const std::string fieldError = stepper.setField(field);
  if (!fieldError.empty())
  {
    return Pass::fail(fieldError + ".");
  }
  const Pass shortStep = this->stepShort(true);
  if (shortStep.kind != Pass::Done)
  {
    return shortStep;
  }
  this->gatherExchange();
  const bp::Engine* particles = stepper.particles();
  this->Owner->UpdateProgress(1.0);
  if (particles)
  {
    bpvtk::OutputFrame frame;
    frame.time = target;
    frame.backward = this->Plan.direction() == bp::TimeDirection::Backward;
    frame.offset = this->Held.offset;
    frame.domain = this->Layout.domainBounds(this->Held.grid);
    const auto local = this->Held.grid.bounds();
    for (int a = 0; a < 3; ++a)
    {
      frame.reach =
        std::max(frame.reach, std::abs(this->Held.offset[a]) + std::abs(local[2 * a + 1]));
    }
    frame.cellLength = this->Held.grid.cellLength();
    frame.coloringAxis = config.coloringAxis;
    frame.wanted = config.wanted;
    bpvtk::fillParticleOutput(
      output, *particles, field, frame, this->Storage, this->Steppers.runner());
  }
  else
  {
    this->handToDisplay(config, output);
  }
  this->addSettingsFieldData(output);
  // The GPU display that showed this time stays the one the State output
  // reads, when the CPU output shows the same time after it: ParaView
  // updates every output of the tracer (the elements' on the CPU, its
  // display's request taken back) before a writer of the State output runs.
  const int queue = this->Steppers.queue() ? this->Steppers.queue()->id() : 0;
  if (queue != 0 || !this->Shown.valid || this->Shown.target != target)
  {
    this->Shown.queue = queue;
  }
  this->Shown.valid = true;
  this->Shown.target = target;
  this->Shown.stamp.Modified();
  return Pass();
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::stepShort(bool fieldSet)
{
  bp::Stepper& stepper = this->stepper();
  const double target = this->target();
  const double committed = stepper.cursor.committed;
  if (!(target - committed > this->Schedule->epsilon()))
  {
    return Pass();
  }
  if (!fieldSet)
  {
    const std::string fieldError = stepper.setField(
      this->Held.cache.field(this->Held.grid, this->Plan.intervalAt(target, false)));
    if (!fieldError.empty())
    {
      return Pass::fail(fieldError + ".");
    }
  }
  stepper.save();
  stepper.step(committed, target - committed);
  stepper.cursor.showsPartialStep = true;
  this->Update.stepsInLastUpdate += this->Update.forState ? 0 : 1;
  return Pass();
}

void vtkBoundParticleTracerInternals::gatherExchange()
{
  if (!this->Layout.distributed())
  {
    return;
  }
  if (this->Update.stepsInLastUpdate > 0 || this->Update.lastUpdateReplayed)
  {
    // Collective, so only in an update that every process runs in step
    // with the others: one that took steps (each exchanges elements) or
    // replayed (each shares the field's largest speed).
    const bp::Engine* held = this->stepper().particles();
    this->Exchange.elementsPerProcess =
      this->Layout.gather(held ? (long long)held->elementCount() : 0);
  }
  this->Exchange.migrated += this->Steppers.distributed().takeMigrated();
  const std::string error = this->Steppers.distributed().takeExchangeError();
  if (!error.empty())
  {
    vtkWarningWithObjectMacro(this->Owner, "An element exchange failed: " << error);
  }
}

void vtkBoundParticleTracerInternals::handToDisplay(const Config& config, vtkPolyData* output)
{
  bp::WorkQueue& queue = *this->Steppers.queue();
  bp::DrawSettings d = queue.draw();
  d.time = this->target();
  d.offset = this->Held.offset;
  const auto bounds = this->Held.grid.bounds();
  for (int a = 0; a < 3; ++a)
  {
    d.bounds[2 * a] = bounds[2 * a] + this->Held.offset[a];
    d.bounds[2 * a + 1] = bounds[2 * a + 1] + this->Held.offset[a];
  }
  d.coloringAxis = config.coloringAxis;
  d.radialCenter = bp::radialCenter(bounds, config.coloringAxis);
  d.backward = this->Plan.direction() == bp::TimeDirection::Backward;
  ++d.serial;
  queue.setDraw(d);
  // Two points spanning the field (for the camera and the axes grid).
  bpvtk::fillRangeOutput(output, this->Resolved.rangeFacts, d.bounds);
  vtkNew<vtkIntArray> id;
  id->SetName("BoundParticlesWorkQueue");
  id->InsertNextValue(queue.id());
  output->GetFieldData()->AddArray(id);
}

void vtkBoundParticleTracerInternals::addSettingsFieldData(vtkPolyData* output)
{
  // What the automatic settings came to, for the Information panel and scripts.
  bpvtk::addFieldValue(output, "TimeStep", this->Resolved.dt);
  bpvtk::addFieldValue(output, "ElementSize", this->Resolved.elementSize);
  bpvtk::addFieldValue(output, "SimulationTime", this->dataTarget());
  if (this->Resolved.parameters.trailLength > 0)
  {
    // The age at which a trail pose has faded out on the Bound Particles
    // display: one interval past the oldest pose (as its GPU mapper fades).
    bpvtk::addFieldValue(output, "TrailFadeSpan",
      (this->Resolved.parameters.trailLength + 1) * this->Resolved.parameters.trailInterval);
  }
  if (this->Held.resampled)
  {
    // The grid a mesh was resampled onto (TracerResample.h).
    const bp::ResampleGrid& g = this->Held.resampler.grid();
    vtkNew<vtkIntArray> dims;
    dims->SetName("ResampledDimensions");
    vtkNew<vtkDoubleArray> spacing;
    spacing->SetName("ResampledSpacing");
    for (int a = 0; a < 3; ++a)
    {
      dims->InsertNextValue(g.dims[a]);
      spacing->InsertNextValue(g.spacing[a]);
    }
    output->GetFieldData()->AddArray(dims);
    output->GetFieldData()->AddArray(spacing);
  }
  if (this->Layout.distributed())
  {
    // This process's share: ghost layers read, elements sent to other pieces;
    // and the balance: every process's element count (the same on each).
    bpvtk::addFieldValue(output, "GhostLayers", this->Layout.GhostCells);
    bpvtk::addFieldValue(output, "MigratedElements", double(this->Exchange.migrated));
    vtkNew<vtkIdTypeArray> perProcess;
    perProcess->SetName("ElementsPerProcess");
    for (long long c : this->Exchange.elementsPerProcess)
    {
      perProcess->InsertNextValue(vtkIdType(c));
    }
    output->GetFieldData()->AddArray(perProcess);
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->dataTarget());
}
