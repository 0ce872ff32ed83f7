// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerInteractions.h
 * @brief The tracer's fourth output: the events at the field's sides
 * (Core/Engine/Interactions.h; engine specification 2.9) from the trace's
 * start, or the Initial State it resumed, to the time shown.
 *
 * One vertex per event at the point where it happened (world coordinates),
 * with the point arrays ElementId, ParticleIndex (-1 for the whole element),
 * Time (the data's time at the end of the step it happened in; for a
 * surface's passage, when the element's centre crossed it), ElementVelocity
 * (the element's mean velocity over that step, per time of the data),
 * Normal (the outward normal of the side or face of the cells outside the
 * flow met, 0 for an element that left into a cell outside the flow; the
 * surface's own normal for a passage), SurfaceId (the box's sides
 * 0..5 = -x, +x, -y, +y, -z, +z, -1 for none; 6 + the block's index for a
 * surface of the Surfaces input), SurfaceCell (the Surfaces input's cell
 * passed, -1 for a side) and Interaction (bp::Interaction: 0 Released,
 * 1 Terminated, 2 Stuck, 3 Slid, 4 Bounced, 5 Passed), whose names the field data array
 * InteractionNames holds in that order. The events are in the trace's
 * order: by the trace time of their step (so Time decreases in a backward
 * trace), then ElementId, ParticleIndex and Interaction, on any number of
 * processes alike.
 * The CPU engine records them; for a GPU display's trace the output is empty.
 */
#ifndef BoundParticles_TracerInteractions_h
#define BoundParticles_TracerInteractions_h

#include "Interactions.h"

#include "vtkType.h"

#include <array>
#include <memory>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace bpvtk
{

/**
 * The Interactions output of one tracer, kept between updates: fill() puts
 * a log's events in an output (engine coordinates and trace time): points
 * at `offset` + position, times through the trace's `backward` mirror (and
 * velocities negated for it). Where the log only grew since the last fill
 * (InteractionLog::eventsSince, the same offset and direction), only the
 * new steps' events are appended, so showing the output while playing
 * costs the events added, not the whole trace each update; otherwise (a
 * copy gone back in time, a new trace) it is built again.
 *
 * With a `controller` of several processes, each process's events go to
 * process 0, which gets them all and the others an empty output:
 * collective, every process's calls alike. What is gathered is bounded:
 * at most the log's capacity in all (capped so that no count overflows an
 * int), the first steps' events; where a step's events pass the bound, its
 * share is divided evenly among the processes that have some, and
 * clipped() says so.
 */
class InteractionsOutput
{
public:
  void fill(vtkPolyData* out, const bp::InteractionLog& log, const std::array<double, 3>& offset,
    bool backward, vtkMultiProcessController* controller);
  /// Whether a fill left events out for the bound on what is gathered
  /// (alike on every process; never in a serial run, whose log is the bound).
  bool clipped() const { return this->Clipped; }
  /// How many events the output holds (process 0's in a distributed run,
  /// alike on every process).
  vtkIdType size() const { return this->Count; }
  /// The next fill builds the output anew.
  void clear();

private:
  /// fill() in a distributed run: the events added since the last fill
  /// (`shared` of the last log's kept) gathered on process 0.
  void gather(const bp::InteractionLog& log, bool same, std::size_t shared,
    std::vector<bp::InteractionEvent>& added, const std::array<double, 3>& offset, bool backward,
    vtkMultiProcessController* controller);

  struct Arrays;
  std::shared_ptr<Arrays> Data;
  bp::InteractionLog::Mark Mark;
  std::array<double, 3> Offset = { 0, 0, 0 };
  bool Backward = false;
  bool Filled = false;
  bool Clipped = false;
  vtkIdType Count = 0;
};

} // namespace bpvtk

#endif
