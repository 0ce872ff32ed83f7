// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file RendererNotes.h
 * @brief What the Bound Particles display learns about its view's renderer,
 * and tells: the tracer (for Engine = Automatic, through the work queue's
 * report) and the user (once, in Output Messages).
 */
#ifndef BoundParticles_RendererNotes_h
#define BoundParticles_RendererNotes_h

class vtkPVRenderView;

namespace bp
{
class RendererReportWriter;
class WorkQueue;
}

namespace bpvtk
{

/// Tells the tracer (through the queue's report) what renderer the view draws
/// with, for Engine = Automatic: read once from the window's capabilities
/// after it first drew (before that the window may have no context).
void recordRenderer(vtkPVRenderView* view, bp::RendererReportWriter& writer);

/// Says once (`said`), in Output Messages, why Engine Automatic traces on the
/// CPU engine, as soon as the display knows it draws with a software renderer:
/// at the update where it knew before, else at the render that finds out.
void sayAutomaticOnCpu(bool automaticOnCpu, const bp::WorkQueue& queue, bool& said);

} // namespace bpvtk

#endif
