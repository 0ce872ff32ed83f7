// SPDX-License-Identifier: BSD-3-Clause
#include "GpuStepper.h"

namespace bp
{

std::string GpuStepper::configure(const ElementTemplate& shape, const Parameters& parameters)
{
  // A display colours by the pose arrays whatever the tracer's Output
  // Arrays hold: the GPU engine fits poses always (one pass per element).
  Parameters p = parameters;
  p.trackPoses = true;
  // The engine's configure drops its checkpoints.
  this->Checkpoints.clear();
  this->cursor.showsPartialStep = false;
  return this->Gpu.configure(shape, p);
}

std::string GpuStepper::setField(const VectorField& field)
{
  return this->Gpu.setField(field);
}

void GpuStepper::initialize(double startTime)
{
  this->Gpu.initialize(startTime);
  this->cursor.showsPartialStep = false;
}

void GpuStepper::step(double t, double h)
{
  this->Gpu.step(t, h);
}

void GpuStepper::save()
{
  this->Gpu.saveState();
  this->cursor.showsPartialStep = true; // the short step the tracer shows follows
}

void GpuStepper::restore()
{
  this->Gpu.restoreState();
  this->cursor.showsPartialStep = false;
}

void GpuStepper::setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max)
{
  this->Gpu.setEmitter(min, max);
}

bool GpuStepper::committedState(EngineState& state)
{
  return this->readCommittedState(state).empty();
}

std::string GpuStepper::readCommittedState(EngineState& state) const
{
  return this->Gpu.readState(state, this->cursor.showsPartialStep);
}

std::string GpuStepper::loadState(const EngineState& state)
{
  const std::string error = this->Gpu.loadState(state);
  if (error.empty())
  {
    this->cursor.showsPartialStep = false;
  }
  return error;
}

void GpuStepper::keepCheckpoint(long long steps, double time)
{
  this->Gpu.keepCheckpoint(steps);
  this->Checkpoints.add(steps, time);
}

void GpuStepper::resumeCheckpoint(long long steps)
{
  if (!this->Checkpoints.has(steps) || !this->Gpu.resumeCheckpoint(steps))
  {
    return; // the plan resumes only from a copy it was told of
  }
  this->cursor.steps = steps;
  this->cursor.committed = this->Checkpoints.timeOf(steps);
  this->cursor.showsPartialStep = false;
}

void GpuStepper::dropCheckpoints()
{
  this->Gpu.dropCheckpoints();
  Stepper::dropCheckpoints();
}

} // namespace bp
