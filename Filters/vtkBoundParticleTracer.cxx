// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleTracer.h"

#include "ElementTemplate.h"
#include "Memory.h"
#include "OutputArrays.h"
#include "TraceSettings.h"
#include "TracerConfig.h"
#include "TracerFieldProbe.h"
#include "TracerFtleMap.h"
#include "TracerInSitu.h"
#include "TracerInput.h"
#include "TracerPorts.h"
#include "TracerTimeLine.h"
#include "vtkBoundParticleSeedType.h"
#include "vtkBoundParticleTracerInternals.h"

#include "vtkDataArraySelection.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <new>

// The request key's DataKey is where the output keeps the value it was made for.
class vtkInformationGpuWorkQueueRequestKey : public vtkInformationIntegerRequestKey
{
public:
  vtkInformationGpuWorkQueueRequestKey(const char* name, const char* location)
    : vtkInformationIntegerRequestKey(name, location)
  {
    this->DataKey = vtkBoundParticleTracer::DATA_GPU_WORK_QUEUE();
  }
};
vtkInformationKeyMacro(vtkBoundParticleTracer, DATA_GPU_WORK_QUEUE, Integer);
vtkInformationKeySubclassMacro(
  vtkBoundParticleTracer, GPU_WORK_QUEUE, GpuWorkQueueRequest, IntegerRequest);

vtkStandardNewMacro(vtkBoundParticleTracer);

vtkBoundParticleTracer::vtkBoundParticleTracer()
  : Internals(new vtkBoundParticleTracerInternals(this))
  , TimeLine(new bpvtk::TracerTimeLine(this))
{
  this->SetNumberOfInputPorts(4);
  // The elements, the FTLE map of a lattice release (TracerFtleMap.h), the
  // trace's state to save (TracerPorts.h) and the events at the field's
  // sides (TracerInteractions.h).
  this->SetNumberOfOutputPorts(bpvtk::TracerPortCount);
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    // Off by default (the table's flags): the pose arrays (a fit per element a
    // step) and the deformation arrays (a fit per element an output).
    this->OutputArraySelection->AddArray(row.name, row.onByDefault);
  }
  // By default the active point vectors (or, failing that, the first
  // 3-component point array).
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
}

void vtkBoundParticleTracer::ReturnFreedMemory()
{
  bp::returnFreedMemory();
}

vtkBoundParticleTracer::~vtkBoundParticleTracer()
{
  // The trace, its field time steps and its output's memory are freed here:
  // handed back to the system, so Delete and Reset Session show it.
  this->Internals.reset();
  bp::returnFreedMemory();
}

double vtkBoundParticleTracer::GetSimulationTime() const
{
  return this->Internals->dataTarget();
}
vtkIdType vtkBoundParticleTracer::GetStepsInLastUpdate() const
{
  return this->Internals->stepsInLastUpdate();
}
bool vtkBoundParticleTracer::GetLastUpdateReplayed() const
{
  return this->Internals->lastUpdateReplayed();
}
vtkIdType vtkBoundParticleTracer::GetCheckpointSpacing() const
{
  return this->Internals->checkpointEvery();
}
int vtkBoundParticleTracer::GetNumberOfCachedTimeSteps() const
{
  return this->Internals->timeStepsHeld();
}
double vtkBoundParticleTracer::GetResolvedTimeStep() const
{
  return this->Internals->resolvedDt();
}
double vtkBoundParticleTracer::GetResolvedElementSize() const
{
  return this->Internals->resolvedElementSize();
}

const char* vtkBoundParticleTracer::GetUnitsMismatchedVectors()
{
  this->TimeLine->checkHeldInput(this->TimeLineProperties());
  return this->TimeLine->mismatchedVectors().c_str();
}

const char* vtkBoundParticleTracer::GetUnitsFittingVectors()
{
  this->TimeLine->checkHeldInput(this->TimeLineProperties());
  return this->TimeLine->fittingVectors().c_str();
}

bpvtk::TracerInputStep vtkBoundParticleTracer::InputStep(vtkInformationVector** inputVector)
{
  bpvtk::TracerInputStep step;
  step.data = vtkDataObject::GetData(inputVector[0], 0);
  step.association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  // Only a dataset has point data to choose from (readSlice says what else
  // came); a mesh is resampled first, and its grid's array is used instead.
  if (vtkDataSet::SafeDownCast(step.data) && !bpvtk::FieldResampler::needed(step.data))
  {
    step.vectors = this->GetInputArrayToProcess(0, inputVector, step.association);
    vtkInformation* chosen = this->GetInputArrayInformation(0);
    if (step.vectors && chosen && chosen->Has(vtkDataObject::FIELD_NAME()) &&
      step.association == vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      step.vectorsFromCells = bpvtk::cellVectorsMadePoints(
        inputVector[0]->GetInformationObject(0), chosen->Get(vtkDataObject::FIELD_NAME()));
    }
  }
  return step;
}

int vtkBoundParticleTracer::FillInputPortInformation(int port, vtkInformation* info)
{
  // Any data object on every port, so that a wrong type gets an error that
  // says what to do rather than the pipeline's generic type mismatch, and
  // composite data (a multiblock) reaches the tracer whole: the composite
  // pipeline would otherwise run this multi-pass update once per block. A
  // process given no data at all still takes part in the collective steps of
  // a distributed update, instead of leaving the others waiting.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  if (port >= 1) // the template, the Seed Source and the Surfaces
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkBoundParticleTracer::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkImageData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

void vtkBoundParticleTracer::SetTemplateData(vtkPolyData* shape)
{
  this->SetInputDataInternal(1, shape);
}

void vtkBoundParticleTracer::SetSeedType(vtkBoundParticleSeedType* seeds)
{
  if (this->SeedType != seeds)
  {
    this->SeedType = seeds;
    this->Modified();
  }
}

vtkBoundParticleSeedType* vtkBoundParticleTracer::GetSeedType()
{
  return this->SeedType;
}

vtkMTimeType vtkBoundParticleTracer::GetMTime()
{
  // The seeds' parameters are set on their own object (ParaView's Seed Type
  // proxy): a change there must replay the trace as a change here does.
  // So are the output arrays, when a script sets them through
  // GetOutputArraySelection().
  const vtkMTimeType own =
    std::max(this->Superclass::GetMTime(), this->OutputArraySelection->GetMTime());
  return this->SeedType ? std::max(own, this->SeedType->GetMTime()) : own;
}

int vtkBoundParticleTracer::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The time line it offers: post hoc from the input's time steps
  // (bpvtk::TracerTimeLine), in situ one present step at a time.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (bpvtk::offersOnlyPresent(inInfo))
  {
    return this->RequestStreamInformation(inInfo, outputVector);
  }
  // The pipeline asks for information again only when this filter or
  // something upstream changed: the trace is stale (first: the probe's
  // resampler then forgets its grid).
  this->Internals->forgetTrace();
  const std::vector<double> inputTimes = bpvtk::TracerTimeLine::inputTimeSteps(inInfo);
  const bpvtk::TracerConfig config = this->Config();
  const bpvtk::TimeLineSettings settings = this->TimeLineProperties();
  const bool automatic = settings.automatic(inputTimes);
  // Before Vectors is chosen (a tracer just made, whose default comes next:
  // vtkSMBoundParticleVectorsDomain) its warnings wait for an update.
  const bool unchosen = config.vectors.name.empty();
  const bool checksUnits = this->TimeLine->beginUnitsCheck(unchosen);
  // The field is probed once here where the time line is automatic or the
  // FTLE map's extent (a lattice release's) depends on it.
  bpvtk::FieldProbe probe;
  if ((automatic || bpvtk::mapsLattice(config)) && inInfo->Has(vtkDataObject::DATA_OBJECT()))
  {
    const bpvtk::DeliveredInput delivered(this->GetInputConnection(0, 0), inInfo, inputTimes);
    probe = this->ProbeDelivered(delivered.data(), inInfo, inputTimes);
    if (checksUnits && unchosen && automatic && bpvtk::TracerTimeLine::isSerialRun())
    {
      this->TimeLine->preferFittingVectors(settings, delivered.data(), inInfo, inputTimes);
    }
  }
  bp::TimeScale scale = automatic ? probe.scale : bp::TimeScale();
  if (automatic && probe.read)
  {
    // Heavy particles settle: the time line follows gravity where it is faster.
    scale.gravitySpeed = bp::gravityMotion(config.trace.engine, probe.facts).speed;
  }
  const bp::TimeLine line = this->TimeLine->resolve(settings, inputTimes, scale, unchosen);
  const std::string error = this->Internals->setTimes(inputTimes, line.duration,
    this->NumberOfTimeSteps, line.framesPerInterval, this->TimeDirection);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
  bpvtk::TracerTimeLine::announce(
    outputVector, error.empty() ? &this->Internals->outputTimes() : nullptr, config, probe);
  return 1;
}

int vtkBoundParticleTracer::RequestStreamInformation(
  vtkInformation* inInfo, vtkInformationVector* outputVector)
{
  const double time = bpvtk::presentTime(inInfo);
  std::string warning;
  // Upstream changes with every step that arrives; only a change of this
  // filter's settings starts the trace again.
  const std::string error =
    this->Internals->offerStreamTime(this->GetMTime(), time, bpvtk::announcedGrid(inInfo), warning);
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
  const bpvtk::TracerConfig config = this->Config();
  bpvtk::TracerTimeLine::announce(outputVector,
    error.empty() ? &this->Internals->outputTimes() : nullptr, config,
    error.empty() && bpvtk::mapsLattice(config) && inInfo->Has(vtkDataObject::DATA_OBJECT())
      ? this->ProbeField(inInfo, { time })
      : bpvtk::FieldProbe());
  return 1;
}

bpvtk::FieldProbe vtkBoundParticleTracer::ProbeField(
  vtkInformation* inInfo, const std::vector<double>& inputTimes)
{
  const bpvtk::DeliveredInput delivered(this->GetInputConnection(0, 0), inInfo, inputTimes);
  return this->ProbeDelivered(delivered.data(), inInfo, inputTimes);
}

bpvtk::FieldProbe vtkBoundParticleTracer::ProbeDelivered(
  vtkDataObject* data, vtkInformation* inInfo, const std::vector<double>& inputTimes)
{
  return bpvtk::probeDelivered(data, inInfo, inputTimes,
    [this](vtkDataObject* data, vtkSmartPointer<vtkDataObject>& grid, int& association)
    {
      if (bpvtk::FieldResampler::needed(data))
      {
        return this->Internals->probeGrid(this->Config(), data, grid);
      }
      grid = data;
      // Only a dataset has arrays to choose from (readSlice says what else came).
      return vtkDataSet::SafeDownCast(data) ? this->GetInputArrayToProcess(0, data, association)
                                            : nullptr;
    });
}

int vtkBoundParticleTracer::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkBoundParticleTracerInternals& I = *this->Internals;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  // One execution fills every output (TracerPorts.h).
  const int port = bpvtk::askedPort(request);
  vtkInformation* outInfo = outputVector->GetInformationObject(port);
  bpvtk::askOthersAlike(outputVector, port);

  const std::array<bool, 3> periodic = { this->Periodic[0] != 0, this->Periodic[1] != 0,
    this->Periodic[2] != 0 };
  I.requestPieces(outInfo, inInfo,
    bpvtk::FieldResampler::needed(inInfo->Get(vtkDataObject::DATA_OBJECT())), periodic);
  if (!I.continuing() && I.hasTimes())
  {
    // A new update: decide it once here, before anything is asked of
    // upstream. The pipeline may ask for an update extent without executing,
    // so the state changes wait for RequestData, which takes this decision.
    // The engine as the elements' display asks (port 0), whichever port asks
    // (the State output's: as the elements were last shown, decide()).
    vtkInformation* display = outputVector->GetInformationObject(0);
    I.decide(this->Config(), outInfo,
      display->Has(GPU_WORK_QUEUE()) ? display->Get(GPU_WORK_QUEUE()) : 0, port == bpvtk::StatePort);
    if (port == bpvtk::InteractionsPort)
    {
      I.decideInteractionsOnly(); // the events of the time shown: no step
    }
  }
  // The GPU request concerns this filter only. The pipeline copies request
  // keys upstream with every update-extent request; left there, each
  // alternation between the GPU display and another consumer would make
  // every algorithm upstream run again (a reader re-read its time step and
  // ParaView gathered its data information, every frame).
  inInfo->Remove(vtkBoundParticleTracer::GPU_WORK_QUEUE());
  bpvtk::requestWholeInputs(inputVector, I.hasTimes(), I.startTime());
  I.requestTimeStep(inInfo);
  return 1;
}

vtkTypeBool vtkBoundParticleTracer::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_NOT_GENERATED()))
  {
    bpvtk::markNotGenerated(request, outputVector,
      bpvtk::askedPort(request) == bpvtk::InteractionsPort && this->Internals->interactionsOnly());
    // Set before the executive reports 0: a state pass follows the elements'
    // update ParaView just ran, whose progress stays at its end; a new
    // update starts at 0 (a later pass of one holds the bar where it stands).
    if (bpvtk::askedPort(request) == bpvtk::StatePort)
    {
      this->SetProgressShiftScale(1.0, 0.0);
    }
    else if (!this->Internals->continuing())
    {
      this->SetProgressShiftScale(0.0, 1.0);
    }
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkBoundParticleTracer::ComputePipelineMTime(vtkInformation* request,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector, int port,
  vtkMTimeType* mtime)
{
  const int result =
    this->Superclass::ComputePipelineMTime(request, inputVector, outputVector, port, mtime);
  if (port == bpvtk::StatePort)
  {
    // The state saved is the time shown: out of date once another is shown.
    *mtime = std::max(*mtime, this->Internals->shownMTime());
  }
  return result;
}

int vtkBoundParticleTracer::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The checks before every large allocation leave only what they cannot
  // foresee (memory taken meanwhile): that ends the update with a message,
  // never the process.
  std::string failure;
  try
  {
    return this->ExecuteUpdatePass(request, inputVector, outputVector);
  }
  catch (const std::bad_alloc&)
  {
    failure = "Out of memory while tracing " + std::to_string(this->NumberOfElements) +
      " elements; use fewer elements or a smaller template, or close other data.";
  }
  catch (const std::exception& e)
  {
    // Nothing else is thrown on purpose: end the update, keep the session.
    failure = std::string("The trace failed: ") + e.what() + "; please report this with the input.";
  }
  vtkErrorMacro(<< failure);
  vtkBoundParticleTracerInternals& I = *this->Internals;
  I.endFailedUpdate();
  request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
  bpvtk::markFailedUpdate(request, outputVector, failure);
  return 1;
}

int vtkBoundParticleTracer::EndUpdatePass(
  const bpvtk::TracerPass& pass, vtkInformation* request, vtkInformationVector* outputs)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  using Pass = bpvtk::TracerPass;
  vtkBoundParticleTracerInternals& I = *this->Internals;
  if (pass.kind == Pass::NeedStep)
  {
    I.continueWith(pass.index);
    request->Set(SDDP::CONTINUE_EXECUTING(), 1);
    // The executive reports 1 at this pass's end and 0 at the next one's
    // start: hold the bar where the update stands until steps move it.
    this->SetProgressShiftScale(I.forState() ? 1.0 : I.progress(), 0.0);
    return 1;
  }
  if (pass.kind != Pass::Aborted)
  {
    vtkErrorMacro(<< pass.message);
  }
  I.endFailedUpdate(pass.kind == Pass::Skipped);
  request->Remove(SDDP::CONTINUE_EXECUTING());
  const bool saving = bpvtk::askedPort(request) == bpvtk::StatePort;
  vtkPolyData::GetData(outputs, saving ? bpvtk::StatePort : bpvtk::ElementsPort)->Initialize();
  if (pass.kind == Pass::Failed)
  {
    // Said once per update: the other ports' requests find the outputs up to date.
    bpvtk::markFailedUpdate(request, outputs, pass.message);
  }
  return 1;
}

int vtkBoundParticleTracer::ExecuteUpdatePass(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  using Pass = bpvtk::TracerPass;
  vtkBoundParticleTracerInternals& I = *this->Internals;
  const bpvtk::TracerConfig config = this->Config();
  if (I.interactionsOnly() && bpvtk::askedPort(request) == bpvtk::InteractionsPort)
  {
    // The engine stands at the time shown: its events are the whole update.
    I.showInteractionsAlone(vtkPolyData::GetData(outputVector, bpvtk::InteractionsPort));
    return 1;
  }
  // A request for the State output fills it alone (TracerPorts.h).
  const bool saving = bpvtk::askedPort(request) == bpvtk::StatePort;
  vtkPolyData* output = vtkPolyData::GetData(outputVector, saving ? bpvtk::StatePort : 0);
  output->Initialize();
  vtkImageData* ftleMap = vtkImageData::GetData(outputVector->GetInformationObject(1));
  if (!saving)
  {
    ftleMap->Initialize();
    this->SetProgressShiftScale(0.0, 1.0);
  }

  auto end = [&](const Pass& pass) { return this->EndUpdatePass(pass, request, outputVector); };
  // The time line's warnings of an update whose Vectors is still not chosen.
  this->TimeLine->sayPending();
  if (!I.hasTimes())
  {
    return end(Pass::fail("The filter has no time range; see the previous error."));
  }
  if (I.idle())
  {
    // Asked for a piece of several with no process per piece: piece 0 holds
    // the whole trace.
    return 1;
  }
  if (saving && I.readsShownState())
  {
    // The GPU display's engine read back where it stands: nothing to step.
    const Pass shown = I.showState(config, output);
    if (shown.kind != Pass::Done)
    {
      vtkErrorMacro(<< shown.message);
    }
    return 1;
  }
  if (!I.continuing())
  {
    I.begin(config);
    if (I.replayPending() && I.tooSmallToSplit())
    {
      vtkWarningMacro("The field has too few cells to give each of the "
        << vtkStreamingDemandDrivenPipeline::GetUpdateNumberOfPieces(
             outputVector->GetInformationObject(0))
        << " processes a block; process 0 traces it alone.");
    }
  }
  const std::string error = I.takeTimeStep(config, this->InputStep(inputVector));
  if (!error.empty())
  {
    return end(I.skipPresentStep(error));
  }
  Pass pass = I.replayPending() ? I.replay(config, inputVector) : Pass();
  if (pass.kind == Pass::Done)
  {
    pass = I.stepToTarget();
  }
  if (pass.kind == Pass::Done)
  {
    pass = I.readAhead();
  }
  if (pass.kind != Pass::Done)
  {
    return end(pass);
  }
  I.finishPasses();
  request->Remove(SDDP::CONTINUE_EXECUTING());
  // The state on the last step boundary reached (no short step shown), or
  // the elements; a state that cannot be saved leaves the trace as it is.
  const Pass shown = saving ? I.showState(config, output) : I.show(config, output);
  if (shown.kind != Pass::Done && !saving)
  {
    return end(shown);
  }
  if (shown.kind != Pass::Done)
  {
    vtkErrorMacro(<< shown.message);
  }
  else if (!saving)
  {
    I.showFtleMap(ftleMap);
    if (bpvtk::fillsInteractions(request, outputVector))
    {
      I.showInteractions(vtkPolyData::GetData(outputVector, bpvtk::InteractionsPort));
    }
  }
  return 1;
}

vtkDataArraySelection* vtkBoundParticleTracer::GetOutputArraySelection()
{
  return this->OutputArraySelection;
}

int vtkBoundParticleTracer::GetNumberOfOutputArrays()
{
  return this->OutputArraySelection->GetNumberOfArrays();
}

const char* vtkBoundParticleTracer::GetOutputArrayName(int index)
{
  return this->OutputArraySelection->GetArrayName(index);
}

int vtkBoundParticleTracer::GetOutputArrayStatus(const char* name)
{
  return name && this->OutputArraySelection->ArrayIsEnabled(name) ? 1 : 0;
}

void vtkBoundParticleTracer::SetOutputArrayStatus(const char* name, int status)
{
  if (name && !this->OutputArraySelection->ArrayExists(name))
  {
    // The selection offers every row and only those: a name it lacks is a
    // typo in a script or a state file, said rather than added.
    std::string offered;
    for (const bp::OutputArray& row : bp::outputArrays())
    {
      offered += (offered.empty() ? "" : ", ") + std::string(row.name);
    }
    vtkWarningMacro(
      "Output Arrays has no array named '" << name << "'; it offers " << offered << ".");
    return;
  }
  if (!name || this->GetOutputArrayStatus(name) == (status ? 1 : 0))
  {
    return;
  }
  this->OutputArraySelection->SetArraySetting(name, status ? 1 : 0);
  this->Modified();
}

void vtkBoundParticleTracer::DisableAllOutputArrays()
{
  if (this->OutputArraySelection->GetNumberOfArraysEnabled() > 0)
  {
    this->OutputArraySelection->DisableAllArrays();
    this->Modified();
  }
}

void vtkBoundParticleTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ElementShape: " << this->GetElementShapeAsString() << "\n";
  os << indent << "TemplateSprings: " << this->GetTemplateSpringsAsString() << "\n";
  os << indent << "ReleaseOrientation: " << this->GetReleaseOrientationAsString() << "\n";
  os << indent << "ReleasePattern: " << this->GetReleasePatternAsString() << "\n";
  os << indent << "Engine: " << this->GetEngineAsString() << "\n";
  os << indent << "StepSizeUnit: " << this->GetStepSizeUnitAsString() << "\n";
  os << indent << "Integrator: " << this->GetIntegratorAsString() << "\n";
  os << indent << "Restoration: " << this->GetRestorationAsString() << "\n";
  os << indent << "ShapeMatchingMode: " << this->GetShapeMatchingModeAsString() << "\n";
  os << indent << "Anchor: " << this->GetAnchorAsString() << "\n";
  os << indent << "Inertia: " << this->GetInertiaAsString() << "\n";
  os << indent << "Linking: " << this->GetLinkingAsString() << "\n";
  os << indent << "ResetWhen: " << this->GetResetWhenAsString() << "\n";
  os << indent << "Boundary: " << this->GetBoundaryAsString()
     << ", Restitution: " << this->Restitution << "\n";
  os << indent << "SurfaceInteraction: " << this->GetSurfaceInteractionAsString()
     << ", SurfaceInteractionArray: " << this->SurfaceInteractionArray << "\n";
  os << indent << "Periodic: " << this->Periodic[0] << " " << this->Periodic[1] << " "
     << this->Periodic[2] << "\n";
  os << indent << "ColoringAxis: " << char('X' + this->ColoringAxis) << "\n";
  os << indent << "NumberOfElements: " << this->NumberOfElements << "\n";
  os << indent << "ElementSize: " << this->ElementSize << "\n";
  os << indent << "EmitterCenter: " << this->EmitterCenter[0] << " " << this->EmitterCenter[1]
     << " " << this->EmitterCenter[2] << "\n";
  os << indent << "EmitterSize: " << this->EmitterSize[0] << " " << this->EmitterSize[1] << " "
     << this->EmitterSize[2] << "\n";
  os << indent << "LifetimeRange: " << this->LifetimeRange[0] << " " << this->LifetimeRange[1]
     << "\n";
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "CheckpointMemory: " << this->CheckpointMemory
     << (this->CheckpointMemory < 0.0 ? " (half the trace's size)\n" : " MiB\n");
  os << indent << "InitialStateFile: " << this->InitialStateFile << "\n";
  os << indent << "RestorationIterations: " << this->RestorationIterations << "\n";
  os << indent << "LatticeSpacing: " << this->LatticeSpacing << "\n";
  os << indent << "ResponseTime: " << this->ResponseTime << ", DensityRatio: " << this->DensityRatio
     << ", Gravity: " << this->Gravity[0] << " " << this->Gravity[1] << " " << this->Gravity[2]
     << "\n";
  os << indent << "MinimumReleaseSpeed: " << this->MinimumReleaseSpeed << "\n";
  os << indent << "Trails: " << this->Trails << " (" << this->TrailLength << " poses, every "
     << this->TrailSpacing << " steps)\n";
  os << indent << "ReleaseWindow: " << this->ReleaseWindow << " [" << this->ReleaseStart << ", "
     << this->ReleaseStop << "]\n";
  os << indent << "TimeDirection: " << this->GetTimeDirectionAsString() << "\n";
  os << indent << "SeedType: "
     << (this->SeedType ? this->SeedType->GetSeedTypeName() : "(none: the emitter box)") << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Duration: " << this->Duration
     << ", NumberOfTimeSteps: " << this->NumberOfTimeSteps
     << ", FramesPerInputStep: " << this->FramesPerInputStep << "\n";
  os << indent << "ComputeVorticity: " << this->ComputeVorticity << "\n";
}
