// SPDX-License-Identifier: BSD-3-Clause
#include "EngineCall.h"

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
    case Kind::SetEmitter:
      target.setEmitter(this->parameters.emitterMin, this->parameters.emitterMax);
      break;
    case Kind::KeepCheckpoint:
      target.keepCheckpoint(this->steps, this->t);
      break;
    case Kind::ResumeCheckpoint:
      target.resumeCheckpoint(this->steps);
      break;
    case Kind::DropCheckpoints:
      target.dropCheckpoints();
      break;
    case Kind::LoadState:
      return target.loadState(*this->state);
  }
  return std::string();
}

} // namespace bp
