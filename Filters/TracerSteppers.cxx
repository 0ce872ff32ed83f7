// SPDX-License-Identifier: BSD-3-Clause
#include "TracerSteppers.h"

#include "BoundParticleWorkQueues.h"
#include "TracerParallel.h"
#include "vtkBoundParticleTracer.h"

#include "vtkInformation.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkSMPTools.h"

namespace bpvtk
{
bp::RangeRunner smpRunner()
{
  return [](std::size_t count, const bp::RangeFunction& f)
  {
    vtkSMPTools::For(vtkIdType(0), vtkIdType(count),
      [&f](vtkIdType begin, vtkIdType end) { f(std::size_t(begin), std::size_t(end)); });
  };
}

TracerSteppers::TracerSteppers()
  : Cpu(smpRunner())
{
}

void TracerSteppers::select(bool gpu, vtkInformation* outInfo, const PieceLayout& pieces)
{
  this->Queue = nullptr;
  // The GPU engine's state lives in the GL context that draws it: only a
  // display in this process, in a run of one process, can take it.
  if (gpu && !pieces.distributed() && outInfo->Has(vtkBoundParticleTracer::GPU_WORK_QUEUE()))
  {
    this->Queue = FindWorkQueue(outInfo->Get(vtkBoundParticleTracer::GPU_WORK_QUEUE()));
  }
  if (pieces.distributed() && !this->Distributed)
  {
    this->Distributed.reset(new bp::DistributedStepper(smpRunner(), pieces.exchange()));
  }
  this->Active = this->Queue ? static_cast<bp::Stepper*>(this->Queue.get())
    : pieces.distributed()   ? static_cast<bp::Stepper*>(this->Distributed.get())
                             : &this->Cpu;
}

std::string TracerSteppers::fallBackIfTooLarge(
  const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  if (!this->Queue || bp::Engine::validate(shape, p) != "")
  {
    return std::string();
  }
  const bp::ParticleLayout layout =
    bp::ParticleLayout::of(p.numberOfElements, shape.particleCount());
  const int maxSize = this->Queue->maxTextureSize;
  if (maxSize <= 0 || (layout.width <= maxSize && layout.height <= maxSize))
  {
    return std::string();
  }
  // The display falls back to the CPU result, from this update on.
  const std::string message = std::to_string(p.numberOfElements) + " elements of " +
    std::to_string(shape.particleCount()) + " particles need a " + std::to_string(layout.width) +
    " x " + std::to_string(layout.height) + " GPU state texture, beyond this GPU's limit of " +
    std::to_string(maxSize) +
    " texels; the CPU engine runs this trace instead. Use fewer elements to run it on the GPU.";
  this->Queue->clear();
  this->Queue->cursor.valid = false;
  this->Queue->failure = message;
  this->Queue = nullptr;
  this->Active = &this->Cpu;
  return message;
}

void TracerSteppers::invalidate()
{
  this->Cpu.cursor.valid = false;
  if (this->Distributed)
  {
    this->Distributed->cursor.valid = false;
  }
  if (this->Queue)
  {
    this->Queue->clear();
    this->Queue->cursor.valid = false;
  }
}

} // namespace bpvtk
