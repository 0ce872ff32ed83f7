// SPDX-License-Identifier: BSD-3-Clause
#include "GpuStepper.h"

namespace bp
{

std::string GpuStepper::configure(const ElementTemplate& shape, const Parameters& parameters)
{
  return this->Gpu.configure(shape, parameters);
}

std::string GpuStepper::setField(const VectorField& field)
{
  return this->Gpu.setField(field);
}

void GpuStepper::initialize(double startTime)
{
  this->Gpu.initialize(startTime);
}

void GpuStepper::step(double t, double h)
{
  this->Gpu.step(t, h);
}

void GpuStepper::save()
{
  this->Gpu.saveState();
}

void GpuStepper::restore()
{
  this->Gpu.restoreState();
}

} // namespace bp
