// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerPorts.h
 * @brief How the tracer's requests reach its ports and inputs: its three
 * outputs come from one execution, and its template and seed inputs are
 * asked for whole.
 *
 * Output 0 holds the elements, output 1 the FTLE map of a lattice release
 * (TracerFtleMap.h), output 2 the trace's state (TracerState.h), output 3
 * the events at the field's sides (TracerInteractions.h). One execution
 * fills the elements, the map and the events: the port asked for gives the
 * time and pieces, and the others are asked alike, so that a consumer of
 * another port at the same time finds it up to date. The State output is
 * filled only when it is the port asked for (markNotGenerated): playing
 * the animation pays nothing for it, while ParaView's Apply and a script's
 * UpdatePipeline, which ask for every port, pay a copy of the engine's
 * state (and under MPI its gather to process 0; for the GPU display that
 * showed the elements, a read-back of its textures), with no step.
 */
#ifndef BoundParticles_TracerPorts_h
#define BoundParticles_TracerPorts_h

#include <string>

class vtkInformation;
class vtkInformationVector;

namespace bpvtk
{

/// The tracer's output ports.
enum TracerPort
{
  ElementsPort = 0,
  FtleMapPort = 1,
  StatePort = 2,
  InteractionsPort = 3,
  TracerPortCount = 4
};

/// The output port a request came from (the elements' when it names none).
int askedPort(vtkInformation* request);

/// Every other output asked for what the port `port` was asked for: the
/// time and the pieces.
void askOthersAlike(vtkInformationVector* outputs, int port);

/// `other` asked for the time and pieces `asked` was asked for.
void askAlike(vtkInformation* asked, vtkInformation* other);

/**
 * REQUEST_DATA_NOT_GENERATED: an execution for the elements (or the map)
 * leaves the State output not generated, so that a later request for it
 * (a writer's) executes again; one for the State output fills it alone and
 * leaves the others not generated (they keep what they hold). ParaView
 * updates every port of a source it updates (vtkSMSourceProxy::
 * UpdatePipeline), so the state is made then too: a copy of the engine's
 * state, without a step. The Interactions output is left not generated too
 * by an execution for another port while nothing consumes it (fillsInteractions).
 */
/// With `interactionsOnly` (an update that fills the Interactions output
/// alone, vtkBoundParticleTracerInternals::interactionsOnly) every other
/// output is left not generated.
void markNotGenerated(
  vtkInformation* request, vtkInformationVector* outputs, bool interactionsOnly = false);

/**
 * After a failed execution (its error said): the State output emptied when
 * it was the port asked for (the others keep what they hold); else every
 * output emptied and marked generated, the State and Interactions outputs
 * too, so that the requests ParaView makes of the other ports in the same
 * update (vtkSMSourceProxy::UpdatePipeline asks each) find them up to date
 * instead of executing again to say the same error. A change of the filter
 * or its input, or another time, executes again and says it again. The
 * State output emptied holds the failure `why` as its note (writeStateNote),
 * so a state saved from it says why it holds none when it is resumed.
 */
void markFailedUpdate(
  vtkInformation* request, vtkInformationVector* outputs, const std::string& why);

/**
 * Whether an execution fills the Interactions output: it is the port asked
 * for, or it has a consumer (a display, a filter, a writer, a fetch). So
 * playing the animation with no consumer of it builds nothing for it: it keeps
 * what it holds, not generated, and a later request for it executes again
 * (markNotGenerated).
 */
bool fillsInteractions(vtkInformation* request, vtkInformationVector* outputs);

/**
 * The template (input 1), seed (input 2) and Surfaces (input 3) connections asked for whole on
 * every process, and without the GPU display's request; a time-varying one
 * at the trace's start `startTime` when `hasTimes`, a steady one at no time.
 */
void requestWholeInputs(vtkInformationVector** inputs, bool hasTimes, double startTime);

} // namespace bpvtk

#endif
