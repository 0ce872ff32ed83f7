// SPDX-License-Identifier: BSD-3-Clause
#include "WorkQueue.h"

namespace bp
{
std::string EngineCall::applyTo(Stepper& target) const
{
  switch (this->kind)
  {
    case Kind::Configure:
      return target.configure(*this->shape, this->parameters);
    case Kind::SetField:
      return target.setField(*this->field);
    case Kind::Initialize:
      target.initialize(this->t);
      break;
    case Kind::Step:
      target.step(this->t, this->h);
      break;
    case Kind::Save:
      target.save();
      break;
    case Kind::Restore:
      target.restore();
      break;
  }
  return std::string();
}

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

std::vector<EngineCall> WorkQueue::take()
{
  std::vector<EngineCall> calls;
  calls.swap(this->Pending);
  return calls;
}

} // namespace bp
