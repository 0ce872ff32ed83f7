// SPDX-License-Identifier: BSD-3-Clause
#include "WorkQueue.h"

#include <algorithm>
#include <cctype>

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

void WorkQueue::stoppedAt(double committed)
{
  if (!this->Pending.empty())
  {
    this->Pending.clear();
    this->cursor.valid = false;
    return;
  }
  this->cursor.committed = committed;
  this->cursor.showsPartialStep = false;
}

RendererKind rendererKind(const std::string& glRenderer)
{
  std::string name(glRenderer.size(), ' ');
  std::transform(glRenderer.begin(), glRenderer.end(), name.begin(),
    [](unsigned char c) { return char(std::tolower(c)); });
  if (name.empty())
  {
    return RendererKind::Unknown;
  }
  for (const char* software :
    { "llvmpipe", "softpipe", "swrast", "software rasterizer", "swiftshader", "lavapipe" })
  {
    if (name.find(software) != std::string::npos)
    {
      return RendererKind::Software;
    }
  }
  return RendererKind::Hardware;
}

bool usesGpuEngine(EngineChoice choice, RendererKind renderer)
{
  return choice == EngineChoice::Gpu ||
    (choice == EngineChoice::Automatic && renderer == RendererKind::Hardware);
}

std::string automaticOnCpuNote(const std::string& rendererName)
{
  return "Bound Particle Tracer: Engine is Automatic and this render window draws with a "
         "software renderer (" +
    rendererName +
    "), on which the GPU engine is slower: the CPU engine traces. Set Engine to GPU to use the "
    "GPU engine anyway.";
}

} // namespace bp
