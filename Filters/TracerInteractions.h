// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerInteractions.h
 * @brief The tracer's fourth output: the events at the field's sides
 * (Core/Engine/Interactions.h; engine specification 2.9) from the trace's
 * start, or the Initial State it resumed, to the time shown.
 *
 * One vertex per event at the point where it happened (world coordinates),
 * with the point arrays ElementId, ParticleIndex (-1 for the whole element),
 * Time (the data's time at the end of the step it happened in), ElementVelocity
 * (the element's mean velocity over that step, per time of the data),
 * Normal (the outward normal of the side met; 0 for a cell outside the
 * flow), SurfaceId (the box's sides 0..5 = -x, +x, -y, +y, -z, +z, -1 for
 * none; ids from 6 up are kept for surfaces given as an input, a later
 * stage) and Interaction (bp::Interaction: 0 Released, 1 Terminated,
 * 2 Stuck, 3 Slid, 4 Bounced), whose names the field data array
 * InteractionNames holds in that order. The events are ordered by (Time,
 * ElementId, ParticleIndex, Interaction), on any number of processes alike.
 * The CPU engine records them; for a GPU display's trace the output is empty.
 */
#ifndef BoundParticles_TracerInteractions_h
#define BoundParticles_TracerInteractions_h

#include "Interactions.h"

#include <array>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace bpvtk
{

/**
 * Fills `out` with `events` (engine coordinates and trace time): points at
 * `offset` + position, times through the trace's `backward` mirror (and
 * velocities negated for it). With a `controller` of several processes,
 * each process's events go to process 0, which gets them all and the
 * others an empty output: collective.
 */
void fillInteractions(vtkPolyData* out, std::vector<bp::InteractionEvent> events,
  const std::array<double, 3>& offset, bool backward, vtkMultiProcessController* controller);

} // namespace bpvtk

#endif
