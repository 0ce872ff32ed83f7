// SPDX-License-Identifier: BSD-3-Clause
#include "TracerSteppers.h"

#include "Surfaces.h"

#include "BoundParticleWorkQueues.h"
#include "TracerParallel.h"

#include "ParticleLayout.h"
#include "vtkSMPTools.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

namespace bpvtk
{
namespace
{
/// The process runs vtkSMPTools sequentially only because that is the build's
/// default (Debian's VTK), not because the user asked for it.
bool sequentialByDefault()
{
  const char* backend = vtkSMPTools::GetBackend();
  return !std::getenv("VTK_SMP_BACKEND_IN_USE") && backend && std::string(backend) == "Sequential";
}

/// The threads the STDThread backend would use: VTK_SMP_MAX_THREADS, else
/// one per core.
int threadsPerCore()
{
  const char* max = std::getenv("VTK_SMP_MAX_THREADS");
  const int asked = max ? std::atoi(max) : 0;
  return asked > 0 ? asked : std::max(1, int(std::thread::hardware_concurrency()));
}

/**
 * Whether the loops run through vtkSMPTools rather than the core's pool:
 * where that was measured as fast (bench/smp_loops.py, docs/performance.md),
 * that is VTK's TBB backend (VTK 9.3 and later; Debian forky's default). On
 * VTK 9.2 every loop starts and joins threads; VTK 9.3's persistent STDThread
 * backend still took 27% longer over a 4,096-element update than the pool;
 * and the Sequential backend, Debian's default up to trixie, has one thread.
 * BOUNDPARTICLES_SMP_LOOPS=pool or =vtk overrides this (for benchmarks).
 */
bool useVtkLoops()
{
  const char* pick = std::getenv("BOUNDPARTICLES_SMP_LOOPS");
  if (pick && std::string(pick) == "pool")
  {
    return false;
  }
  if (pick && std::string(pick) == "vtk")
  {
    return true;
  }
  const char* backend = vtkSMPTools::GetBackend();
  return VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0) && backend &&
    std::string(backend) == "TBB";
}

/// Ranges through vtkSMPTools::For. A throw must not leave a worker thread
/// (std::terminate): the first is kept and rethrown once every range ended.
void smpFor(std::size_t count, const bp::RangeFunction& f)
{
  std::exception_ptr first;
  std::mutex firstLock;
  vtkSMPTools::For(0, vtkIdType(count),
    [&](vtkIdType begin, vtkIdType end)
    {
      try
      {
        f(std::size_t(begin), std::size_t(end));
      }
      catch (...)
      {
        const std::lock_guard<std::mutex> lock(firstLock);
        first = first ? first : std::current_exception();
      }
    });
  if (first)
  {
    std::rethrow_exception(first);
  }
}

} // namespace

void SmpPool::refresh()
{
  // VTK 9.2 asks the system for its processors on every call (a file read):
  // at most once a second.
  const auto now = std::chrono::steady_clock::now();
  if (this->Current->threads > 0 && now - this->Checked < std::chrono::seconds(1))
  {
    return;
  }
  this->Checked = now;
  const bool byDefault = sequentialByDefault();
  const int threads =
    byDefault ? threadsPerCore() : std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  const bool vtkLoops = useVtkLoops();
  if (threads != this->Current->threads || vtkLoops != this->Current->vtkLoops)
  {
    this->Current->threads = threads;
    this->Current->vtkLoops = vtkLoops;
    this->Current->run = vtkLoops ? bp::RangeRunner(smpFor) : bp::poolRunner(unsigned(threads));
  }
}

bp::RangeRunner SmpPool::runner() const
{
  return [state = this->Current](std::size_t count, const bp::RangeFunction& f)
  { state->run(count, f); };
}

TracerSteppers::TracerSteppers()
  : Cpu(Pool.runner())
{
}

void TracerSteppers::select(bp::EngineChoice engine, int gpuQueue, const PieceLayout& pieces)
{
  this->Pool.refresh(); // once an update: the user may have changed the thread count
  this->Queue = nullptr;
  // The GPU engine's state lives in the GL context that draws it: only a
  // display in this process, in a run of one process, can take it.
  if (engine != bp::EngineChoice::Cpu && !pieces.distributed() && gpuQueue != 0)
  {
    this->Queue = FindWorkQueue(gpuQueue);
  }
  if (this->Queue)
  {
    // Where the display's renderer stopped (an abort) or lost the state:
    // this decision starts from there.
    this->Queue->settleCursor();
    // The display says why Automatic traces on the CPU engine: it learns its
    // renderer when it first draws, maybe after this update.
    const bool gpu = bp::usesGpuEngine(engine, this->Queue->report().renderer);
    this->Queue->setAutomaticOnCpu(!gpu);
    if (!gpu)
    {
      this->Queue = nullptr;
    }
  }
  if (pieces.distributed() && !this->Distributed)
  {
    this->Distributed.reset(
      new bp::DistributedStepper(this->Pool.runner(), pieces.exchange(), pieces.releaseMask()));
  }
  this->Active = this->Queue ? static_cast<bp::Stepper*>(this->Queue.get())
    : pieces.distributed()   ? static_cast<bp::Stepper*>(this->Distributed.get())
                             : &this->Cpu;
}

std::string TracerSteppers::fallBackIfTooLarge(
  const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  // The tracer has validated shape and parameters already.
  if (!this->Queue)
  {
    return std::string();
  }
  const int maxSize = this->Queue->report().maxTextureSize;
  std::string limit =
    maxSize > 0 ? bp::gpuTextureError(shape, p.numberOfElements, maxSize) : std::string();
  if (limit.empty() && p.surfaces)
  {
    // The GPU engine tests each element's step against every Outlet triangle
    // (gates change nothing in a step: they record, and it records nothing),
    // and each particle's (or element's) against every Wall triangle.
    limit = bp::gpuOutletError(p.surfaces->outletCorners().size() / 9);
  }
  if (limit.empty() && p.surfaces)
  {
    limit = bp::gpuWallError(p.surfaces->wallCorners().size() / 9);
  }
  if (limit.empty())
  {
    return std::string();
  }
  // The display, given a CPU trace for its GPU request, draws the CPU result
  // until a property changes (vtkBoundParticleRepresentation's CpuAnswer).
  std::string message = limit + "; the CPU engine runs this trace instead.";
  message[0] = char(std::toupper(static_cast<unsigned char>(message[0])));
  this->Queue->clear();
  this->Queue->cursor.valid = false;
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
