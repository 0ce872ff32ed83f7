// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BoundParticleWorkQueues.h
 * @brief The process's one registry of GPU work queues.
 *
 * A Bound Particles display makes a queue and puts its id into its input
 * request (vtkBoundParticleTracer::GPU_WORK_QUEUE); the tracer finds the
 * queue by that id and records its engine calls into it (Core/Stepping/WorkQueue.h).
 * Kept in the Filters module so that every library of the plugin sees the
 * same registry. The registry holds queues weakly (a tracer holds the one it
 * records into until its next update), so a queue lives about as long as its
 * display.
 */
#ifndef BoundParticleWorkQueues_h
#define BoundParticleWorkQueues_h

#include "BoundParticlesFiltersModule.h" // for export macro

#include <memory>

namespace bp
{
class WorkQueue;
}

namespace bpvtk
{
/// A new queue with an id no live queue has.
BOUNDPARTICLESFILTERS_EXPORT std::shared_ptr<bp::WorkQueue> NewWorkQueue();
/// The live queue with this id, or null.
BOUNDPARTICLESFILTERS_EXPORT std::shared_ptr<bp::WorkQueue> FindWorkQueue(int id);
}

#endif
