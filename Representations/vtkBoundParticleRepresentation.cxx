// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleRepresentation.h"

#include "BoundParticleWorkQueues.h"
#include "EngineChoice.h"
#include "OutputArrays.h"
#include "RendererNotes.h"
#include "TrailFade.h"
#include "WorkQueue.h"
#include "vtkBoundParticleTracer.h"
#include "vtkOpenGLBoundParticleMapper.h"
#include "vtkOpenGLKeptCellsMapper.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProcessModule.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkView.h"

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>

struct vtkBoundParticleRepresentation::vtkInternals
{
  /// The queue this display asks the tracer to record into, and its report's
  /// one writer, which the GPU mapper borrows.
  bp::DisplayWorkQueue Display = bpvtk::NewWorkQueue();
  /// The queue, read-only: the tracer records into it, the writer drains it.
  std::shared_ptr<const bp::WorkQueue> Queue = Display.queue;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkProperty> Property;
  vtkNew<vtkOpenGLBoundParticleMapper> GpuMapper;
  vtkNew<vtkOpenGLKeptCellsMapper> CpuMapper;
  /// The CPU output with trails that fade: its colours mapped here, their
  /// alpha scaled by age (TrailFade.h), drawn as direct scalars.
  vtkNew<vtkOpenGLKeptCellsMapper> FadeMapper;
  vtkNew<vtkPolyData> Faded;
  std::string FadedFrom; // what Faded's colours were made from
  vtkSmartPointer<vtkPolyData> Cache;
  double Bounds[6] = { 0, -1, 0, -1, 0, -1 };
  /// The GPU request is left on the input until the view renders, for this
  /// display's decorations (see RequestData).
  bool RequestHeld = false;
  bool Gpu = false; // the cached input is a GPU work order
  std::string ColorArray;
  bool GpuFailed = false;
  vtkMTimeType FailurePipelineTime = 0;
  /// The input's pipeline MTime at this display's last update request.
  vtkMTimeType RequestPipelineTime = 0;
  /// The tracer answered the GPU request with its CPU result (Engine CPU,
  /// Automatic on a software renderer, a distributed run). Until the
  /// pipeline or the renderer changes it would answer the same, so the
  /// request is not made: asked with the key and then without it by this
  /// display's decorations, the tracer ran twice every frame.
  bool CpuAnswer = false;
  vtkMTimeType CpuAnswerPipelineTime = 0;
  bp::RendererKind CpuAnswerRenderer = bp::RendererKind::Unknown;
  int TextureSizeLimit = 0;
  bool StreamTimeSteps = true;
  /// The last answer was Automatic's CPU engine (WorkQueue::automaticOnCpu()).
  bool AutomaticOnCpu = false;
  /// Why Automatic traces on the CPU engine was said (once per display).
  bool SaidAutomaticOnCpu = false;
};

vtkStandardNewMacro(vtkBoundParticleRepresentation);

vtkBoundParticleRepresentation::vtkBoundParticleRepresentation()
  : Internals(new vtkInternals)
{
  vtkInternals& I = *this->Internals;
  I.Actor->SetProperty(I.Property);
  I.Actor->SetMapper(I.CpuMapper);
  // The XML's (Surface's) defaults where VTK's differ (TestPropertyDefaults).
  I.Property->SetPointSize(2.0);
  I.Property->SetSpecularPower(100.0);
  I.CpuMapper->SetColorModeToMapScalars();
  I.GpuMapper->SetWorkQueue(I.Queue, &I.Display.writer);
  // The tracer's State output reads the GPU engine's state back through the
  // queue: the mapper does, in the context of the view this display is in.
  I.Display.writer.setStateReader(
    [this](bp::EngineState& state)
    {
      auto* view = vtkPVRenderView::SafeDownCast(this->GetView());
      return this->Internals->GpuMapper->ReadEngineState(
        view ? view->GetRenderWindow() : nullptr, state);
    });
  // ParaView listens to this display's progress and sets its abort flag: the
  // mapper reports a long GPU replay here and stops it on request.
  I.GpuMapper->SetContainerAlgorithm(this);
  // The CPU output's scalars look as the Surface representation draws them.
  I.CpuMapper->SetScalarModeToUsePointFieldData();
  I.CpuMapper->SetInterpolateScalarsBeforeMapping(1);
  I.CpuMapper->SetUseLookupTableScalarRange(1);
  I.CpuMapper->SetScalarVisibility(0);
  I.GpuMapper->SetUseLookupTableScalarRange(1);
  I.FadeMapper->SetScalarModeToUsePointFieldData();
  I.FadeMapper->SelectColorArray("BoundParticlesFadedColors");
  I.FadeMapper->SetColorModeToDirectScalars();
  I.FadeMapper->SetScalarVisibility(1);
}

vtkBoundParticleRepresentation::~vtkBoundParticleRepresentation()
{
  // The tracer may hold the queue a while longer: it must not call back here.
  this->Internals->Display.writer.setStateReader(nullptr);
  this->ReleaseGpuRequest();
  // A renderer may hold the mapper still: it keeps neither this display nor
  // the writer this display lent it.
  this->Internals->GpuMapper->SetContainerAlgorithm(nullptr);
  this->Internals->GpuMapper->SetWorkQueue(nullptr, nullptr);
}

namespace
{
/// The algorithm that feeds `consumer`, past ParaView's pass-through post filters.
vtkAlgorithm* FirstProducer(vtkAlgorithm* consumer)
{
  vtkAlgorithm* producer = consumer;
  do
  {
    producer = producer->GetNumberOfInputPorts() > 0 && producer->GetNumberOfInputConnections(0) > 0
      ? producer->GetInputAlgorithm(0, 0)
      : nullptr;
  } while (producer && producer->IsA("vtkPVPostFilter"));
  return producer;
}

/// Whether `consumer` draws something of its own from the data, as opposed
/// to a decoration of a display of it: the axes grids (bounds only) and the
/// selection's highlight (a plain geometry representation fed by ParaView's
/// selection extraction; the selected elements of a GPU display are not data
/// in this process).
bool NeedsElements(vtkDataRepresentation* consumer)
{
  if (consumer->IsA("vtkPVGridAxes3DRepresentation") ||
    consumer->IsA("vtkPolarAxesRepresentation") || consumer->IsA("vtkSelectionRepresentation") ||
    consumer->IsA("vtkPVCompositeRepresentation"))
  {
    return false;
  }
  vtkAlgorithm* producer = FirstProducer(consumer);
  const bool selectionHighlight =
    std::string(consumer->GetClassName()) == "vtkGeometryRepresentation" && producer &&
    producer->IsA("vtkPVExtractSelection");
  return !selectionHighlight;
}

/// Whether `source` is upstream of `algorithm` (or is it), through every
/// input connection; the connections hold references, so the walk is safe.
bool Reaches(vtkAlgorithm* algorithm, vtkAlgorithm* source, std::set<vtkAlgorithm*>& seen)
{
  if (!algorithm || !seen.insert(algorithm).second)
  {
    return false;
  }
  if (algorithm == source)
  {
    return true;
  }
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int k = 0; k < algorithm->GetNumberOfInputConnections(port); ++k)
    {
      if (Reaches(algorithm->GetInputAlgorithm(port, k), source, seen))
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

bool vtkBoundParticleRepresentation::ViewHasOtherConsumers()
{
  vtkView* view = this->GetView();
  vtkAlgorithm* source =
    this->GetNumberOfInputConnections(0) ? this->GetInputAlgorithm(0, 0) : nullptr;
  if (!view || !source)
  {
    return true; // nothing to tell: assume someone needs the elements
  }
  for (int i = 0; i < view->GetNumberOfRepresentations(); ++i)
  {
    auto* other = vtkPVDataRepresentation::SafeDownCast(view->GetRepresentation(i));
    if (!other || other == this || !other->GetVisibility() || !NeedsElements(other))
    {
      continue;
    }
    std::set<vtkAlgorithm*> seen;
    if (Reaches(other, source, seen))
    {
      return true;
    }
  }
  return false;
}

void vtkBoundParticleRepresentation::ReleaseGpuRequest()
{
  vtkInternals& I = *this->Internals;
  if (!I.RequestHeld)
  {
    return;
  }
  I.RequestHeld = false;
  vtkExecutive* executive = this->GetExecutive();
  if (this->GetNumberOfInputConnections(0) > 0 && executive)
  {
    if (vtkInformation* inInfo = executive->GetInputInformation(0, 0))
    {
      inInfo->Set(vtkBoundParticleTracer::GPU_WORK_QUEUE(), 0);
    }
  }
}

int vtkBoundParticleRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkBoundParticleRepresentation::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkInternals& I = *this->Internals;
  // After a GPU failure ask for the CPU result, until the pipeline changes.
  vtkMTimeType pipelineTime = 0;
  if (auto* executive = vtkStreamingDemandDrivenPipeline::SafeDownCast(
        this->GetInputAlgorithm() ? this->GetInputAlgorithm()->GetExecutive() : nullptr))
  {
    pipelineTime = executive->GetPipelineMTime();
  }
  // Known before the tracer decides wherever the view drew before (the GUI's
  // view draws its background first): Automatic then picks its engine, and
  // says so, at the display's first frame.
  bpvtk::recordRenderer(vtkPVRenderView::SafeDownCast(this->GetView()), I.Display.writer);
  bp::RendererReport& report = I.Display.writer.report();
  if (!report.failure.empty())
  {
    if (!I.GpuFailed)
    {
      I.GpuFailed = true;
      I.FailurePipelineTime = pipelineTime;
    }
    else if (pipelineTime != I.FailurePipelineTime)
    {
      // The user changed something: try the GPU again.
      I.GpuFailed = false;
      report.failure.clear();
    }
  }
  if (I.CpuAnswer &&
    (pipelineTime != I.CpuAnswerPipelineTime || report.renderer != I.CpuAnswerRenderer))
  {
    // A property changed, or Automatic now knows the renderer: ask again.
    I.CpuAnswer = false;
  }
  I.RequestPipelineTime = pipelineTime;
  report.streamTimeSteps = I.StreamTimeSteps;
  if (I.TextureSizeLimit > 0)
  {
    report.maxTextureSize = report.maxTextureSize > 0
      ? std::min(report.maxTextureSize, I.TextureSizeLimit)
      : I.TextureSizeLimit;
  }
  // The GPU engine's state lives in the GL context that draws it, so it runs
  // only where this process renders everything it traces: the built-in
  // session or a one-process pvbatch. A pvserver's data may be drawn by the
  // client (local rendering) and a parallel run's elements move between
  // processes, so there the tracer's CPU output is drawn and composited.
  vtkProcessModule* pm = vtkProcessModule::GetProcessModule();
  const int type = pm ? pm->GetProcessType() : vtkProcessModule::PROCESS_CLIENT;
  const bool gpuHere = type == vtkProcessModule::PROCESS_CLIENT ||
    (type == vtkProcessModule::PROCESS_BATCH && pm->GetNumberOfLocalPartitions() == 1);
  const bool ask = gpuHere && !I.GpuFailed && !I.CpuAnswer;
  for (int k = 0; k < inputVector[0]->GetNumberOfInformationObjects(); ++k)
  {
    inputVector[0]->GetInformationObject(k)->Set(
      vtkBoundParticleTracer::GPU_WORK_QUEUE(), ask ? I.Queue->id() : 0);
  }
  return 1;
}

int vtkBoundParticleRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInternals& I = *this->Internals;
  vtkMath::UninitializeBounds(I.Bounds);
  // Never null: a client (which has no input) takes part in delivering the
  // server's data for local rendering with this empty one.
  I.Cache = vtkSmartPointer<vtkPolyData>::New();
  I.Gpu = false;
  bool failedGpuAnswer = false;
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    vtkPolyData* input = vtkPolyData::GetData(inInfo);
    if (input)
    {
      I.Cache->ShallowCopy(input);
      auto* id =
        vtkIntArray::SafeDownCast(input->GetFieldData()->GetArray("BoundParticlesWorkQueue"));
      I.Gpu = id && id->GetNumberOfValues() == 1 && id->GetValue(0) == I.Queue->id();
      const bool asked = inInfo->Has(vtkBoundParticleTracer::GPU_WORK_QUEUE()) &&
        inInfo->Get(vtkBoundParticleTracer::GPU_WORK_QUEUE()) == I.Queue->id();
      // A failed update (a time jump of too many steps, an in situ step
      // skipped) has no SimulationTime and may go to the GPU at the next frame.
      failedGpuAnswer = !I.Gpu && asked && !input->GetFieldData()->GetArray("SimulationTime");
      // Asked for the GPU and given a finished CPU trace.
      if (!I.Gpu && asked && !failedGpuAnswer)
      {
        I.CpuAnswer = true;
        I.CpuAnswerPipelineTime = I.RequestPipelineTime;
        I.CpuAnswerRenderer = I.Queue->report().renderer;
      }
      if (asked && !failedGpuAnswer)
      {
        I.AutomaticOnCpu = !I.Gpu && I.Queue->automaticOnCpu();
        bpvtk::sayAutomaticOnCpu(I.AutomaticOnCpu, *I.Queue, I.SaidAutomaticOnCpu);
      }
      if (I.Gpu)
      {
        std::copy(I.Queue->draw().bounds.begin(), I.Queue->draw().bounds.end(), I.Bounds);
      }
      else if (input->GetNumberOfPoints() > 0)
      {
        // From the ranges the tracer cached on the points' array: no pass
        // over a million points per frame.
        for (int c = 0; c < 3; ++c)
        {
          input->GetPoints()->GetData()->GetRange(I.Bounds + 2 * c, c);
        }
      }
    }
    // The request is answered. Every consumer that needs the elements as data
    // (Surface, Save Data, filters, Fetch) must get the CPU result, so the
    // request is taken back: consumers never set it and the pipeline leaves
    // what they find. Only this display's decorations (the axes grid, the
    // selection) update between here and the render in the same view pass;
    // they need bounds and ranges, which the GPU output has, and would make
    // the CPU engine step every frame. So when nothing else in the view draws
    // from this data, the request is held until the view renders. So it is
    // after a failed update: the CPU engine would only fail again, and in situ
    // (a step skipped) it cannot go on from the GPU engine's state, so its
    // update would start the trace again at the next good step.
    if ((I.Gpu || failedGpuAnswer) && !this->ViewHasOtherConsumers())
    {
      I.RequestHeld = true;
    }
    else
    {
      inInfo->Set(vtkBoundParticleTracer::GPU_WORK_QUEUE(), 0);
    }
    // The render runs the recorded work and reports its progress from 0 to
    // 1: this update's own end (the executive's 1 after RequestData) would
    // make an observer see 0, 1, then the run's 0.03 ... 1. It reports 0 instead.
    const bool runFollows =
      I.Gpu && I.Queue->hasPending() && vtkOpenGLBoundParticleMapper::ReportsReplayProgress();
    this->SetProgressShiftScale(0.0, runFollows ? 0.0 : 1.0);
    if (runFollows)
    {
      I.GpuMapper->OweProgressEnd();
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkBoundParticleRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  vtkInternals& I = *this->Internals;
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVRenderView::SetPiece(inInfo, this, I.Cache);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, I.Bounds);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    this->ReleaseGpuRequest(); // the view's update pass is over
    bpvtk::recordRenderer(vtkPVRenderView::SafeDownCast(this->GetView()), I.Display.writer);
    bpvtk::sayAutomaticOnCpu(I.AutomaticOnCpu, *I.Queue, I.SaidAutomaticOnCpu);
    vtkDataObject* piece = vtkPVView::GetDeliveredPiece(inInfo, this);
    if (I.Gpu)
    {
      // The GPU output's Age spans [0, the oldest trail pose's age]: the
      // mapper knows from it that trails make the actor translucent before
      // it runs the configuration queued for this frame.
      vtkDataArray* age =
        I.Cache->GetPointData()->GetArray(bp::outputArray(bp::OutputArrayId::Age).name);
      I.GpuMapper->SetExpectedTrailSpan(
        age && age->GetNumberOfTuples() > 0 ? age->GetRange(0)[1] : 0.0);
      I.Actor->SetMapper(I.GpuMapper);
    }
    else
    {
      I.CpuMapper->SetInputDataObject(piece);
      I.Actor->SetMapper(this->FadesTrails(vtkPolyData::SafeDownCast(piece))
          ? static_cast<vtkMapper*>(I.FadeMapper)
          : static_cast<vtkMapper*>(I.CpuMapper));
    }
    this->UpdateColoring();
  }
  return 1;
}

void vtkBoundParticleRepresentation::SetStreamTimeSteps(bool stream)
{
  if (this->Internals->StreamTimeSteps != stream)
  {
    this->Internals->StreamTimeSteps = stream;
    this->Modified();
  }
}

void vtkBoundParticleRepresentation::SetGpuTextureSizeLimit(int texels)
{
  this->Internals->TextureSizeLimit = texels;
  this->Internals->GpuMapper->SetTextureSizeLimit(texels);
}

int vtkBoundParticleRepresentation::GetGpuTextureSizeLimit() const
{
  return this->Internals->TextureSizeLimit;
}

bool vtkBoundParticleRepresentation::GetStreamTimeSteps() const
{
  return this->Internals->StreamTimeSteps;
}

bool vtkBoundParticleRepresentation::FadesTrails(vtkPolyData* piece)
{
  vtkInternals& I = *this->Internals;
  const double span = bpvtk::trailFadeSpan(piece);
  vtkScalarsToColors* lut = I.CpuMapper->GetLookupTable();
  const bool mapped = !I.ColorArray.empty() && lut;
  if (mapped)
  {
    lut->Build();
  }
  // A colour map that maps opacity fades the trails itself (colouring by
  // Age, say), as on the GPU; direct colours are the user's own.
  if (!(span > 0.0) || (mapped && !lut->IsOpaque()) ||
    (mapped && I.CpuMapper->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS))
  {
    return false;
  }
  bpvtk::TrailColoring coloring;
  coloring.array = mapped ? I.ColorArray.c_str() : nullptr;
  coloring.component = mapped && lut->GetVectorMode() == vtkScalarsToColors::COMPONENT
    ? lut->GetVectorComponent()
    : -1;
  coloring.lut = mapped ? lut : nullptr;
  I.Property->GetDiffuseColor(coloring.solid);
  // Mapped again only when the data, the colouring or the colour change.
  const std::string from = std::to_string(reinterpret_cast<std::uintptr_t>(piece)) + " " +
    std::to_string(piece->GetMTime()) + " " + I.ColorArray + " " +
    std::to_string(coloring.component) + " " + std::to_string(mapped ? lut->GetMTime() : 0) + " " +
    std::to_string(coloring.solid[0]) + " " + std::to_string(coloring.solid[1]) + " " +
    std::to_string(coloring.solid[2]) + " " + std::to_string(span);
  if (from != I.FadedFrom)
  {
    vtkSmartPointer<vtkUnsignedCharArray> colors = bpvtk::fadedTrailColors(piece, coloring, span);
    if (!colors)
    {
      return false;
    }
    I.Faded->ShallowCopy(piece);
    I.Faded->GetPointData()->AddArray(colors);
    I.FadeMapper->SetInputDataObject(I.Faded);
    I.FadedFrom = from;
  }
  return true;
}

void vtkBoundParticleRepresentation::UpdateColoring()
{
  vtkInternals& I = *this->Internals;
  const bool scalars = !I.ColorArray.empty();
  I.CpuMapper->SetScalarVisibility(scalars ? 1 : 0);
  I.CpuMapper->SelectColorArray(I.ColorArray.c_str());
  I.GpuMapper->SetScalarVisibility(scalars ? 1 : 0);
  vtkScalarsToColors* lut = I.CpuMapper->GetLookupTable();
  const int component =
    lut && lut->GetVectorMode() == vtkScalarsToColors::COMPONENT ? lut->GetVectorComponent() : -1;
  if (!I.GpuMapper->SetColorArray(I.ColorArray.c_str(), component) && I.Gpu)
  {
    vtkWarningMacro(
      "The GPU engine cannot colour by '" << I.ColorArray << "'; drawing the solid colour.");
  }
}

bool vtkBoundParticleRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->AddActor(this->Internals->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkBoundParticleRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    this->ReleaseGpuRequest();
    rview->GetRenderer()->RemoveActor(this->Internals->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkBoundParticleRepresentation::SetVisibility(bool value)
{
  this->Superclass::SetVisibility(value);
  this->Internals->Actor->SetVisibility(value ? 1 : 0);
  if (!value)
  {
    this->ReleaseGpuRequest(); // e.g. another representation type was chosen
  }
}

void vtkBoundParticleRepresentation::SetInputArrayToProcess(
  int idx, int port, int connection, int fieldAssociation, const char* name)
{
  this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
  const bool points = fieldAssociation == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  this->Internals->ColorArray = points && name ? name : "";
  this->UpdateColoring();
}

void vtkBoundParticleRepresentation::SetLookupTable(vtkScalarsToColors* lut)
{
  this->Internals->CpuMapper->SetLookupTable(lut);
  this->Internals->GpuMapper->SetLookupTable(lut);
}

void vtkBoundParticleRepresentation::SetMapScalars(int value)
{
  const int mode = value ? VTK_COLOR_MODE_MAP_SCALARS : VTK_COLOR_MODE_DIRECT_SCALARS;
  this->Internals->CpuMapper->SetColorMode(mode);
}

void vtkBoundParticleRepresentation::SetInterpolateScalarsBeforeMapping(int value)
{
  this->Internals->CpuMapper->SetInterpolateScalarsBeforeMapping(value);
}

// Forwarded to the property.
void vtkBoundParticleRepresentation::SetColor(double r, double g, double b)
{
  this->Internals->Property->SetColor(r, g, b);
}
void vtkBoundParticleRepresentation::SetDiffuseColor(double r, double g, double b)
{
  this->Internals->Property->SetDiffuseColor(r, g, b);
}
void vtkBoundParticleRepresentation::SetAmbientColor(double r, double g, double b)
{
  this->Internals->Property->SetAmbientColor(r, g, b);
}
void vtkBoundParticleRepresentation::SetSpecularColor(double r, double g, double b)
{
  this->Internals->Property->SetSpecularColor(r, g, b);
}
void vtkBoundParticleRepresentation::SetOpacity(double value)
{
  this->Internals->Property->SetOpacity(value);
}
void vtkBoundParticleRepresentation::SetAmbient(double value)
{
  this->Internals->Property->SetAmbient(value);
}
void vtkBoundParticleRepresentation::SetDiffuse(double value)
{
  this->Internals->Property->SetDiffuse(value);
}
void vtkBoundParticleRepresentation::SetSpecular(double value)
{
  this->Internals->Property->SetSpecular(value);
}
void vtkBoundParticleRepresentation::SetSpecularPower(double value)
{
  this->Internals->Property->SetSpecularPower(value);
}
void vtkBoundParticleRepresentation::SetInterpolation(int value)
{
  this->Internals->Property->SetInterpolation(value);
}
void vtkBoundParticleRepresentation::SetPointSize(double value)
{
  this->Internals->Property->SetPointSize(value);
}
void vtkBoundParticleRepresentation::SetLineWidth(double value)
{
  this->Internals->Property->SetLineWidth(value);
}

// Forwarded to the actor.
void vtkBoundParticleRepresentation::SetPosition(double x, double y, double z)
{
  this->Internals->Actor->SetPosition(x, y, z);
}
void vtkBoundParticleRepresentation::SetScale(double x, double y, double z)
{
  this->Internals->Actor->SetScale(x, y, z);
}
void vtkBoundParticleRepresentation::SetOrientation(double x, double y, double z)
{
  this->Internals->Actor->SetOrientation(x, y, z);
}
void vtkBoundParticleRepresentation::SetOrigin(double x, double y, double z)
{
  this->Internals->Actor->SetOrigin(x, y, z);
}
void vtkBoundParticleRepresentation::SetUserTransform(const double matrix[16])
{
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(matrix);
  this->Internals->Actor->SetUserTransform(transform);
}
void vtkBoundParticleRepresentation::SetPickable(int value)
{
  this->Internals->Actor->SetPickable(value);
}

void vtkBoundParticleRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ColorArray: " << this->Internals->ColorArray << "\n";
  os << indent << "Gpu: " << this->Internals->Gpu << "\n";
}
