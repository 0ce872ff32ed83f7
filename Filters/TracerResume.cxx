// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, saving and resuming: the State output filled from
// the committed step boundary, and a new trace that goes on from its Initial
// State File. See vtkBoundParticleTracerInternals.h and TracerState.h.
#include "vtkBoundParticleTracerInternals.h"

#include "vtkBoundParticleSeedType.h"

#include "EngineState.h"
#include "TracerState.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
/// The field's values that say its time steps: in situ, those handed since
/// the trace started, which a restart's are not.
bool namesTimeSteps(const std::string& name)
{
  return name == bp::FieldStateNames::TimeSteps || name == bp::FieldStateNames::TimeStepsHash;
}

/// The value named `name` in `values`; `otherwise` where there is none.
double namedValue(const std::vector<bp::NamedValue>& values, const char* name, double otherwise)
{
  for (const bp::NamedValue& value : values)
  {
    if (value.name == name)
    {
      return value.value;
    }
  }
  return otherwise;
}

/// `values` without those `namesTimeSteps`.
std::vector<bp::NamedValue> withoutTimeSteps(std::vector<bp::NamedValue> values)
{
  values.erase(std::remove_if(values.begin(), values.end(),
                 [](const bp::NamedValue& v) { return namesTimeSteps(v.name); }),
    values.end());
  return values;
}
/// Only the seed points' values (their count and hash) of a state's settings.
std::vector<bp::NamedValue> seedPointValues(std::vector<bp::NamedValue> values)
{
  values.erase(std::remove_if(values.begin(), values.end(),
                 [](const bp::NamedValue& v) { return v.name.rfind("seedPoints", 0) != 0; }),
    values.end());
  return values;
}
} // namespace

std::vector<bp::NamedValue> vtkBoundParticleTracerInternals::fieldValues(const Config& config)
{
  bp::FieldStateFacts facts;
  facts.dims = this->Layout.wholeDims(this->Held.grid);
  facts.bounds = this->Layout.domainBounds(this->Held.grid);
  for (int a = 0; a < 3; ++a)
  {
    facts.bounds[2 * a] += this->Held.offset[a];
    facts.bounds[2 * a + 1] += this->Held.offset[a];
  }
  facts.vectors = config.vectors.name;
  facts.vectorsAssociation = config.vectors.association;
  facts.releaseWeights = config.releaseWeights;
  facts.inputTimes = this->Plan.inputTimes();
  facts.startMaxSpeed = this->Resolved.startMaxSpeed;
  facts.timeDirection = int(this->Plan.direction());
  facts.periodic = config.periodic;
  facts.processes = this->Layout.Pieces;
  return bp::fieldStateValues(facts);
}

std::string vtkBoundParticleTracerInternals::stateMismatch(const Config& config,
  const bp::TraceState& state, const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  // The version first: another version's values may differ in name too.
  if (state.version != bp::EngineStateVersion)
  {
    return bp::checkTraceState(state, shape, p);
  }
  // A restart in situ has only the time steps handed since it started.
  const bool restart = this->restartsAtState();
  std::string difference = restart
    ? bp::firstDifference(
        withoutTimeSteps(state.field), withoutTimeSteps(this->fieldValues(config)), "the field's")
    : bp::firstDifference(state.field, this->fieldValues(config), "the field's");
  if (difference.empty())
  {
    difference = bp::firstDifference(state.shape, bp::templateValues(shape), "the template's");
  }
  if (difference.empty())
  {
    difference = bp::firstDifference(state.parameters, bp::parameterValues(p), "the setting");
    if (restart && !difference.empty() && config.seedType && config.seedType->UsesSeedSource() &&
      !bp::firstDifference(
        seedPointValues(state.parameters), seedPointValues(bp::parameterValues(p)), "")
         .empty())
    {
      // A state keeps only the seed points' count and hash; a Surface draws
      // them from the flow at the first step handed, here the restart step
      // (the emitter box, fitted around them, is named first).
      difference += " (Seed Type Surface draws its points from the flow at the trace's first "
                    "step, after a restart in situ the restart step's, and the state keeps none: "
                    "where the flux through the surface changed since the saved trace's start, "
                    "it cannot go on from the state; use a Point Cloud or a Line to restart)";
    }
  }
  if (difference.empty() &&
    (state.scheduleStart != this->Resolved.scheduleStart || state.dt != this->Resolved.dt))
  {
    std::ostringstream text;
    text.precision(17);
    text << "its trace started at t = "
         << bp::traceTime(this->Plan.direction(), state.scheduleStart) << " with steps of "
         << state.dt << "; this one starts at t = "
         << bp::traceTime(this->Plan.direction(), this->Resolved.scheduleStart) << " with steps of "
         << this->Resolved.dt;
    difference = text.str();
  }
  // Then the records themselves (ids, layout, trail ring).
  return difference.empty() ? bp::checkTraceState(state, shape, p) : difference;
}

bool vtkBoundParticleTracerInternals::resumesFromState(const Config& config, double from)
{
  if (config.initialStateFile.empty())
  {
    this->Initial = bpvtk::InitialState(); // its memory back
    return false;
  }
  this->Initial.take(config.initialStateFile);
  // A state that cannot be read, or lies past the trace's times, is said by
  // the replay; one whose time the work reaches and has not yet passed is
  // gone on from.
  const double eps = this->Plan.epsilon();
  const double t = this->Initial.state.time;
  const bool restart = this->restartsAtState();
  return this->Initial.error.empty() && (from < t - eps || restart) &&
    (this->target() >= t - eps || restart);
}

bool vtkBoundParticleTracerInternals::restartsAtState() const
{
  // In situ the trace cannot replay to a later state's time, nor go back to
  // an earlier one's: only a state at the first step handed is gone on from.
  // One time within the times' own rounding (TracePlan::sameTime): at 1e9
  // (seconds since 1970) two doubles are 1.2e-7 apart at the least.
  return this->Plan.streaming() && this->Initial.error.empty() &&
    this->Plan.sameTime(this->Initial.state.time, this->Plan.startTime());
}

void vtkBoundParticleTracerInternals::restartInSitu(const Config& config, bp::FieldFacts& facts)
{
  this->Resolved.scheduleStart = this->Plan.startTime();
  this->InSitu.restart = false;
  if (!this->Plan.streaming() || config.initialStateFile.empty())
  {
    return;
  }
  // Each decision is taken alike on every process (collective, in order).
  const auto agreed = [this](bool everywhere)
  {
    return this->Layout.distributed() ? this->Layout.globalMax(everywhere ? 0.0 : 1.0) == 0.0
                                      : everywhere;
  };
  this->Initial.take(config.initialStateFile);
  // A state tried once in this run (gone on from, refused, or not used) is
  // not tried again when the trace starts again at a later step (a setting
  // changed): the later step is not a restart.
  if (agreed(this->Initial.stamp == this->InSitu.stateTried))
  {
    return;
  }
  if (!agreed(this->Initial.error.empty()))
  {
    this->InSitu.restart = true; // resumeFromState says why, at this step only
    return;
  }
  const bp::TraceState& state = this->Initial.state;
  if (!agreed(this->restartsAtState()))
  {
    this->InSitu.stateTried = this->Initial.stamp;
    // Every digit: times of 1e9 that differ print alike at 6 digits.
    std::ostringstream times;
    times.precision(17);
    times << "stands at t = " << state.time
          << ", but the first time step handed in situ is t = " << this->Plan.startTime();
    vtkWarningWithObjectMacro(this->Owner,
      "Initial State File '"
        << config.initialStateFile << "' " << times.str()
        << ": it is not used, and the trace starts there. A simulation restarted from its "
           "checkpoint must hand the step the state was saved at first (the same time within "
           "its rounding).");
    return;
  }
  // The settings resolve as they did at the saved trace's start (its step,
  // lifetimes and release speed come from its largest speed there), and
  // its steps stay on the saved schedule; the rest is checked as a replay's.
  facts.maxSpeed = namedValue(state.field, bp::FieldStateNames::LargestStartSpeed, facts.maxSpeed);
  if (this->Layout.distributed())
  {
    facts.maxSpeed = this->Layout.globalMax(facts.maxSpeed); // the same on every process
  }
  this->Resolved.scheduleStart = state.scheduleStart;
  this->InSitu.restart = true;
}

std::string vtkBoundParticleTracerInternals::resumeFromState(
  const Config& config, const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  this->ResumedSteps = -1;
  if (this->Plan.streaming() && !this->InSitu.restart)
  {
    return std::string(); // in situ only a restart goes on from a state (restartInSitu)
  }
  if (this->Plan.streaming())
  {
    // Gone on from or refused here, it is not tried again in this run (a
    // replay that asked for more ghost layers first tries it again).
    this->InSitu.stateTried = this->Initial.stamp;
  }
  const bool distributed = this->Layout.distributed();
  // Every branch below is taken alike on every process: what each read is
  // agreed on first. A file that cannot be read, or lies past this trace's
  // times, is said whatever time is asked for.
  bool resumes = this->resumesFromState(config, this->Plan.startTime());
  // A state outside this trace's times was saved by another trace. In situ
  // a state at another time than the first step's is not used
  // (restartInSitu says so): the times to come are not known.
  const std::vector<double>& times = this->Plan.outputTimes();
  const double eps = this->Plan.epsilon();
  const double saved = this->Initial.state.time;
  const bool past = !this->Plan.streaming() && !times.empty() && saved > times.back() + eps;
  const bool before = !this->Plan.streaming() && !times.empty() && saved < times.front() - eps;
  resumes = resumes || !this->Initial.error.empty() ||
    (!config.initialStateFile.empty() && (past || before));
  if (!(distributed ? this->Layout.globalMax(resumes ? 1.0 : 0.0) > 0.0 : resumes))
  {
    return std::string();
  }
  const std::string named = "Initial State File '" + config.initialStateFile + "'";
  const bp::TraceState& state = this->Initial.state;
  std::string error = this->Initial.error;
  if (error.empty() && (past || before))
  {
    // A state of the other direction has its time in that direction's terms.
    const double direction = double(this->Plan.direction());
    error = namedValue(state.field, bp::FieldStateNames::TimeDirection, direction) != direction
      ? named + " was saved by a trace of the other Time Direction: set Time Direction as it was."
      : named + ": its time " + std::to_string(bp::traceTime(this->Plan.direction(), saved)) +
        (past ? " lies past this trace's times" : " lies before this trace's start") +
        ": it was saved by another trace.";
  }
  if (distributed)
  {
    error = this->Layout.agree(error);
    if (error.empty() && this->Layout.globalMax(state.time) != -this->Layout.globalMax(-state.time))
    {
      error = named + ": the processes read different states (is the file the same for all?).";
    }
  }
  if (!error.empty())
  {
    return error;
  }
  if (this->target() < state.time - this->Plan.epsilon() && !this->restartsAtState())
  {
    return std::string(); // before the state's time: traced from the start
  }
  std::string difference = this->stateMismatch(config, state, shape, p);
  if (!difference.empty())
  {
    error = named + " was saved by a trace that differs from this one: " + difference +
      ". Set the tracer and its input as they were when it was saved, or clear Initial State "
      "File to trace from the start.";
  }
  if (error.empty())
  {
    const std::string refused = this->stepper().loadState(state.engine);
    error = refused.empty() ? refused : named + ": " + refused + ".";
  }
  error = distributed ? this->Layout.agree(error) : error;
  if (error.empty())
  {
    this->ResumedSteps = state.steps;
    this->ResumedTime = state.time;
  }
  return error;
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::showState(
  const Config& config, vtkPolyData* out)
{
  bp::Stepper& stepper = this->stepper();
  bp::WorkQueue* queue = this->Steppers.queue();
  bp::TraceState state;
  const bp::Engine* particles = queue ? nullptr : stepper.particles();
  const bp::ElementTemplate* shape = queue ? queue->configuredShape()
    : particles                            ? &particles->shape()
                                           : nullptr;
  // The GPU display's engine is read back in its GL context, once it has run
  // every call recorded for it (WorkQueue::readState).
  std::string why = queue                               ? queue->readState(state.engine)
    : particles && stepper.committedState(state.engine) ? std::string()
                                                        : std::string("the engine holds no trace");
  if (why.empty() && !shape)
  {
    why = "the engine holds no trace";
  }
  if (!why.empty())
  {
    // Said when the file is read, not here: ParaView asks for every output
    // of a source it updates, a writer or not.
    bpvtk::writeStateNote(queue ? "the GPU display's state could not be read back: " + why +
          "; show the time to keep in the view and save again, or set Engine to CPU"
                                : why,
      out);
    // The display still goes on to the time it shows, read back or not.
    return queue && !this->Update.readsShownState ? this->stepShort(false) : Pass();
  }
  state.time = stepper.cursor.committed;
  state.steps = stepper.cursor.steps;
  state.scheduleStart = this->Schedule->start();
  state.dt = this->Schedule->dt();
  state.parameters = bp::parameterValues(this->Resolved.parameters);
  state.shape = bp::templateValues(*shape);
  state.field = this->fieldValues(config);
  if (queue && !this->Update.readsShownState)
  {
    // This update took back the short step the display showed, or stepped
    // for it: it goes on to the time shown again, so it draws what it drew.
    const Pass shortStep = this->stepShort(false);
    if (shortStep.kind != Pass::Done)
    {
      return shortStep;
    }
  }
  if (this->Layout.distributed())
  {
    // The exchanges of the steps this pass took (a replay to the time
    // shown) are not the elements' update's to report.
    this->Steppers.distributed().takeMigrated();
    // Process 0's piece holds every element; the others hold none (and no
    // field data, which a reader of the pieces would take as well).
    const std::string error = bpvtk::gatherStateElements(this->Layout.Controller, state.engine);
    if (!error.empty())
    {
      return Pass::fail(error);
    }
    if (this->Layout.Piece != 0)
    {
      return Pass();
    }
  }
  bpvtk::writeStatePolyData(state, this->Held.offset, out);
  out->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->dataTarget());
  return Pass();
}
