// SPDX-License-Identifier: BSD-3-Clause
#include "WorkQueue.h"

namespace bp
{
void WorkQueue::configure(const ElementTemplate& shape, const Parameters& parameters)
{
  EngineCall call;
  call.kind = EngineCall::Kind::Configure;
  call.shape = std::make_shared<const ElementTemplate>(shape);
  call.parameters = parameters;
  this->Pending.push_back(std::move(call));
}

void WorkQueue::setField(const VectorField& field)
{
  EngineCall call;
  call.kind = EngineCall::Kind::SetField;
  call.field = std::make_shared<const VectorField>(field);
  this->Pending.push_back(std::move(call));
}

void WorkQueue::initialize()
{
  EngineCall call;
  call.kind = EngineCall::Kind::Initialize;
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
