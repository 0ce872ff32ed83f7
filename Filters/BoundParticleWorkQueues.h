// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BoundParticleWorkQueues.h
 * @brief The process's one registry of GPU work queues.
 *
 * A Bound Particles display makes a queue and puts its id into its input
 * request (vtkBoundParticleTracer::GPU_WORK_QUEUE); the tracer finds the
 * queue by that id and records its engine calls into it (Core/Stepping/WorkQueue.h).
 * Only the display gets the queue's report writer (bp::RendererReportWriter),
 * with the queue it makes; the tracer reads the report `const`.
 * Kept in the Filters module so that every library of the plugin sees the
 * same registry. The registry holds queues weakly (a tracer holds the one it
 * records into until its next update), so a queue lives about as long as its
 * display.
 */
#ifndef BoundParticleWorkQueues_h
#define BoundParticleWorkQueues_h

#include "BoundParticlesFiltersModule.h" // for export macro

#include "WorkQueue.h" // for bp::DisplayWorkQueue

#include <memory>

namespace bpvtk
{
/// A new queue with an id no live queue has, with its report's one writer:
/// for the display that asks the tracer to record into it.
BOUNDPARTICLESFILTERS_EXPORT bp::DisplayWorkQueue NewWorkQueue();
/// The live queue with this id, or null: for the tracer that records into it.
BOUNDPARTICLESFILTERS_EXPORT std::shared_ptr<bp::WorkQueue> FindWorkQueue(int id);
}

#endif
