// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerSteppers.h
 * @brief The tracer's steppers (Core/Stepping/Stepper.h) and which one an update uses.
 *
 * The CPU engine in this process; a piece of a distributed run; or, when the
 * Engine property is GPU and the request comes from a Bound Particles display
 * in this process, that display's work queue, which records the calls for
 * the GPU engine in its render window. Each keeps its own cursor, so a trace
 * for the display and one for any other consumer never mix.
 */
#ifndef BoundParticles_TracerSteppers_h
#define BoundParticles_TracerSteppers_h

#include "ElementTemplate.h"
#include "Engine.h"
#include "EngineChoice.h"
#include "Stepper.h"
#include "WorkQueue.h"

#include <chrono>
#include <memory>
#include <string>

namespace bpvtk
{
class PieceLayout;

/**
 * Runs the tracer's parallel loops (the engine's and the output's) on
 * threads, without changing the process's SMP backend for anyone else.
 *
 * Which threads: the process's backend and thread count (vtkSMPTools), except
 * that a process on the Sequential backend only because it is Debian's
 * default (VTK_SMP_BACKEND_IN_USE unset) still gets one thread per core for
 * these loops, as the STDThread backend would give.
 *
 * How: through vtkSMPTools where the process's backend is TBB (VTK 9.3 and
 * later), else through a pool of persistent threads of the core's
 * (bp::poolRunner), measured side by side (bench/smp_loops.py): VTK 9.2's
 * STDThread backend starts and joins its threads in every loop, which cost a
 * 4,096-element update more than its engine step (issue 16), and VTK 9.3's
 * persistent STDThread backend still took 27% longer over such an update;
 * with TBB both take the same time. The pool can go once the ParaView
 * versions this plugin supports default to TBB (6.x on Debian forky does).
 * BOUNDPARTICLES_SMP_LOOPS=pool or =vtk picks one (benchmarks).
 */
class SmpPool
{
public:
  SmpPool() { this->refresh(); }
  /// Follows a change of vtkSMPTools' backend or thread count (call between
  /// loops; it looks at most once a second).
  void refresh();
  /// Runs ranges as the last refresh() decided.
  bp::RangeRunner runner() const;

private:
  struct State
  {
    int threads = 0;
    bool vtkLoops = false;
    bp::RangeRunner run;
  };
  std::shared_ptr<State> Current = std::make_shared<State>();
  std::chrono::steady_clock::time_point Checked;
};

class TracerSteppers
{
public:
  TracerSteppers();

  /// Picks this update's stepper for a request to a tracer whose Engine
  /// property is `engine` (bp::usesGpuEngine() with the renderer of the
  /// display that asked): `gpuQueue` is the work queue a Bound Particles
  /// display asked for (vtkBoundParticleTracer::GPU_WORK_QUEUE; 0: none).
  /// The queue's cursor first takes in what its display recorded since
  /// (bp::WorkQueue::settleCursor: a run stopped short, a state lost).
  void select(bp::EngineChoice engine, int gpuQueue, const PieceLayout& pieces);

  bp::Stepper& active() { return *this->Active; }
  /// The display's queue when this update records for it, else null.
  bp::WorkQueue* queue() { return this->Queue.get(); }

  /**
   * Before a replay configures the active stepper: when it records for a
   * display whose GPU cannot hold this system, or more Outlet or Wall
   * triangles than the GPU engine tests (bp::gpuOutletError,
   * bp::gpuWallError), gives the display the reason and takes the CPU
   * engine instead. Returns the message to show (empty when nothing changed).
   */
  std::string fallBackIfTooLarge(const bp::ElementTemplate& shape, const bp::Parameters& p);

  /// Forgets every stepper's trace and any pending GPU work.
  void invalidate();

  /// The distributed stepper (valid while the pieces are distributed).
  bp::DistributedStepper& distributed() { return *this->Distributed; }

  /// What runs the engines' parallel loops, for the output's as well.
  bp::RangeRunner runner() const { return this->Pool.runner(); }

private:
  SmpPool Pool; // before the steppers, which take its runner
  bp::CpuStepper Cpu;
  std::unique_ptr<bp::DistributedStepper> Distributed;
  std::shared_ptr<bp::WorkQueue> Queue;
  bp::Stepper* Active = &Cpu;
};

} // namespace bpvtk

#endif
