// SPDX-License-Identifier: BSD-3-Clause
// The Bound Particles display's GPU mapper (vtkOpenGLBoundParticleMapper.h):
// the VTK mapper's side of each render, from running the queued engine calls
// to the instanced draws. Its parts have files of their own, one role each:
//   GLStateGuard          GL state saved around the engine's passes
//   QueueReplay           the work queue's calls run on the GPU engine
//   ReplayHooks           where a replay's progress, stop and messages go
//   DrawTables            the template, link and corner tables of a configuration
//   DrawDeformation       the stretch fit's template side (ElementStretch, ElementFTLE)
//   ColorTableTexture     the lookup table as a texture
//   DrawSamplers          the draw shader's samplers on texture units
//   DrawShaders           the drawing code spliced into VTK's shaders
//   GridLocalCoordinates  camera matrices and clipping planes, grid-local
//   TrailFade             the trails' fade (shared with the CPU path)
#include "vtkOpenGLBoundParticleMapper.h"

#include "ColorTableTexture.h"
#include "DrawDeformation.h"
#include "DrawSamplers.h"
#include "DrawShaders.h"
#include "DrawTables.h"
#include "GLStateGuard.h"
#include "GpuEngine.h"
#include "GridLocalCoordinates.h"
#include "OutputArrays.h"
#include "QueueReplay.h"
#include "ReplayHooks.h"
#include "ReplayProgress.h"
#include "TrailFade.h"
#include "WorkQueue.h"

#include "vtkActor.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace
{
/// What a frame spends on uploading the next field time step: a 128^3
/// float time step (24 MiB) then arrives over a few frames on a software
/// renderer, in one or two on a GPU.
constexpr double StagingSecondsPerFrame = 0.004;

/// A run of at least this many steps measures the engine's rate
/// (RendererReport::particleStepsPerSecond).
constexpr long MeasuredRunSteps = 32;
} // namespace

struct vtkOpenGLBoundParticleMapper::vtkInternals
{
  bpvtk::QueueReplay Replay; ///< replays the recorded calls on the GPU engine
  bp::GpuEngine& Engine = Replay.engine();
  std::shared_ptr<const bp::WorkQueue> Queue;
  /// The display's report writer, lent with the queue: the mapper's only way
  /// to change the queue (take, stoppedAt, stateLost) or the report.
  bp::RendererReportWriter* Writer = nullptr;
  std::string LastError;
  std::uint64_t SamplesSerial = 0; // the draw serial the samples texture is for
  bp::GpuEngine::DrawInputs Inputs;
  double Particles = 0.0; ///< of the configured system, for the measured rate

  bp::ColorSource ScalarMode = bp::ColorSource::Solid;
  int Component = -1;
  int SizeLimit = 0; // a cap below GL_MAX_TEXTURE_SIZE, for tests

  bpvtk::ColorTableTexture ColorTable;

  /// A super set's links, per link its two element indices (RG32I, as many
  /// a row as fit); made once per configuration.
  bpvtk::IntegerTable LinkTable{ 2 };
  /// The template's own cells are lines (springs), not a stand-in for the links.
  bool TemplateLines = false;
  /// Binds no vertex arrays: the link draw's vertex IDs go beyond the template's
  /// vertex buffer, which its shader does not read anyway.
  vtkNew<vtkOpenGLVertexArrayObject> LinkVAO;

  /// Motion trails, from the configuration run: how many poses, how far apart
  /// in time; TrailSpan is their product, the oldest pose's age.
  int TrailLength = 0;
  double TrailInterval = 0.0;
  double TrailSpan = 0.0;
  /// The span the display's input expects (SetExpectedTrailSpan): ahead of
  /// the configuration run when the input changed.
  double ExpectedTrailSpan = 0.0;
  /// Per template particle, the triangles it is a corner of (cornerTable,
  /// RGBA32I); made once per configuration with trails.
  bpvtk::IntegerTable CornerTable{ 4 };
  /// The template's side of the stretch fit and the lifetime draw (colouring
  /// by ElementStretch or ElementFTLE); made once per configuration.
  bpvtk::DeformationTable Deformation;
  /// The trail poses of this frame's draw (chooseTrailPoses).
  std::vector<bpvtk::TrailPoseDraw> TrailPoses;

  /// The engine's and the tables' textures on units of their own while drawing.
  bpvtk::DrawSamplers Samplers;

  /// The camera matrices with the grid-local origin composed in
  /// (SetCameraShaderParameters; kept, not allocated per draw).
  vtkNew<vtkMatrix4x4> ModelToWorld;
  vtkNew<vtkMatrix4x4> ModelToView;
};

vtkStandardNewMacro(vtkOpenGLBoundParticleMapper);

vtkOpenGLBoundParticleMapper::vtkOpenGLBoundParticleMapper()
  : Internals(new vtkInternals)
{
  // Positions come from the engine's textures, grid-local, and the draw's own translation to world
  // coordinates goes into the camera matrices (SetCameraShaderParameters): VTK must not shift and
  // scale the template's buffer (which the shaders do not read) and fold that in as well.
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  this->SetScalarVisibility(0);
  bp::setGpuMessageSink(bpvtk::sayInOutputWindow);
}

vtkOpenGLBoundParticleMapper::~vtkOpenGLBoundParticleMapper() = default;

void vtkOpenGLBoundParticleMapper::SetWorkQueue(
  const std::shared_ptr<const bp::WorkQueue>& queue, bp::RendererReportWriter* writer)
{
  if (this->Internals->Queue != queue || this->Internals->Writer != writer)
  {
    this->Internals->Queue = queue;
    this->Internals->Writer = queue ? writer : nullptr;
    this->Modified();
  }
}

bool vtkOpenGLBoundParticleMapper::SetColorArray(const char* name, int component)
{
  vtkInternals& I = *this->Internals;
  const bp::OutputArray* row = name && *name ? bp::findOutputArray(name) : nullptr;
  const bool known = !(name && *name) || (row && row->color != bp::ColorSource::Solid);
  const bp::ColorSource mode = row ? row->color : bp::ColorSource::Solid;
  // A component of a vector source (Velocity, ElementSpin, Orientation), or
  // the magnitude; a one-component array's component is the array itself.
  const int comp = row && row->components > 1 && !row->colorsMagnitude && component >= 0 &&
      component < row->components
    ? component
    : -1;
  if (mode != I.ScalarMode || comp != I.Component)
  {
    I.ScalarMode = mode;
    I.Component = comp;
    this->Modified();
  }
  return known;
}

const std::string& vtkOpenGLBoundParticleMapper::GetLastError() const
{
  return this->Internals->LastError;
}

void vtkOpenGLBoundParticleMapper::SetTextureSizeLimit(int texels)
{
  this->Internals->SizeLimit = texels;
  this->Internals->Engine.setTextureSizeLimit(texels > 0 ? texels : (1 << 30));
}

double* vtkOpenGLBoundParticleMapper::GetBounds()
{
  const auto& queue = this->Internals->Queue;
  if (!queue || queue->draw().serial == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  else
  {
    std::copy(queue->draw().bounds.begin(), queue->draw().bounds.end(), this->Bounds);
  }
  return this->Bounds;
}

void vtkOpenGLBoundParticleMapper::SetExpectedTrailSpan(double span)
{
  vtkInternals& I = *this->Internals;
  if (I.ExpectedTrailSpan != span)
  {
    I.ExpectedTrailSpan = span;
    this->Modified();
  }
}

bool vtkOpenGLBoundParticleMapper::ColorMapIsTranslucent()
{
  if (!this->ScalarVisibility || this->Internals->ScalarMode == bp::ColorSource::Solid)
  {
    return false;
  }
  vtkScalarsToColors* lut = this->GetLookupTable();
  lut->Build();
  return lut->IsOpaque() == 0;
}

bool vtkOpenGLBoundParticleMapper::HasTranslucentPolygonalGeometry()
{
  // Trails fade, by the colour map's opacity or by the display's own. The
  // configuration queued for this frame has not run yet when VTK asks: the
  // input's expectation counts as well (one translucent frame too many when
  // trails are switched off, none too few when they are switched on).
  const vtkInternals& I = *this->Internals;
  return I.TrailSpan > 0.0 || I.ExpectedTrailSpan > 0.0 || this->ColorMapIsTranslucent();
}

bool vtkOpenGLBoundParticleMapper::TakeAbortRequest()
{
  // The one place that reads VTK's abort request: this mapper's AbortExecute,
  // else its container's (the display, whose flag ParaView 6.1's Abort button
  // sets with SetAbortExecuteAndUpdateTime), and through the container the
  // flags of the algorithms upstream that were set that way.
  if (!this->CheckAbort())
  {
    return false;
  }
  // VTK clears AbortOutput only when an algorithm next executes and never
  // clears AbortExecute (ParaView 6.1 clears a source's when it updates it,
  // never a display's). A render is not an execution: once honoured, the
  // request is taken here, or every later replay would stop at its first report.
  for (vtkAlgorithm* algorithm :
    { static_cast<vtkAlgorithm*>(this), this->GetContainerAlgorithm() })
  {
    if (algorithm)
    {
      algorithm->SetAbortExecute(0);
      algorithm->SetAbortOutput(false);
    }
  }
  return true;
}

bool vtkOpenGLBoundParticleMapper::ReportsReplayProgress()
{
  return bpvtk::replayReportsProgress();
}

bool vtkOpenGLBoundParticleMapper::RunCalls(
  const std::vector<bp::EngineCall>& calls, vtkOpenGLRenderWindow* window)
{
  vtkInternals& I = *this->Internals;
  bpvtk::GLStateGuard guard;
  // A replay from the start of a long trace takes seconds: its progress goes
  // where ParaView listens, to the display that holds this mapper (its
  // container), and the user may stop it between two steps (ReplayProgress.h).
  vtkAlgorithm* owner = this->GetContainerAlgorithm() ? this->GetContainerAlgorithm() : this;
  const std::string ownerText = owner->GetProgressText() ? owner->GetProgressText() : "";
  bp::ReplayProgress progress(
    calls, bpvtk::replayHooks(owner, window, [this] { return this->TakeAbortRequest(); }));
  bpvtk::QueueReplay::Listener listener;
  listener.configured = [this](const bp::EngineCall& call) { this->ConfigureDraw(call); };
  listener.failed = [this](const std::string& message) { this->Fail(message); };
  // A render asked for from inside a report returns at once (Render).
  bpvtk::QueueReplay::Running running(I.Replay);
  const auto started = std::chrono::steady_clock::now();
  I.Replay.run(calls, progress, listener);
  progress.finish();
  this->MeasureRate(calls, std::chrono::steady_clock::now() - started, progress.stopped());
  if (bpvtk::replayReportsProgress() && progress.reports() > 0)
  {
    owner->SetProgressText(ownerText.empty() ? nullptr : ownerText.c_str());
    // The GUI ran in the reports ("Error in cache state" in ParaView 5.11).
    guard.resetCacheAfter(window->GetState());
  }
  if (progress.stopped())
  {
    // What has been stepped stays and is drawn; the tracer's next decision
    // starts from where the engine stands (WorkQueue::settleCursor).
    I.Writer->stoppedAt(progress.stoppedAt(), progress.stoppedSteps(), I.Replay.checkpoints());
    const double sign = I.Queue->draw().backward ? -1.0 : 1.0; // the data's time
    vtkWarningMacro("Aborted: the GPU engine stopped at t = "
      << sign * progress.stoppedAt() << " on its way to t = " << sign * I.Queue->draw().time
      << ", and the display shows the elements there. The next update (another time, or "
         "Play) goes on from there.");
  }
  if (I.Replay.ready())
  {
    I.Engine.updateNormals();
    I.SamplesSerial = 0;
    const GLenum glError = glGetError();
    if (glError != GL_NO_ERROR)
    {
      this->Fail("The GPU engine failed with OpenGL error " + std::to_string(glError) +
        "; this display draws the CPU result from the next update on.");
    }
  }
  return progress.stopped();
}

std::string vtkOpenGLBoundParticleMapper::ReadEngineState(
  vtkRenderWindow* renderWindow, bp::EngineState& state)
{
  vtkInternals& I = *this->Internals;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderWindow);
  if (!I.Queue || !I.Writer)
  {
    return "the display holds no GPU engine";
  }
  if (I.Replay.replaying())
  {
    return "the display's GPU engine is running its work";
  }
  if (!window || window->GetNeverRendered())
  {
    // Before its first render a window may have no context to read in.
    return "the view has not drawn yet: render it (Render() in pvpython), then save";
  }
  window->PushContext();
  std::string error;
  const std::vector<bp::EngineCall> calls = I.Writer->take();
  if (!calls.empty() && this->RunCalls(calls, window))
  {
    error = "the GPU engine was stopped before the time shown: show it again, then save";
  }
  else if (!I.Replay.ready())
  {
    error = I.LastError.empty() ? "the display's GPU engine holds no trace" : I.LastError;
  }
  else
  {
    bpvtk::GLStateGuard guard;
    error = I.Replay.readState(state);
  }
  window->PopContext();
  return error;
}

void vtkOpenGLBoundParticleMapper::MeasureRate(
  const std::vector<bp::EngineCall>& calls, std::chrono::steady_clock::duration took, bool stopped)
{
  vtkInternals& I = *this->Internals;
  const auto steps = std::count_if(calls.begin(), calls.end(),
    [](const bp::EngineCall& call) { return call.kind == bp::EngineCall::Kind::Step; });
  // Only a run long enough to time (a replay, not a frame's step or two,
  // whose GL work is still queued when it returns): it waited for the GPU
  // while it reported its progress, and its last steps are waited for here.
  if (stopped || steps < MeasuredRunSteps || I.Particles <= 0.0)
  {
    return;
  }
  glFinish();
  const double seconds = std::chrono::duration<double>(took).count();
  if (seconds > 0.0)
  {
    I.Writer->report().particleStepsPerSecond = double(steps) * I.Particles / seconds;
  }
}

void vtkOpenGLBoundParticleMapper::ConfigureDraw(const bp::EngineCall& configure)
{
  vtkInternals& I = *this->Internals;
  const bp::Parameters& p = configure.parameters;
  const bp::ElementTemplate& shape = *configure.shape;
  I.Particles = double(p.numberOfElements) * double(shape.particleCount());
  I.LinkTable.set(bpvtk::linkPairs(p), 0);
  I.TemplateLines = shape.triangles.empty() && !shape.springs.empty();
  I.TrailLength = std::max(p.trailLength, 0);
  I.TrailInterval = p.trailInterval;
  I.TrailSpan = I.TrailLength * I.TrailInterval;
  int cornerWidth = 0;
  std::vector<int> corners =
    I.TrailLength > 0 ? bpvtk::cornerTable(shape, cornerWidth) : std::vector<int>();
  I.CornerTable.set(std::move(corners), cornerWidth);
  I.Deformation.set(shape, p);
  this->SetInputData(bpvtk::templatePolyData(shape, p.elementSize, !I.LinkTable.empty()));
}

void vtkOpenGLBoundParticleMapper::Fail(const std::string& message)
{
  vtkInternals& I = *this->Internals;
  I.Replay.fail();
  I.LastError = message;
  vtkErrorMacro(<< message);
  I.Writer->report().failure = message;
}

void vtkOpenGLBoundParticleMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& I = *this->Internals;
  if (!I.Queue || !I.Writer || I.Replay.replaying())
  {
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return;
  }
  window->MakeCurrent();
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  I.Writer->report().maxTextureSize =
    I.SizeLimit > 0 ? std::min<int>(maxSize, I.SizeLimit) : maxSize;

  std::vector<bp::EngineCall> calls = I.Writer->take();
  vtkAlgorithm* owner = this->GetContainerAlgorithm();
  const bool owed = this->ProgressOwed && owner;
  this->ProgressOwed = false;
  if (owed)
  {
    owner->SetProgressShiftScale(0.0, 1.0); // the run's share of the progress
  }
  const double reportedBefore = owner ? owner->GetProgress() : 0.0;
  if (!calls.empty())
  {
    this->RunCalls(calls, window);
  }
  if (owed && owner->GetProgress() == reportedBefore && !owner->GetAbortExecute())
  {
    owner->UpdateProgress(1.0); // a run too short to report: the update's end
    window->MakeCurrent();      // whatever listens may have drawn elsewhere
  }
  if (!I.Replay.ready())
  {
    return;
  }
  this->PrepareEngineTextures();
  I.Inputs = I.Engine.drawInputs();
  I.LastError.clear();
  this->Superclass::Render(ren, act);
}

void vtkOpenGLBoundParticleMapper::PrepareEngineTextures()
{
  vtkInternals& I = *this->Internals;
  if (I.Queue->report().streamTimeSteps && I.Queue->upcoming().velocity)
  {
    // Upload the next time step a slab at a time, within a small time
    // budget per frame, so the frame that crosses into it does not stall.
    bpvtk::GLStateGuard guard;
    I.Engine.stageSliceWithin(I.Queue->upcoming(), StagingSecondsPerFrame);
  }
  // Orientation and spin need nothing here: the display's engine fits the
  // poses every step (GpuStepper turns Parameters::trackPoses on).
  if (I.ScalarMode == bp::ColorSource::Velocity || I.ScalarMode == bp::ColorSource::Vorticity ||
    I.ScalarMode == bp::ColorSource::ParticleVelocity)
  {
    if (I.SamplesSerial != I.Queue->draw().serial)
    {
      bpvtk::GLStateGuard guard;
      I.Engine.updateFieldSamples(I.Queue->draw().time);
      I.SamplesSerial = I.Queue->draw().serial;
    }
  }
}

void vtkOpenGLBoundParticleMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  // Tags of our own after VTK's colour code and its gl_Position, so ours runs
  // after them; then VTK's replacements; then our code at our tags.
  bpvtk::addDrawTags(shaders);
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  bpvtk::spliceDrawCode(shaders);
}

void vtkOpenGLBoundParticleMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkInternals& I = *this->Internals;
  vtkShaderProgram* program = cellBO.Program;
  I.Samplers.setUniforms(program);
  I.Deformation.setUniforms(program);
  // Read only in the link draw, which needs links (and so a width).
  program->SetUniformi("bpLinksPerRow", std::max(I.LinkTable.width(), 1));
  program->SetUniformi("bpDrawLinks", 0);
  program->SetUniformi("bpAdjacencyWidth", I.CornerTable.width());
  program->SetUniform3f("bpTrailHalfPeriods", I.Inputs.trailHalfPeriods); // the trail's breaks
  // The elements themselves; the trail draws change these three per slot.
  program->SetUniformi("bpTrail", 0);
  program->SetUniformf("bpTrailAge", 0.0f);
  program->SetUniformf("bpFade", 1.0f);
  program->SetUniform2i("bpElementGrid", I.Inputs.elementGrid);
  program->SetUniformi("bpBlocksPerRow", I.Inputs.blocksPerRow);
  const auto& d = I.Queue->draw();
  const bp::ColorSource mode = this->ScalarVisibility ? I.ScalarMode : bp::ColorSource::Solid;
  program->SetUniformi("bpScalarMode", int(mode));
  program->SetUniformi("bpComponent", I.Component);
  // Layer is a world coordinate, the engine's centres are grid-local: the
  // range moves to grid-local coordinates here, in double, so the shader
  // compares grid-local floats that keep their precision far from the origin.
  const double shift = mode == bp::ColorSource::Layer && d.coloringAxis >= 0 && d.coloringAxis < 3
    ? d.offset[std::size_t(d.coloringAxis)]
    : 0.0;
  const double* tableRange = I.ColorTable.range();
  const float range[2] = { float(tableRange[0] - shift), float(tableRange[1] - shift) };
  program->SetUniform2f("bpScalarRange", range);
  program->SetUniformi("bpColoringAxis", d.coloringAxis);
  const float center[2] = { float(d.radialCenter[0]), float(d.radialCenter[1]) };
  program->SetUniform2f("bpRadialCenter", center);
  program->SetUniformf("bpVelocitySign", d.backward ? -1.0f : 1.0f); // per the data's time
  program->SetUniformi("bpColorTable", I.ColorTable.texture()->GetTextureUnit());
  program->SetUniformf("bpColorTableSize", float(bpvtk::ColorTableTexture::Size));
  // The superclass gave the clipping planes for world positions.
  bpvtk::setGridLocalClippingPlanes(program, this, act, d.offset);
}

void vtkOpenGLBoundParticleMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // Every camera uniform as for model coordinates that are world ones (the
  // template's buffer is never shifted); then the three that hold the model
  // coordinates' origin again, with the grid-local origin composed in.
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  vtkInternals& I = *this->Internals;
  bpvtk::setGridLocalCamera(
    cellBO.Program, ren, act, I.Queue->draw().offset, I.ModelToWorld, I.ModelToView);
}

void vtkOpenGLBoundParticleMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& I = *this->Internals;
  vtkOpenGLRenderWindow* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  I.ColorTable.update(this->GetLookupTable(), window);
  I.ColorTable.texture()->Activate();
  this->UploadTables(window);
  // Where the colour map maps opacity (colouring by Age, say) it fades the
  // trails; otherwise the display's own fade does.
  bpvtk::chooseTrailPoses(I.Inputs.trail, I.Queue->draw().time, I.TrailSpan + I.TrailInterval,
    this->ColorMapIsTranslucent(), I.TrailPoses);
  I.Samplers.bindAll(window,
    bp::drawSamplerTextures(
      I.Inputs, { I.LinkTable.handle(), I.CornerTable.handle(), I.Deformation.handle() }));
  for (int p = PrimitiveStart; p <= PrimitiveTris; ++p)
  {
    this->DrawPrimitive(p, ren, act);
  }
  I.Samplers.unbindAll(window);
  I.ColorTable.texture()->Deactivate();
}

void vtkOpenGLBoundParticleMapper::UploadTables(vtkOpenGLRenderWindow* window)
{
  // Nothing about them changes while the engine steps: once per configuration.
  vtkInternals& I = *this->Internals;
  const int reported = I.Queue->report().maxTextureSize;
  const int maxSize = reported > 0 ? reported : 4096;
  const std::size_t links = I.LinkTable.texelCount();
  if (!I.LinkTable.upload(window, maxSize))
  {
    vtkWarningMacro(<< links
                    << " links are too many for one texture; the display draws the "
                       "elements without their links.");
  }
  const std::size_t particles = I.CornerTable.rows(maxSize); // a row per template particle
  if (!I.CornerTable.upload(window, maxSize))
  {
    // Every trail normal then reads (0, 0, 1).
    vtkWarningMacro(<< "The template's " << particles
                    << " particles are too many for one texture; the display lights its "
                       "trails with a fixed normal.");
  }
  I.Deformation.upload(window, maxSize);
}

void vtkOpenGLBoundParticleMapper::DrawPrimitive(int primitive, vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& I = *this->Internals;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  this->DrawingVertices = false;
  this->DrawingSelection = false;
  vtkOpenGLHelper& helper = this->Primitives[primitive];
  const GLsizei linkCount = GLsizei(I.LinkTable.texelCount());
  // The line shader also draws the links; a stand-in line cell is not drawn.
  const bool elementCells = primitive != PrimitiveLines || I.TemplateLines;
  const bool linkCells = primitive == PrimitiveLines && linkCount > 0;
  if (!helper.IBO->IndexCount || !(elementCells || linkCells))
  {
    return;
  }
  const GLenum mode = this->GetOpenGLMode(act->GetProperty()->GetRepresentation(), primitive);
  this->UpdateShaders(helper, ren, act);
  if (!helper.Program)
  {
    I.LastError = "The Bound Particles drawing shader does not compile; see the error above.";
    return;
  }
  if (mode == GL_POINTS)
  {
    state->vtkglPointSize(act->GetProperty()->GetPointSize());
  }
  else if (mode == GL_LINES && !this->HaveWideLines(ren, act))
  {
    state->vtkglLineWidth(act->GetProperty()->GetLineWidth());
  }
  if (elementCells)
  {
    this->DrawElementCells(helper, mode, window);
  }
  if (linkCells)
  {
    // One instance per link, two vertices per template particle: the
    // vertex shader fetches both ends from the state textures.
    helper.Program->SetUniformi("bpDrawLinks", 1);
    I.LinkVAO->Bind();
    glDrawArraysInstanced(mode, 0, 2 * I.Inputs.particlesPerElement, linkCount);
    helper.VAO->Bind(); // as VTK left it: RenderPieceFinish releases it
    helper.Program->SetUniformi("bpDrawLinks", 0);
  }
}

void vtkOpenGLBoundParticleMapper::DrawElementCells(
  vtkOpenGLHelper& helper, unsigned int mode, vtkOpenGLRenderWindow* window)
{
  vtkInternals& I = *this->Internals;
  helper.IBO->Bind();
  glDrawElementsInstanced(GLenum(mode), GLsizei(helper.IBO->IndexCount), GL_UNSIGNED_INT, nullptr,
    GLsizei(I.Inputs.elementCount));
  // Each trail pose shown: the same cells again, positions from the slot's
  // copy of the particle texture (the engine's ring, nothing uploaded);
  // elements of another generation there are clipped.
  for (const bpvtk::TrailPoseDraw& t : I.TrailPoses)
  {
    I.Samplers.bind(window, bp::DrawSampler::TrailPositions, t.positions);
    I.Samplers.bind(window, bp::DrawSampler::TrailElements, t.elements);
    helper.Program->SetUniformi("bpTrail", 1);
    helper.Program->SetUniformf("bpTrailAge", t.age);
    helper.Program->SetUniformf("bpFade", t.fade);
    glDrawElementsInstanced(GLenum(mode), GLsizei(helper.IBO->IndexCount), GL_UNSIGNED_INT, nullptr,
      GLsizei(I.Inputs.elementCount));
  }
  if (!I.TrailPoses.empty())
  {
    helper.Program->SetUniformi("bpTrail", 0);
    helper.Program->SetUniformf("bpTrailAge", 0.0f);
    helper.Program->SetUniformf("bpFade", 1.0f);
  }
  helper.IBO->Release();
}

void vtkOpenGLBoundParticleMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& I = *this->Internals;
  if (I.Replay.configured())
  {
    if (window)
    {
      static_cast<vtkOpenGLRenderWindow*>(window)->MakeCurrent();
      bpvtk::GLStateGuard guard;
      I.Engine.release();
    }
    I.Replay.forget();
    if (I.Writer)
    {
      // The state is gone: what is queued continues from it, so the filter
      // must replay into this queue.
      I.Writer->stateLost();
    }
  }
  I.ColorTable.release(window);
  I.LinkTable.release(window);
  I.CornerTable.release(window);
  I.Deformation.release(window);
  I.LinkVAO->ReleaseGraphicsResources();
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLBoundParticleMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarMode: " << int(this->Internals->ScalarMode) << "\n";
  os << indent << "Configured: " << this->Internals->Replay.configured() << "\n";
  os << indent << "TrailSpan: " << this->Internals->TrailSpan << "\n";
}
