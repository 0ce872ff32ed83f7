// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ReplayHooks.h
 * @brief Where the GPU mapper's replay speaks: its progress to the display
 * ParaView listens to, its stop to VTK's abort request, the GPU engine's
 * messages to VTK's output window.
 *
 * vtkOpenGLBoundParticleMapper runs the work queue's calls inside a render
 * (QueueReplay); a replay from the start of a long trace takes seconds, so
 * it reports progress between steps and may be stopped there
 * (bp::ReplayProgress). These are the VTK ends of those hooks.
 */
#ifndef BoundParticles_ReplayHooks_h
#define BoundParticles_ReplayHooks_h

#include "ReplayProgress.h"

#include <functional>
#include <string>

class vtkAlgorithm;
class vtkOpenGLRenderWindow;

namespace bpvtk
{

/// Whether a GPU replay reports progress in this ParaView: not from 6.1 on,
/// whose GUI processes its events on every report (for its Abort button), so
/// that a report from inside a render never returned there (python.GUI hung
/// in Render). An abort request is still honoured between steps.
bool replayReportsProgress();

/// The replay's hooks: its progress goes to `owner` (the display that holds
/// the mapper), `stop` says whether to stop between two steps, and after a
/// report (whose listeners may have drawn in another window) `window` is made
/// current again.
bp::ReplayProgress::Hooks replayHooks(
  vtkAlgorithm* owner, vtkOpenGLRenderWindow* window, std::function<bool()> stop);

/// The GPU engine's messages (which path it runs, GpuPath.h) in VTK's output
/// window, where the tracer's own notes go: bp::setGpuMessageSink's sink.
void sayInOutputWindow(const std::string& text, bool warning);

} // namespace bpvtk

#endif
