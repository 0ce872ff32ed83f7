// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Parallel.h
 * @brief How the core runs a loop over elements in parallel without knowing VTK.
 *
 * The engine's work is split into ranges of elements that touch disjoint
 * memory. A RangeRunner decides how ranges are scheduled: the filter passes one
 * built on vtkSMPTools, the unit tests pass serial or std::thread runners.
 */
#ifndef BoundParticles_Parallel_h
#define BoundParticles_Parallel_h

#include <cstddef>
#include <functional>

namespace bp
{

/// Processes items [begin, end).
using RangeFunction = std::function<void(std::size_t begin, std::size_t end)>;

/// Calls the function on ranges that together cover [0, count) exactly once.
using RangeRunner = std::function<void(std::size_t count, const RangeFunction&)>;

/// Runs the whole range on the calling thread.
RangeRunner serialRunner();

/// Splits the range into contiguous chunks over `threads` std::threads,
/// started anew for every call (simple; costly for small ranges).
RangeRunner threadRunner(unsigned threads);

/// The same chunks on a pool of `threads - 1` persistent workers and the
/// calling thread. The pool lives as long as the returned runner (and its
/// copies). A call made while the workers serve another (from inside a job,
/// or from another thread) runs on its caller alone.
RangeRunner poolRunner(unsigned threads);

} // namespace bp

#endif
