// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, saving and resuming: the State output filled from
// the committed step boundary, and a new trace that goes on from its Initial
// State File. See vtkBoundParticleTracerInternals.h and TracerState.h.
#include "vtkBoundParticleTracerInternals.h"

#include "EngineState.h"
#include "TracerState.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstring>
#include <sstream>

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
  std::string difference =
    bp::firstDifference(state.field, this->fieldValues(config), "the field's");
  if (difference.empty())
  {
    difference = bp::firstDifference(state.shape, bp::templateValues(shape), "the template's");
  }
  if (difference.empty())
  {
    difference = bp::firstDifference(state.parameters, bp::parameterValues(p), "the setting");
  }
  if (difference.empty() &&
    (state.scheduleStart != this->Plan.startTime() || state.dt != this->Resolved.dt))
  {
    std::ostringstream text;
    text.precision(17);
    text << "its trace started at t = " << bp::traceTime(this->Plan.direction(), state.scheduleStart)
         << " with steps of " << state.dt << "; this one starts at t = " << this->startTime()
         << " with steps of " << this->Resolved.dt;
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
  return this->Initial.error.empty() && from < t - eps && this->target() >= t - eps;
}

std::string vtkBoundParticleTracerInternals::resumeFromState(
  const Config& config, const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  this->ResumedSteps = -1;
  const bool distributed = this->Layout.distributed();
  // Every branch below is taken alike on every process: what each read is
  // agreed on first. A file that cannot be read, or lies past this trace's
  // times, is said whatever time is asked for.
  bool resumes = this->resumesFromState(config, this->Plan.startTime());
  resumes = resumes || !this->Initial.error.empty() ||
    (!config.initialStateFile.empty() && !this->Plan.outputTimes().empty() &&
      this->Initial.state.time > this->Plan.outputTimes().back() + this->Plan.epsilon());
  if (!(distributed ? this->Layout.globalMax(resumes ? 1.0 : 0.0) > 0.0 : resumes))
  {
    return std::string();
  }
  const std::string named = "Initial State File '" + config.initialStateFile + "'";
  const bp::TraceState& state = this->Initial.state;
  std::string error = this->Initial.error;
  const std::vector<double>& times = this->Plan.outputTimes();
  if (error.empty() && !times.empty() && state.time > times.back() + this->Plan.epsilon())
  {
    error = named + ": its time " + std::to_string(bp::traceTime(this->Plan.direction(), state.time)) +
      " lies past this trace's times: it was saved by another trace.";
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
  if (this->target() < state.time - this->Plan.epsilon())
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
  if (error.empty() && !this->stepper().particles())
  {
    error = "Initial State File: the GPU engine cannot resume a saved state yet; set Engine to "
            "CPU to go on from it.";
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
  bp::TraceState state;
  const bp::Engine* particles = stepper.particles();
  if (!particles || !stepper.committedState(state.engine))
  {
    // Said when the file is read, not here: ParaView asks for every output
    // of a source it updates, a writer or not.
    bpvtk::writeStateNote("the GPU engine's state stays in its display: set Engine to CPU and "
                          "save the State output again",
      out);
    return Pass();
  }
  state.time = stepper.cursor.committed;
  state.steps = stepper.cursor.steps;
  state.scheduleStart = this->Schedule->start();
  state.dt = this->Schedule->dt();
  state.parameters = bp::parameterValues(this->Resolved.parameters);
  state.shape = bp::templateValues(particles->shape());
  state.field = this->fieldValues(config);
  if (this->Layout.distributed())
  {
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
