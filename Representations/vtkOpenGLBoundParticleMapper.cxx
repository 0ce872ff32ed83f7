// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLBoundParticleMapper.h"

#include "BoundParticlesShaders.h" // generated from Shaders/
#include "GpuEngine.h"
#include "GpuStepper.h"
#include "OutputArrays.h"
#include "ReplayProgress.h"
#include "SuperSet.h"
#include "WorkQueue.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPVVersion.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtkUnsignedCharArray.h"
// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace
{
// ParaView 6.1's GUI processes its events on every progress report (for its
// Abort button); a report from inside a render then never returns there
// (python.GUI hung in Render), so the GPU replay reports no progress on 6.1
// and later. An abort request is still honoured between steps.
#if PARAVIEW_VERSION_NUMBER >= PARAVIEW_VERSION_CHECK(6, 1, 0)
constexpr bool ReportsReplayProgress = false;
#else
constexpr bool ReportsReplayProgress = true;
#endif
} // namespace

namespace
{
/**
 * Saves the GL state the engine's passes change and puts it back, so VTK's
 * cached view of the state (vtkOpenGLState, the texture units, the bound
 * shader) stays true.
 */
/// What a frame spends on uploading the next field time step: a 128^3
/// float time step (24 MiB) then arrives over a few frames on a software
/// renderer, in one or two on a GPU.
constexpr double StagingSecondsPerFrame = 0.004;

class GLStateGuard
{
public:
  static constexpr int Units = 16;
  GLStateGuard()
  {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &this->DrawFbo);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &this->ReadFbo);
    glGetIntegerv(GL_VIEWPORT, this->Viewport);
    glGetIntegerv(GL_CURRENT_PROGRAM, &this->Program);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &this->ActiveTexture);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &this->Vao);
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &this->UnitCount);
    this->UnitCount = std::min(this->UnitCount, Units);
    for (int u = 0; u < this->UnitCount; ++u)
    {
      glActiveTexture(GLenum(GL_TEXTURE0 + u));
      glGetIntegerv(GL_TEXTURE_BINDING_2D, &this->Texture2D[u]);
      glGetIntegerv(GL_TEXTURE_BINDING_3D, &this->Texture3D[u]);
    }
    glActiveTexture(GLenum(this->ActiveTexture));
    for (int k = 0; k < 5; ++k)
    {
      this->Enabled[k] = glIsEnabled(Capabilities[k]);
    }
    glGetBooleanv(GL_COLOR_WRITEMASK, this->ColorMask);
  }
  ~GLStateGuard()
  {
    for (int k = 0; k < 5; ++k)
    {
      if (this->Enabled[k])
        glEnable(Capabilities[k]);
      else
        glDisable(Capabilities[k]);
    }
    glColorMask(this->ColorMask[0], this->ColorMask[1], this->ColorMask[2], this->ColorMask[3]);
    for (int u = 0; u < this->UnitCount; ++u)
    {
      glActiveTexture(GLenum(GL_TEXTURE0 + u));
      glBindTexture(GL_TEXTURE_2D, GLuint(this->Texture2D[u]));
      glBindTexture(GL_TEXTURE_3D, GLuint(this->Texture3D[u]));
    }
    glActiveTexture(GLenum(this->ActiveTexture));
    glBindVertexArray(GLuint(this->Vao));
    glUseProgram(GLuint(this->Program));
    glViewport(this->Viewport[0], this->Viewport[1], this->Viewport[2], this->Viewport[3]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(this->DrawFbo));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(this->ReadFbo));
  }

private:
  static constexpr GLenum Capabilities[5] = { GL_BLEND, GL_DEPTH_TEST, GL_SCISSOR_TEST,
    GL_CULL_FACE, GL_STENCIL_TEST };
  GLint DrawFbo = 0, ReadFbo = 0, Viewport[4] = { 0, 0, 0, 0 }, Program = 0, ActiveTexture = 0,
        Vao = 0, UnitCount = 0;
  GLint Texture2D[Units] = {}, Texture3D[Units] = {};
  GLboolean Enabled[5] = {}, ColorMask[4] = {};
};
constexpr GLenum GLStateGuard::Capabilities[5];

/// The template as VTK polydata: its triangles (or springs as lines, or the
/// lone particle as a vertex) over n points, so VTK builds one index buffer
/// whose indices are template particle indices. With `links`, a template
/// without lines gets one stand-in line cell, so that VTK also builds its
/// line shader, which draws the super set's links; the cell itself is never
/// drawn.
vtkSmartPointer<vtkPolyData> templateMesh(const bp::ElementTemplate& shape, float size, bool links)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (const auto& r : shape.rest)
  {
    points->InsertNextPoint(size * r[0], size * r[1], size * r[2]);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
  }
  mesh->SetPoints(points);
  mesh->GetPointData()->SetNormals(normals);
  vtkNew<vtkCellArray> cells;
  if (!shape.triangles.empty())
  {
    for (const auto& t : shape.triangles)
    {
      const vtkIdType ids[3] = { vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2]) };
      cells->InsertNextCell(3, ids);
    }
    mesh->SetPolys(cells);
  }
  else if (!shape.springs.empty())
  {
    for (const auto& s : shape.springs)
    {
      const vtkIdType ids[2] = { vtkIdType(s.a), vtkIdType(s.b) };
      cells->InsertNextCell(2, ids);
    }
    mesh->SetLines(cells);
  }
  else
  {
    for (vtkIdType i = 0; i < vtkIdType(shape.rest.size()); ++i)
    {
      cells->InsertNextCell(1, &i);
    }
    mesh->SetVerts(cells);
  }
  if (links && mesh->GetNumberOfLines() == 0)
  {
    vtkNew<vtkCellArray> standIn;
    const vtkIdType ids[2] = { 0, 0 };
    standIn->InsertNextCell(2, ids);
    mesh->SetLines(standIn);
  }
  return mesh;
}

/// The links of a super set as the CPU output has them (TracerOutput.cxx's
/// link cells): for each element in order, its +u and then its +v link, each
/// link once, as pairs of element indices.
std::vector<int> linkPairs(const bp::Parameters& p)
{
  const bp::LinkTable table =
    bp::makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax);
  std::vector<int> pairs;
  pairs.reserve(2 * table.linkCount());
  const std::size_t elements = table.sites.size() / 3;
  for (std::size_t e = 0; e < elements; ++e)
  {
    for (int d : { 0, 2 }) // +u and +v
    {
      const std::int32_t f = table.neighbours[bp::LinkDirections * e + d];
      if (f >= 0)
      {
        pairs.push_back(int(e));
        pairs.push_back(int(f));
      }
    }
  }
  return pairs;
}

/**
 * For each template particle, the triangles it is a corner of, so the draw
 * shader can compute a trail pose's normals from the pose's positions as
 * bp::elementNormals does: row i holds the corners (in the triangle's own
 * order, so the normal's sign is the mesh's) of each triangle with i among
 * them, then (-1, -1, -1) where the row ends early. `width` is the longest
 * row (1 for a template without triangles: its rows are all ends).
 */
std::vector<int> cornerTable(const bp::ElementTemplate& shape, int& width)
{
  const std::size_t n = shape.rest.size();
  std::vector<std::vector<std::array<int, 3>>> rows(n);
  for (const auto& t : shape.triangles)
  {
    const std::array<int, 3> corners = { int(t[0]), int(t[1]), int(t[2]) };
    for (std::uint32_t i : t)
    {
      rows[i].push_back(corners);
    }
  }
  width = 1;
  for (const auto& row : rows)
  {
    width = std::max(width, int(row.size()));
  }
  std::vector<int> texels(std::size_t(4) * width * n, -1);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t k = 0; k < rows[i].size(); ++k)
    {
      std::copy(rows[i][k].begin(), rows[i][k].end(), texels.begin() + 4 * (i * width + k));
    }
  }
  return texels;
}
} // namespace

struct vtkOpenGLBoundParticleMapper::vtkInternals
{
  bp::GpuStepper Stepper; ///< replays the recorded calls on the GPU engine
  bp::GpuEngine& Engine = Stepper.engine();
  std::shared_ptr<bp::WorkQueue> Queue;
  bool Configured = false; // the engine holds a system
  bool Failed = false;     // the queued work failed: draw nothing until the next Configure
  bool Replaying = false;  // running the queue: a render from inside a progress report waits
  std::string LastError;
  std::uint64_t SamplesSerial = 0; // the draw serial the samples texture is for
  bp::GpuEngine::DrawInputs Inputs;

  bp::ColorSource ScalarMode = bp::ColorSource::Solid;
  int Component = -1;
  int SizeLimit = 0; // a cap below GL_MAX_TEXTURE_SIZE, for tests

  vtkNew<vtkTextureObject> ColorTable;
  vtkMTimeType ColorTableTime = 0;
  double ColorTableRange[2] = { 0, 1 };
  static constexpr int ColorTableSize = 256;

  /// A super set's links, as pairs of element indices, and their texture
  /// (RG32I, LinksPerRow a row); made once per configuration.
  std::vector<int> LinkPairs;
  bool LinksUploaded = false;
  vtkNew<vtkTextureObject> LinkTable;
  int LinksPerRow = 1;
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
  /// Per template particle, the triangles it is a corner of (cornerTable):
  /// made once per configuration, uploaded as RGBA32I.
  std::vector<int> CornerTexels;
  int CornerWidth = 0; ///< texels a row; 0 when the table does not fit a texture
  bool CornersUploaded = false;
  vtkNew<vtkTextureObject> CornerTable;

  /// The samplers' names, in the order of `Units` (Trail* are bound per slot).
  enum Texture
  {
    Positions,
    Normals,
    Samples,
    Elements,
    Centers,
    Links,
    Poses,
    Spins,
    TrailPositions,
    TrailElements,
    Corners,
    TextureCount
  };
  int Units[TextureCount] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }; // while drawing

  /// The camera matrices with the grid-local origin composed in
  /// (SetCameraShaderParameters; kept, not allocated per draw).
  vtkNew<vtkMatrix4x4> ModelToWorld;
  vtkNew<vtkMatrix4x4> ModelToView;
};

vtkStandardNewMacro(vtkOpenGLBoundParticleMapper);

vtkOpenGLBoundParticleMapper::vtkOpenGLBoundParticleMapper()
  : Internals(new vtkInternals)
{
  // Positions come from the engine's textures, grid-local, and the draw's
  // own translation to world coordinates goes into the camera matrices
  // (SetCameraShaderParameters): VTK must not shift and scale the template's
  // buffer (which the shaders do not read) and fold that in as well.
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  this->SetScalarVisibility(0);
}

vtkOpenGLBoundParticleMapper::~vtkOpenGLBoundParticleMapper() = default;

void vtkOpenGLBoundParticleMapper::SetWorkQueue(const std::shared_ptr<bp::WorkQueue>& queue)
{
  if (this->Internals->Queue != queue)
  {
    this->Internals->Queue = queue;
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
  if (!queue || queue->draw.serial == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  else
  {
    std::copy(queue->draw.bounds.begin(), queue->draw.bounds.end(), this->Bounds);
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

void vtkOpenGLBoundParticleMapper::RunCalls(
  const std::vector<bp::EngineCall>& calls, vtkOpenGLRenderWindow* window)
{
  vtkInternals& I = *this->Internals;
  GLStateGuard guard;
  auto failWith = [&](const std::string& message)
  {
    I.Failed = true;
    I.LastError = message;
    vtkErrorMacro(<< message);
    I.Queue->failure = message;
  };
  // A replay from the start of a long trace takes seconds: its progress goes
  // where ParaView listens, to the display that holds this mapper (its
  // container), and the user may stop it between two steps (ReplayProgress.h).
  vtkAlgorithm* owner = this->GetContainerAlgorithm() ? this->GetContainerAlgorithm() : this;
  const std::string ownerText = owner->GetProgressText() ? owner->GetProgressText() : "";
  bp::ReplayProgress::Hooks hooks;
  hooks.settle = [] { glFinish(); };
  hooks.report = [owner](double share)
  {
    if (ReportsReplayProgress)
    {
      owner->SetProgressText("Bound Particles: GPU engine");
      owner->UpdateProgress(share);
    }
  };
  hooks.stop = [this] { return this->TakeAbortRequest(); };
  // Whatever listens to the progress may have drawn in another window.
  hooks.resume = [window] { window->MakeCurrent(); };
  bp::ReplayProgress progress(calls, hooks);
  // A render asked for from inside a report returns at once (Render).
  struct Flag
  {
    bool& Set;
    explicit Flag(bool& flag)
      : Set(flag)
    {
      flag = true;
    }
    ~Flag() { this->Set = false; }
  } replaying(I.Replaying);

  for (std::size_t k = 0; k < calls.size() && progress.beforeCall(k); ++k)
  {
    const bp::EngineCall& call = calls[k];
    const bool configure = call.kind == bp::EngineCall::Kind::Configure;
    if (configure)
    {
      I.Failed = false;
      I.Configured = false;
    }
    else if (!I.Configured || I.Failed)
    {
      continue; // what follows a failed call would continue from nothing
    }
    // Only configure and setField can fail: the system or the field does not fit.
    const std::string error = call.applyTo(I.Stepper);
    if (!error.empty())
    {
      failWith(std::string(configure ? "The GPU engine cannot run this trace: "
                                     : "The GPU engine cannot hold this field: ") +
        error + ". This display draws the CPU result from the next update on.");
    }
    else if (configure)
    {
      I.Configured = true;
      I.LinkPairs = linkPairs(call.parameters);
      I.LinksUploaded = false;
      I.TemplateLines = call.shape->triangles.empty() && !call.shape->springs.empty();
      I.TrailLength = std::max(call.parameters.trailLength, 0);
      I.TrailInterval = call.parameters.trailInterval;
      I.TrailSpan = I.TrailLength * I.TrailInterval;
      I.CornerTexels =
        I.TrailLength > 0 ? cornerTable(*call.shape, I.CornerWidth) : std::vector<int>();
      I.CornersUploaded = false;
      this->SetInputData(
        templateMesh(*call.shape, call.parameters.elementSize, !I.LinkPairs.empty()));
    }
  }
  progress.finish();
  if (progress.reports() > 0)
  {
    owner->SetProgressText(ownerText.empty() ? nullptr : ownerText.c_str());
  }
  if (progress.stopped())
  {
    // What has been stepped stays and is drawn; the tracer's next decision
    // starts from where the engine stands.
    I.Queue->stoppedAt(progress.stoppedAt());
    vtkWarningMacro("Aborted: the GPU engine stopped at t = "
      << progress.stoppedAt() << " on its way to t = " << I.Queue->draw.time
      << ", and the display shows the elements there. The next update (another time, or "
         "Play) goes on from there.");
  }
  if (I.Configured && !I.Failed)
  {
    I.Engine.updateNormals();
    I.SamplesSerial = 0;
    const GLenum glError = glGetError();
    if (glError != GL_NO_ERROR)
    {
      failWith("The GPU engine failed with OpenGL error " + std::to_string(glError) +
        "; this display draws the CPU result from the next update on.");
    }
  }
}

void vtkOpenGLBoundParticleMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& I = *this->Internals;
  if (!I.Queue || I.Replaying)
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
  I.Queue->maxTextureSize = I.SizeLimit > 0 ? std::min<int>(maxSize, I.SizeLimit) : maxSize;

  std::vector<bp::EngineCall> calls = I.Queue->take();
  if (!calls.empty())
  {
    this->RunCalls(calls, window);
  }
  if (!I.Configured || I.Failed)
  {
    return;
  }
  if (I.Queue->streamTimeSteps && I.Queue->upcoming.velocity)
  {
    // Upload the next time step a slab at a time, within a small time
    // budget per frame, so the frame that crosses into it does not stall.
    GLStateGuard guard;
    I.Engine.stageSliceWithin(I.Queue->upcoming, StagingSecondsPerFrame);
  }
  // Orientation and spin need nothing here: the display's engine fits the
  // poses every step (GpuStepper turns Parameters::trackPoses on).
  if (I.ScalarMode == bp::ColorSource::Velocity || I.ScalarMode == bp::ColorSource::Vorticity)
  {
    if (I.SamplesSerial != I.Queue->draw.serial)
    {
      GLStateGuard guard;
      I.Engine.updateFieldSamples(I.Queue->draw.time);
      I.SamplesSerial = I.Queue->draw.serial;
    }
  }
  I.Inputs = I.Engine.drawInputs();
  I.LastError.clear();
  this->Superclass::Render(ren, act);
}

void vtkOpenGLBoundParticleMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  // Tags of our own after VTK's colour code and its gl_Position, so ours runs after them.
  vtkShaderProgram::Substitute(fs, "//VTK::Color::Impl", "//VTK::Color::Impl\n//BP::Color::Impl");
  vtkShaderProgram::Substitute(fs, "//VTK::Color::Dec", "//VTK::Color::Dec\n//BP::Color::Dec");
  vtkShaderProgram::Substitute(
    vs, "//VTK::PositionVC::Impl", "//VTK::PositionVC::Impl\n//BP::PositionVC::Impl");
  // With a geometry shader (wide lines where the GL has none of its own) the
  // fragment shader's inputs are renamed to come from it (VSOutput becomes
  // GSOutput): it must pass the scalar on, as VTK's colour code does.
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  vtkShaderProgram::Substitute(gs, "//VTK::Color::Impl", "//VTK::Color::Impl\n//BP::Color::Impl");
  vtkShaderProgram::Substitute(gs, "//VTK::Color::Dec", "//VTK::Color::Dec\n//BP::Color::Dec");
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Geometry]->SetSource(gs);
  shaders[vtkShader::Fragment]->SetSource(fs);
  this->Superclass::ReplaceShaderValues(shaders, ren, act);

  vs = shaders[vtkShader::Vertex]->GetSource();
  gs = shaders[vtkShader::Geometry]->GetSource();
  fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(
    gs, "//BP::Color::Dec", "in float bpScalarVSOutput[];\nout float bpScalarGSOutput;", false);
  vtkShaderProgram::Substitute(
    gs, "//BP::Color::Impl", "bpScalarGSOutput = bpScalarVSOutput[i];", false);
  shaders[vtkShader::Geometry]->SetSource(gs);
  // The colour modes' numbers, from the table of output arrays.
  const std::string colorModes = bp::colorSourceDefinitions();
  // Every use of the vertex and normal attributes reads the fetched values;
  // the attributes stay declared so VTK's buffers still bind.
  vtkShaderProgram::Substitute(vs, "vertexMC", "bpVertexMC", true);
  vtkShaderProgram::Substitute(vs, "normalMC", "bpNormalMC", true);
  vtkShaderProgram::Substitute(
    vs, "in vec4 bpVertexMC;", "in vec4 vertexMC;\n" + colorModes + bpShaderDrawVSDec, false);
  vtkShaderProgram::Substitute(vs, "in vec3 bpNormalMC;", "in vec3 normalMC;", false);
  vtkShaderProgram::Substitute(
    vs, "void main()\n{", std::string("void main()\n{\n") + bpShaderDrawVSImpl, false);
  vtkShaderProgram::Substitute(vs, "//BP::PositionVC::Impl", "  bpClipHidden();", false);
  vtkShaderProgram::Substitute(fs, "//BP::Color::Dec", colorModes + bpShaderDrawFSDec, false);
  vtkShaderProgram::Substitute(fs, "//BP::Color::Impl", bpShaderDrawFSImpl, false);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

void vtkOpenGLBoundParticleMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkInternals& I = *this->Internals;
  vtkShaderProgram* program = cellBO.Program;
  // Every sampler on a unit of its own, bpLinks included when nothing is
  // linked: samplers of different types on one unit make a draw fail.
  const char* samplers[vtkInternals::TextureCount] = { "bpPositions", "bpNormals", "bpSamples",
    "bpElements", "bpCenters", "bpLinks", "bpPoses", "bpSpins", "bpTrailPositions",
    "bpTrailElements", "bpAdjacency" };
  for (int k = 0; k < vtkInternals::TextureCount; ++k)
  {
    program->SetUniformi(samplers[k], I.Units[k]);
  }
  program->SetUniformi("bpLinksPerRow", I.LinksPerRow);
  program->SetUniformi("bpDrawLinks", 0);
  program->SetUniformi("bpAdjacencyWidth", I.CornerWidth);
  // The elements themselves; the trail draws change these three per slot.
  program->SetUniformi("bpTrail", 0);
  program->SetUniformf("bpTrailAge", 0.0f);
  program->SetUniformf("bpFade", 1.0f);
  program->SetUniform2i("bpElementGrid", I.Inputs.elementGrid);
  program->SetUniformi("bpBlocksPerRow", I.Inputs.blocksPerRow);
  const auto& d = I.Queue->draw;
  const bp::ColorSource mode = this->ScalarVisibility ? I.ScalarMode : bp::ColorSource::Solid;
  program->SetUniformi("bpScalarMode", int(mode));
  program->SetUniformi("bpComponent", I.Component);
  // Layer is a world coordinate, the engine's centres are grid-local: the
  // range moves to grid-local coordinates here, in double, so the shader
  // compares grid-local floats that keep their precision far from the origin.
  const double shift = mode == bp::ColorSource::Layer && d.coloringAxis >= 0 && d.coloringAxis < 3
    ? d.offset[std::size_t(d.coloringAxis)]
    : 0.0;
  const float range[2] = { float(I.ColorTableRange[0] - shift),
    float(I.ColorTableRange[1] - shift) };
  program->SetUniform2f("bpScalarRange", range);
  program->SetUniformi("bpColoringAxis", d.coloringAxis);
  const float center[2] = { float(d.radialCenter[0]), float(d.radialCenter[1]) };
  program->SetUniform2f("bpRadialCenter", center);
  program->SetUniformi("bpColorTable", I.ColorTable->GetTextureUnit());
  program->SetUniformf("bpColorTableSize", float(vtkInternals::ColorTableSize));

  // The superclass gives the clipping planes in world (data) coordinates,
  // the shader tests them on grid-local positions: a plane n.x + c = 0 over
  // x = local + offset is n.local + (c + n.offset) = 0, moved in double.
  const int planes = std::min(this->GetNumberOfClippingPlanes(), 6);
  const bool shifted = d.offset[0] != 0.0 || d.offset[1] != 0.0 || d.offset[2] != 0.0;
  if (shifted && planes > 0 && program->IsUniformUsed("numClipPlanes") &&
    program->IsUniformUsed("clipPlanes"))
  {
    float equations[6][4] = {};
    vtkNew<vtkMatrix4x4> propMatrix;
    act->GetModelToWorldMatrix(propMatrix);
    for (int k = 0; k < planes; ++k)
    {
      double plane[4];
      this->GetClippingPlaneInDataCoords(propMatrix, k, plane);
      equations[k][0] = float(plane[0]);
      equations[k][1] = float(plane[1]);
      equations[k][2] = float(plane[2]);
      equations[k][3] =
        float(plane[3] + plane[0] * d.offset[0] + plane[1] * d.offset[1] + plane[2] * d.offset[2]);
    }
    program->SetUniform4fv("clipPlanes", 6, equations);
  }
}

void vtkOpenGLBoundParticleMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // Every camera uniform as for model coordinates that are world ones (the
  // template's buffer is never shifted); then the three that hold the model
  // coordinates' origin again, with the grid-local origin composed in.
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  vtkInternals& I = *this->Internals;
  const auto& offset = I.Queue->draw.offset;
  if (offset[0] == 0.0 && offset[1] == 0.0 && offset[2] == 0.0)
  {
    return; // grid-local is world: the superclass's matrices are the ones
  }
  vtkShaderProgram* program = cellBO.Program;
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* norms;
  vtkMatrix4x4* vcdc;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  // VTK's key matrices are transposed (they act on row vectors: the
  // translation is the last row, and Multiply4x4(a, b) applies a first), as
  // its VBO shift and scale matrix is. The products are taken in double: the
  // offset and the camera's distance from the world origin cancel here, and
  // what reaches the shader as float is the field's position relative to
  // the camera.
  vtkMatrix4x4* toWorld = I.ModelToWorld;
  toWorld->Identity();
  for (int k = 0; k < 3; ++k)
  {
    toWorld->SetElement(3, k, offset[std::size_t(k)]);
  }
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc;
    vtkMatrix3x3* anorms;
    static_cast<vtkOpenGLActor*>(act)->GetKeyMatrices(mcwc, anorms);
    vtkMatrix4x4::Multiply4x4(toWorld, mcwc, toWorld); // normals: translation-free, as set
  }
  if (program->IsUniformUsed("MCWCMatrix"))
  {
    program->SetUniformMatrix("MCWCMatrix", toWorld);
  }
  vtkMatrix4x4::Multiply4x4(toWorld, wcdc, I.ModelToView);
  program->SetUniformMatrix("MCDCMatrix", I.ModelToView);
  if (program->IsUniformUsed("MCVCMatrix"))
  {
    vtkMatrix4x4::Multiply4x4(toWorld, wcvc, I.ModelToView);
    program->SetUniformMatrix("MCVCMatrix", I.ModelToView);
  }
}

void vtkOpenGLBoundParticleMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& I = *this->Internals;
  vtkOpenGLRenderWindow* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  // The lookup table as a table texture over its range.
  vtkScalarsToColors* lut = this->GetLookupTable();
  const double* range = lut->GetRange();
  if (!I.ColorTable->GetHandle() || lut->GetMTime() > I.ColorTableTime ||
    range[0] != I.ColorTableRange[0] || range[1] != I.ColorTableRange[1])
  {
    const int size = vtkInternals::ColorTableSize;
    vtkNew<vtkDoubleArray> ramp;
    ramp->SetNumberOfValues(size);
    for (int k = 0; k < size; ++k)
    {
      ramp->SetValue(k, range[0] + (range[1] - range[0]) * k / double(size - 1));
    }
    vtkUnsignedCharArray* rgba = lut->MapScalars(ramp, VTK_COLOR_MODE_MAP_SCALARS, -1);
    I.ColorTable->SetContext(window);
    I.ColorTable->Create2DFromRaw(size, 1, 4, VTK_UNSIGNED_CHAR, rgba->GetVoidPointer(0));
    I.ColorTable->SetMinificationFilter(vtkTextureObject::Linear);
    I.ColorTable->SetMagnificationFilter(vtkTextureObject::Linear);
    I.ColorTable->SetWrapS(vtkTextureObject::ClampToEdge);
    I.ColorTable->SetWrapT(vtkTextureObject::ClampToEdge);
    rgba->Delete();
    I.ColorTableTime = lut->GetMTime();
    I.ColorTableRange[0] = range[0];
    I.ColorTableRange[1] = range[1];
  }
  I.ColorTable->Activate();

  // A super set's links, once per configuration: nothing about them changes
  // while the engine steps.
  if (!I.LinkPairs.empty() && (!I.LinksUploaded || !I.LinkTable->GetHandle()))
  {
    I.LinksUploaded = true;
    const int links = int(I.LinkPairs.size() / 2);
    const int maxSize = I.Queue->maxTextureSize > 0 ? I.Queue->maxTextureSize : 4096;
    I.LinksPerRow = std::min(links, maxSize);
    const int rows = (links + I.LinksPerRow - 1) / I.LinksPerRow;
    if (rows > maxSize)
    {
      I.LinkPairs.clear();
      vtkWarningMacro(<< links
                      << " links are too many for one texture; the display draws the "
                         "elements without their links.");
    }
    else
    {
      std::vector<int> texels(std::size_t(2) * I.LinksPerRow * rows, 0);
      std::copy(I.LinkPairs.begin(), I.LinkPairs.end(), texels.begin());
      I.LinkTable->SetContext(window);
      I.LinkTable->SetInternalFormat(GL_RG32I);
      I.LinkTable->SetFormat(GL_RG_INTEGER);
      I.LinkTable->Create2DFromRaw(
        unsigned(I.LinksPerRow), unsigned(rows), 2, VTK_INT, texels.data());
    }
  }
  const GLsizei linkCount = GLsizei(I.LinkPairs.size() / 2);

  // The corner table for the trails' normals, once per configuration.
  if (!I.CornerTexels.empty() && (!I.CornersUploaded || !I.CornerTable->GetHandle()))
  {
    I.CornersUploaded = true;
    const int rows = int(I.CornerTexels.size() / (4 * std::size_t(I.CornerWidth)));
    const int maxSize = I.Queue->maxTextureSize > 0 ? I.Queue->maxTextureSize : 4096;
    if (rows > maxSize || I.CornerWidth > maxSize)
    {
      I.CornerTexels.clear();
      I.CornerWidth = 0; // every trail normal then reads (0, 0, 1)
      vtkWarningMacro(<< "The template's " << rows
                      << " particles are too many for one texture; the display lights its "
                         "trails with a fixed normal.");
    }
    else
    {
      I.CornerTable->SetContext(window);
      I.CornerTable->SetInternalFormat(GL_RGBA32I);
      I.CornerTable->SetFormat(GL_RGBA_INTEGER);
      I.CornerTable->Create2DFromRaw(
        unsigned(I.CornerWidth), unsigned(rows), 4, VTK_INT, I.CornerTexels.data());
    }
  }

  // The trail's slots to draw, newest first: those recorded strictly before
  // the time shown (a step shown and taken back leaves none ahead of it), as
  // the CPU output's trailPoses(). Their opacity falls with age, by the
  // colour map where it maps opacity (colouring by Age, say), otherwise by
  // the display's own fade, 1 - age / (span + interval): the newest pose,
  // one interval old, at L / (L + 1), the oldest at 1 / (L + 1).
  struct TrailDraw
  {
    unsigned positions, elements;
    float age, fade;
  };
  std::vector<TrailDraw> trailDraws;
  const bool mapFades = this->ColorMapIsTranslucent();
  const double fadeSpan = I.TrailSpan + I.TrailInterval;
  for (const auto& slot : I.Inputs.trail)
  {
    const double time = I.Queue->draw.time;
    if (slot.time < time && slot.positions && slot.elements)
    {
      const double age = time - slot.time;
      const double fade = mapFades || !(fadeSpan > 0.0) ? 1.0 : 1.0 - age / fadeSpan;
      trailDraws.push_back(
        { slot.positions, slot.elements, float(age), float(std::min(std::max(fade, 0.0), 1.0)) });
    }
  }

  // The engine's textures on units VTK hands out.
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  const unsigned textures[vtkInternals::TextureCount] = { I.Inputs.positions, I.Inputs.normals,
    I.Inputs.samples, I.Inputs.elements, I.Inputs.centers,
    linkCount > 0 ? I.LinkTable->GetHandle() : 0u, I.Inputs.poses, I.Inputs.spins, 0u, 0u,
    I.CornerWidth > 0 ? I.CornerTable->GetHandle() : 0u };
  for (int k = 0; k < vtkInternals::TextureCount; ++k)
  {
    I.Units[k] = units->Allocate();
    state->vtkglActiveTexture(GLenum(GL_TEXTURE0 + I.Units[k]));
    glBindTexture(GL_TEXTURE_2D, textures[k]);
  }

  const int representation = act->GetProperty()->GetRepresentation();
  for (int p = PrimitiveStart; p <= PrimitiveTris; ++p)
  {
    this->DrawingVertices = false;
    this->DrawingSelection = false;
    vtkOpenGLHelper& helper = this->Primitives[p];
    // The line shader also draws the links; a stand-in line cell is not drawn.
    const bool elementCells = p != PrimitiveLines || I.TemplateLines;
    const bool linkCells = p == PrimitiveLines && linkCount > 0;
    if (!helper.IBO->IndexCount || !(elementCells || linkCells))
    {
      continue;
    }
    GLenum mode = this->GetOpenGLMode(representation, p);
    this->UpdateShaders(helper, ren, act);
    if (!helper.Program)
    {
      I.LastError = "The Bound Particles drawing shader does not compile; see the error above.";
      continue;
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
      helper.IBO->Bind();
      glDrawElementsInstanced(mode, GLsizei(helper.IBO->IndexCount), GL_UNSIGNED_INT, nullptr,
        GLsizei(I.Inputs.elementCount));
      // Each trail pose shown: the same cells again, positions from the
      // slot's copy of the particle texture (the engine's ring, nothing
      // uploaded); elements of another generation there are clipped.
      for (const TrailDraw& t : trailDraws)
      {
        state->vtkglActiveTexture(GLenum(GL_TEXTURE0 + I.Units[vtkInternals::TrailPositions]));
        glBindTexture(GL_TEXTURE_2D, t.positions);
        state->vtkglActiveTexture(GLenum(GL_TEXTURE0 + I.Units[vtkInternals::TrailElements]));
        glBindTexture(GL_TEXTURE_2D, t.elements);
        helper.Program->SetUniformi("bpTrail", 1);
        helper.Program->SetUniformf("bpTrailAge", t.age);
        helper.Program->SetUniformf("bpFade", t.fade);
        glDrawElementsInstanced(mode, GLsizei(helper.IBO->IndexCount), GL_UNSIGNED_INT, nullptr,
          GLsizei(I.Inputs.elementCount));
      }
      if (!trailDraws.empty())
      {
        helper.Program->SetUniformi("bpTrail", 0);
        helper.Program->SetUniformf("bpTrailAge", 0.0f);
        helper.Program->SetUniformf("bpFade", 1.0f);
      }
      helper.IBO->Release();
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

  for (int k = 0; k < vtkInternals::TextureCount; ++k)
  {
    state->vtkglActiveTexture(GLenum(GL_TEXTURE0 + I.Units[k]));
    glBindTexture(GL_TEXTURE_2D, 0);
    units->Free(I.Units[k]);
    I.Units[k] = -1;
  }
  I.ColorTable->Deactivate();
}

void vtkOpenGLBoundParticleMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& I = *this->Internals;
  if (I.Configured)
  {
    if (window)
    {
      static_cast<vtkOpenGLRenderWindow*>(window)->MakeCurrent();
      GLStateGuard guard;
      I.Engine.release();
    }
    I.Configured = false;
    if (I.Queue)
    {
      // The state is gone: what is queued continues from it, so the filter
      // must replay into this queue.
      I.Queue->clear();
      I.Queue->cursor.valid = false;
    }
  }
  I.ColorTable->ReleaseGraphicsResources(window);
  I.LinkTable->ReleaseGraphicsResources(window);
  I.LinksUploaded = false;
  I.CornerTable->ReleaseGraphicsResources(window);
  I.CornersUploaded = false;
  I.LinkVAO->ReleaseGraphicsResources();
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLBoundParticleMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarMode: " << int(this->Internals->ScalarMode) << "\n";
  os << indent << "Configured: " << this->Internals->Configured << "\n";
  os << indent << "TrailSpan: " << this->Internals->TrailSpan << "\n";
}
