// SPDX-License-Identifier: BSD-3-Clause
#include "WorkQueue.h"

namespace bp
{

std::string WorkQueue::configure(const ElementTemplate& shape, const Parameters& parameters)
{
  const std::string error = Engine::validate(shape, parameters);
  if (!error.empty())
  {
    return error;
  }
  // The engine starts again: nothing recorded before matters.
  this->Pending.clear();
  EngineCall call;
  call.kind = EngineCall::Kind::Configure;
  call.shape = std::make_shared<const ElementTemplate>(shape);
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
    this->cursor.showsPartialStep = false;
  }
  if (news.losses() != this->SettledLosses)
  {
    this->SettledLosses = news.losses();
    this->cursor.valid = false;
  }
}

void RendererReportWriter::stoppedAt(double committed)
{
  EngineStateNews& news = this->Queue->Report.engineState;
  if (this->Queue->hasPending())
  {
    this->Queue->clear();
    ++news.Losses;
    return;
  }
  news.StoppedAt = committed;
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
