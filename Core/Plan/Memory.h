// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Memory.h
 * @brief How much a trace or a field will take, and whether this process can
 * have it, so that a size nobody can hold is refused with a message before
 * anything is allocated (an allocation that fails inside VTK aborts).
 */
#ifndef BoundParticles_Memory_h
#define BoundParticles_Memory_h

#include "ElementTemplate.h"
#include "Engine.h"

#include <cstddef>
#include <string>

namespace bp
{

/// The bytes this process can still allocate: the smaller of the machine's
/// physical memory and the address-space limit (ulimit -v) less what the
/// process maps already.
double allocatableBytes();

/// About what a trace of `shape` with `p` takes: the engine's state and its
/// saved copy, and the output's points, arrays and cells.
double traceBytes(const ElementTemplate& shape, const Parameters& p);

/// Empty when `bytes` fit in allocatableBytes(); otherwise a message that
/// names `what` and both sizes.
std::string checkAllocatable(double bytes, const std::string& what);

/**
 * Hands the memory freed in this process back to the system where the C
 * library keeps it (glibc keeps freed blocks below its dynamic mmap
 * threshold in its heap, so after a deleted trace of 200,000 Strip16
 * elements the process still held 470 MiB of a trace that was gone, and the
 * memory meter said so); nothing elsewhere. Call it after freeing a trace.
 */
void returnFreedMemory();

} // namespace bp

#endif
