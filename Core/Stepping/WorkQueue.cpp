// SPDX-License-Identifier: BSD-3-Clause
#include "WorkQueue.h"

#include "ParticleLayout.h"

#include <algorithm>

namespace bp
{

std::string WorkQueue::configure(const ElementTemplate& shape, const Parameters& parameters)
{
  const std::string error = Engine::validate(shape, parameters);
  if (!error.empty())
  {
    return error;
  }
  // The engine starts again: nothing recorded before matters, and the GPU
  // engine's configure drops its checkpoints.
  this->Pending.clear();
  this->Checkpoints.clear();
  Parameters gpu = parameters;
  gpu.trackPoses = true; // as GpuStepper::configure
  this->Configured = gpu;
  this->ConfiguredLayout = Engine::stateLayout(shape, gpu);
  this->ConfiguredShape = std::make_shared<const ElementTemplate>(shape);
  const double cpuBytes = 4.0 * double(Engine::recordWords(shape, gpu));
  const double elements = double(std::max<std::size_t>(parameters.numberOfElements, 1));
  this->CheckpointBytes = std::max(cpuBytes * elements,
    gpuCheckpointBytes(parameters.numberOfElements, shape.particleCount(), parameters.trailLength,
      carriesInertia(parameters)));
  EngineCall call;
  call.kind = EngineCall::Kind::Configure;
  call.shape = this->ConfiguredShape;
  call.parameters = parameters;
  this->Pending.push_back(std::move(call));
  return std::string();
}

std::string WorkQueue::setField(const VectorField& field)
{
  EngineCall call;
  call.kind = EngineCall::Kind::SetField;
  call.field = std::make_shared<const VectorField>(field);
  this->Pending.push_back(std::move(call));
  return std::string();
}

void WorkQueue::initialize(double startTime)
{
  EngineCall call;
  call.kind = EngineCall::Kind::Initialize;
  call.t = startTime;
  this->Pending.push_back(call);
}

void WorkQueue::step(double t, double h)
{
  EngineCall call;
  call.kind = EngineCall::Kind::Step;
  call.t = t;
  call.h = h;
  call.steps = this->cursor.steps; // the tracer counts the step once it is recorded
  this->Pending.push_back(call);
}

void WorkQueue::save()
{
  EngineCall call;
  call.kind = EngineCall::Kind::Save;
  this->Pending.push_back(call);
}

void WorkQueue::restore()
{
  EngineCall call;
  call.kind = EngineCall::Kind::Restore;
  this->Pending.push_back(call);
}

void WorkQueue::setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max)
{
  EngineCall call;
  call.kind = EngineCall::Kind::SetEmitter;
  call.parameters.emitterMin = min;
  call.parameters.emitterMax = max;
  this->Pending.push_back(call);
}

std::string WorkQueue::loadState(const EngineState& state)
{
  if (this->ConfiguredLayout.empty())
  {
    return "the GPU engine cannot resume a state before its system is configured";
  }
  std::string error = checkEngineState(state, this->ConfiguredLayout, this->Configured);
  if (error.empty())
  {
    error = gpuStateRefusal(state, this->Configured.numberOfElements);
  }
  if (!error.empty())
  {
    return error;
  }
  EngineCall call;
  call.kind = EngineCall::Kind::LoadState;
  call.state = std::make_shared<const EngineState>(state);
  this->Pending.push_back(std::move(call));
  return std::string();
}

std::string WorkQueue::readState(EngineState& state)
{
  if (!this->StateReader)
  {
    return "no display reads the GPU engine's state back";
  }
  if (!this->cursor.valid || !this->ConfiguredShape)
  {
    return "the GPU engine holds no trace";
  }
  return this->StateReader(state);
}

void WorkQueue::keepCheckpoint(long long steps, double time)
{
  EngineCall call;
  call.kind = EngineCall::Kind::KeepCheckpoint;
  call.steps = steps;
  call.t = time;
  this->Pending.push_back(call);
  this->Checkpoints.add(steps, time);
}

void WorkQueue::resumeCheckpoint(long long steps)
{
  if (!this->Checkpoints.has(steps))
  {
    return; // the plan resumes only from a copy it was told of
  }
  EngineCall call;
  call.kind = EngineCall::Kind::ResumeCheckpoint;
  call.steps = steps;
  this->Pending.push_back(call);
  this->cursor.steps = steps;
  this->cursor.committed = this->Checkpoints.timeOf(steps);
  this->cursor.showsPartialStep = false;
}

void WorkQueue::dropCheckpoints()
{
  EngineCall call;
  call.kind = EngineCall::Kind::DropCheckpoints;
  this->Pending.push_back(call);
  Stepper::dropCheckpoints();
}

std::vector<EngineCall> WorkQueue::take()
{
  std::vector<EngineCall> calls;
  calls.swap(this->Pending);
  return calls;
}

void WorkQueue::settleCursor()
{
  // Counts, not flags: the display writes them, the tracer only reads. A stop
  // moves the cursor to where the engine stands; a loss leaves it holding no
  // trace, whichever came first.
  const EngineStateNews& news = this->Report.engineState;
  if (news.stops() != this->SettledStops)
  {
    this->SettledStops = news.stops();
    this->cursor.committed = news.stoppedAt();
    this->cursor.steps = news.stoppedSteps();
    this->cursor.showsPartialStep = false;
    // Checkpoints recorded after the stop never ran.
    this->Checkpoints = news.heldAtStop();
  }
  if (news.losses() != this->SettledLosses)
  {
    this->SettledLosses = news.losses();
    this->cursor.valid = false;
    // The copies went with the GPU state: never resume from one.
    this->Checkpoints.clear();
  }
}

void RendererReportWriter::stoppedAt(double committed, long long steps, const CheckpointIndex& held)
{
  EngineStateNews& news = this->Queue->Report.engineState;
  if (this->Queue->hasPending())
  {
    this->Queue->clear();
    ++news.Losses;
    return;
  }
  news.StoppedAt = committed;
  news.StoppedSteps = steps;
  news.HeldAtStop = held;
  ++news.Stops;
}

void RendererReportWriter::stateLost()
{
  this->Queue->clear();
  ++this->Queue->Report.engineState.Losses;
}

DisplayWorkQueue newDisplayWorkQueue(int id, std::shared_ptr<WorkQueue>& recorder)
{
  recorder = std::make_shared<WorkQueue>(id);
  return DisplayWorkQueue{ recorder, RendererReportWriter(recorder) };
}

} // namespace bp
