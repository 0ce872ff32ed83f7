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

#include <sstream>

std::vector<bp::NamedValue> vtkBoundParticleTracerInternals::fieldValues()
{
  std::vector<bp::NamedValue> values;
  const char* axes[3] = { "x", "y", "z" };
  const std::array<int, 3> dims = this->Layout.wholeDims(this->Held.grid);
  const std::array<double, 6> bounds = this->Layout.domainBounds(this->Held.grid);
  for (int a = 0; a < 3; ++a)
  {
    values.push_back({ std::string("points along ") + axes[a], double(dims[a]) });
  }
  for (int a = 0; a < 3; ++a)
  {
    values.push_back(
      { std::string("bounds ") + axes[a] + " from", bounds[2 * a] + this->Held.offset[a] });
    values.push_back(
      { std::string("bounds ") + axes[a] + " to", bounds[2 * a + 1] + this->Held.offset[a] });
  }
  values.push_back({ "largest speed at the start", this->Resolved.startMaxSpeed });
  values.push_back({ "Time Direction (0 Forward, 1 Backward)", double(this->Plan.direction()) });
  return values;
}

std::string vtkBoundParticleTracerInternals::stateMismatch(
  const bp::TraceState& state, const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  // The version first: another version's values may differ in name too.
  if (state.version != bp::EngineStateVersion)
  {
    return bp::checkTraceState(state, shape, p);
  }
  std::string difference = bp::firstDifference(state.field, this->fieldValues(), "the field's");
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
    text << "its trace started at t = "
         << bp::traceTime(this->Plan.direction(), state.scheduleStart) << " with steps of "
         << state.dt << "; this one starts at t = " << this->startTime() << " with steps of "
         << this->Resolved.dt;
    difference = text.str();
  }
  // Then the records themselves (ids, layout, trail ring).
  return difference.empty() ? bp::checkTraceState(state, shape, p) : difference;
}

std::string vtkBoundParticleTracerInternals::resumeFromState(
  const Config& config, const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  this->ResumedSteps = -1;
  if (config.initialStateFile.empty())
  {
    return std::string();
  }
  this->Initial.take(config.initialStateFile);
  const bp::TraceState& state = this->Initial.state;
  std::string error = this->Initial.error;
  if (error.empty() && this->target() < state.time - this->Plan.epsilon())
  {
    // Before the state's time: traced from the start, as without one. Every
    // process reads the same file and decides alike.
    return std::string();
  }
  if (error.empty())
  {
    const std::string difference = this->stateMismatch(state, shape, p);
    if (!difference.empty())
    {
      error = "Initial State File '" + config.initialStateFile +
        "' was saved by a trace that differs from this one: " + difference +
        ". Set the tracer and its input as they were when it was saved, or clear Initial "
        "State File to trace from the start.";
    }
  }
  if (error.empty() && !this->stepper().particles())
  {
    error = "Initial State File: the GPU engine cannot resume a saved state yet; set Engine to "
            "CPU to go on from it.";
  }
  if (error.empty())
  {
    const std::string refused = this->stepper().loadState(state.engine);
    if (!refused.empty())
    {
      error = "Initial State File '" + config.initialStateFile + "': " + refused + ".";
    }
  }
  if (this->Layout.distributed())
  {
    error = this->Layout.agree(error);
  }
  if (error.empty())
  {
    this->ResumedSteps = state.steps;
    this->ResumedTime = state.time;
  }
  return error;
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::showState(vtkPolyData* out)
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
  state.field = this->fieldValues();
  if (this->Layout.distributed())
  {
    const std::string error =
      this->Layout.agree(bpvtk::gatherStateElements(this->Layout.Controller, state.engine));
    if (!error.empty())
    {
      return Pass::fail(error);
    }
  }
  bpvtk::writeStatePolyData(state, this->Held.offset, out);
  out->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->dataTarget());
  return Pass();
}
