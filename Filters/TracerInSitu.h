// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerInSitu.h
 * @brief Whether the tracer's input offers only its present time step.
 *
 * In situ the input holds one time step and the next arrives later: Catalyst's
 * producer (a trivial producer, which lists every time it was given but holds
 * only the last step's data), or any source that flags its output with
 * `vtkStreamingDemandDrivenPipeline::NO_PRIOR_TEMPORAL_ACCESS` (VTK 9.3 on,
 * ParaView 5.12 on). Such an input is traced one step at a time
 * (bp::StreamTimeLine), never asked for a past time.
 */
#ifndef BoundParticles_TracerInSitu_h
#define BoundParticles_TracerInSitu_h

#include <vector>

class vtkInformation;

namespace bpvtk
{

/// Whether the input described by `inInfo` offers only its present time step.
bool offersOnlyPresent(vtkInformation* inInfo);

/// The input's present time: the last of its time values (a trivial producer
/// lists them oldest first), else its data's time, else 0.
double presentTime(vtkInformation* inInfo);

/// The image grid the input announces (whole extent, origin, spacing), as
/// numbers to compare step with step; empty where it announces none. The
/// origin and spacing are left out where the input's piece has no points
/// (under MPI a process may hold none: they are VTK's defaults there).
std::vector<double> announcedGrid(vtkInformation* inInfo);

/// Whether the grid announced `now` differs from the one `before`
/// (announcedGrid): the whole extent, and the origin and spacing where both
/// hold them.
bool gridChanged(const std::vector<double>& before, const std::vector<double>& now);

} // namespace bpvtk

#endif
