// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Parallel.h
 * @brief How the core runs a loop over elements in parallel without knowing VTK.
 *
 * The engine's work is split into ranges of elements that touch disjoint
 * memory. A RangeRunner decides how ranges are scheduled: the filter passes
 * poolRunner() below, or a runner on vtkSMPTools::For only where VTK's TBB
 * backend was measured as fast (Filters/TracerSteppers.cxx); the unit tests
 * pass serial or pool runners.
 */
#ifndef BoundParticles_Parallel_h
#define BoundParticles_Parallel_h

#include <cstddef>
#include <functional>

namespace bp
{

/// Processes items [begin, end).
using RangeFunction = std::function<void(std::size_t begin, std::size_t end)>;

/**
 * Calls the function on ranges that together cover [0, count) exactly once.
 *
 * If the function throws, the runners below wait until every range of the
 * call has ended, then rethrow the first exception on the calling thread (the
 * others are dropped), and stay usable: an allocation that fails in a loop
 * ends the update with a message instead of terminating the process. Every
 * range that did not throw has then been processed in full, one that threw up
 * to where it threw.
 */
using RangeRunner = std::function<void(std::size_t count, const RangeFunction&)>;

/// Runs the whole range on the calling thread; an exception simply propagates.
RangeRunner serialRunner();

/// Splits the range into contiguous chunks on a pool of `threads - 1`
/// persistent workers and the calling thread. The pool lives as long as the
/// returned runner (and its copies). A call made while the workers serve another (from inside a job,
/// or from another thread) runs on its caller alone. If fewer threads can be
/// started, the pool has as many chunks as it got threads.
RangeRunner poolRunner(unsigned threads);

} // namespace bp

#endif
