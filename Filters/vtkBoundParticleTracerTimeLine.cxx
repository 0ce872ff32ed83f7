// SPDX-License-Identifier: BSD-3-Clause
// vtkBoundParticleTracer's RequestInformation: the time line it offers, post
// hoc from the input's time steps, in situ one present step at a time
// (docs/design.md, "One update" and "In situ").
#include "vtkBoundParticleTracer.h"

#include "TraceSettings.h"
#include "TracerFieldProbe.h"
#include "TracerFtleMap.h"
#include "TracerInSitu.h"
#include "VelocityNames.h"
#include "vtkBoundParticleTracerInternals.h"

#include "vtkAlgorithmOutput.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"
#include "vtkRectilinearGrid.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>

int vtkBoundParticleTracer::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkBoundParticleTracerInternals& I = *this->Internals;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (bpvtk::offersOnlyPresent(inInfo))
  {
    return this->RequestStreamInformation(inInfo, outputVector);
  }
  // The pipeline asks for information again only when this filter or
  // something upstream changed: the trace is stale (first: the probe's
  // resampler then forgets its grid).
  I.forgetTrace();
  std::vector<double> inputTimes;
  if (inInfo->Has(SDDP::TIME_STEPS()))
  {
    const double* steps = inInfo->Get(SDDP::TIME_STEPS());
    inputTimes.assign(steps, steps + inInfo->Length(SDDP::TIME_STEPS()));
  }
  // The field is probed once here where the time line is automatic or the
  // FTLE map's extent (a lattice release's) depends on it.
  const bpvtk::TracerConfig config = this->Config();
  const bool automatic = this->AutomaticTimeLine(inputTimes);
  // Before Vectors is chosen (a tracer just made, whose default comes next:
  // vtkSMBoundParticleVectorsDomain) its warnings wait for an update.
  const bool unchosen = config.vectors.name.empty();
  // The Vectors default's units check (GetUnitsFittingVectors): found here
  // while Vectors is not chosen, on the data the probe delivered (nothing
  // else updates for it); kept once it is (the note of why) while the input
  // is the same.
  const UnitsCheckKey key = this->InputKey();
  const bool checksUnits = key != I.UnitsChecked || unchosen;
  if (checksUnits)
  {
    I.UnitsChecked = key;
    I.UnitsMismatchedVectors.clear();
    I.UnitsFittingVectors.clear();
    I.UnitsReason.clear();
  }
  bpvtk::FieldProbe probe;
  if ((automatic || bpvtk::mapsLattice(config)) && inInfo->Has(vtkDataObject::DATA_OBJECT()))
  {
    const bpvtk::DeliveredInput delivered(this->GetInputConnection(0, 0), inInfo, inputTimes);
    probe = this->ProbeDelivered(delivered.data(), inInfo, inputTimes);
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    // Serial runs only: the pieces of an MPI run may offer different arrays.
    if (checksUnits && unchosen && automatic &&
      !(controller && controller->GetNumberOfProcesses() > 1))
    {
      this->PreferFittingVectors(delivered.data(), inInfo, inputTimes);
    }
  }
  bp::TimeScale scale = automatic ? probe.scale : bp::TimeScale();
  if (automatic && probe.read)
  {
    // Heavy particles settle: the time line follows gravity where it is faster.
    scale.gravitySpeed = bp::gravityMotion(config.trace.engine, probe.facts).speed;
  }
  const bp::TimeLine line = this->ResolveTimeLine(inputTimes, scale, unchosen);
  const std::string error =
    I.setTimes(inputTimes, line.duration, this->NumberOfTimeSteps, line.framesPerInterval);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
  this->AnnounceTimes(outputVector, error.empty(), config, probe);
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
  this->AnnounceTimes(outputVector, error.empty(), config,
    error.empty() && bpvtk::mapsLattice(config) && inInfo->Has(vtkDataObject::DATA_OBJECT())
      ? this->ProbeField(inInfo, { time })
      : bpvtk::FieldProbe());
  return 1;
}

void vtkBoundParticleTracer::AnnounceTimes(vtkInformationVector* outputVector, bool hasTimes,
  const bpvtk::TracerConfig& config, const bpvtk::FieldProbe& probe)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* mapInfo = outputVector->GetInformationObject(1);
  // The FTLE map shares the time line; its extent is the lattice's, known
  // from the settings and the field (empty for other releases).
  for (vtkInformation* info : { outputVector->GetInformationObject(0), mapInfo })
  {
    if (!hasTimes)
    {
      info->Remove(SDDP::TIME_STEPS());
      info->Remove(SDDP::TIME_RANGE());
      continue;
    }
    const std::vector<double>& times = this->Internals->outputTimes();
    const double range[2] = { times.front(), times.back() };
    info->Set(SDDP::TIME_STEPS(), times.data(), int(times.size()));
    info->Set(SDDP::TIME_RANGE(), range, 2);
  }
  bpvtk::announceFtleMap(mapInfo, config, hasTimes ? probe : bpvtk::FieldProbe());
}

bool vtkBoundParticleTracer::AutomaticTimeLine(const std::vector<double>& inputTimes) const
{
  return inputTimes.size() >= 2
    ? this->FramesPerInputStep <= 0 || this->FramesPerInputStep > bp::MaxFramesPerInterval
    : this->Duration <= 0.0;
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

bp::TimeLine vtkBoundParticleTracer::ResolveTimeLine(
  const std::vector<double>& inputTimes, const bp::TimeScale& scale, bool unchosen)
{
  const bool unsteady = inputTimes.size() >= 2;
  const bool framesOutOfRange =
    this->FramesPerInputStep < 0 || this->FramesPerInputStep > bp::MaxFramesPerInterval;
  if (unsteady && framesOutOfRange)
  {
    vtkErrorMacro("FramesPerInputStep must be 0 (automatic) to "
      << bp::MaxFramesPerInterval << " (it is " << this->FramesPerInputStep
      << "); using automatic frames.");
  }
  const bp::TimeLine line = bp::resolveTimeLine(this->Duration,
    framesOutOfRange ? 0 : this->FramesPerInputStep, this->NumberOfTimeSteps, this->StepSize,
    this->StepSizeUnit == bp::StepUnit::CellLength, inputTimes, scale);
  // Of the array traced while Vectors is not chosen: said by an update that
  // still has none (ParaView sets the Vectors default just after this
  // request, and a warning of an array not traced misleads).
  this->Internals->PendingTimeLine.clear();
  if (unchosen)
  {
    this->Internals->PendingTimeLine = line.warnings;
    return line;
  }
  this->SayTimeLineWarnings(line.warnings);
  return line;
}

void vtkBoundParticleTracer::SayTimeLineWarnings(const std::vector<std::string>& warnings)
{
  // Said once: the pipeline asks for information again after every change
  // (the Vectors set after the filter is made, say), and the same warning
  // twice in a row says nothing new.
  for (const std::string& warning : this->Internals->unsaid(warnings))
  {
    vtkWarningMacro(<< warning);
  }
}

vtkBoundParticleTracer::UnitsCheckKey vtkBoundParticleTracer::InputKey()
{
  vtkAlgorithmOutput* connection =
    this->GetNumberOfInputConnections(0) > 0 ? this->GetInputConnection(0, 0) : nullptr;
  vtkAlgorithm* upstream = connection ? connection->GetProducer() : nullptr;
  auto* executive =
    upstream ? vtkDemandDrivenPipeline::SafeDownCast(upstream->GetExecutive()) : nullptr;
  return { upstream, connection ? connection->GetIndex() : -1,
    executive ? executive->GetPipelineMTime() : 0 };
}

void vtkBoundParticleTracer::CheckHeldInput()
{
  // Found by RequestInformation on the input it saw. Asked before that (pvpython
  // sets the Vectors default as soon as Input is set, before it updates the
  // tracer's pipeline information): the data the input holds, as it holds
  // it, read without updating anything.
  vtkBoundParticleTracerInternals& I = *this->Internals;
  const UnitsCheckKey key = this->InputKey();
  if (key == I.UnitsChecked)
  {
    return;
  }
  I.UnitsChecked = key;
  I.UnitsMismatchedVectors.clear();
  I.UnitsFittingVectors.clear();
  I.UnitsReason.clear();
  vtkInformation* inInfo =
    std::get<0>(key) ? this->GetExecutive()->GetInputInformation(0, 0) : nullptr;
  vtkInformation* vectors = this->GetInputArrayInformation(0);
  const char* name = vectors && vectors->Has(vtkDataObject::FIELD_NAME())
    ? vectors->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!inInfo || !inInfo->Has(vtkDataObject::DATA_OBJECT()) || (name && *name) ||
    (controller && controller->GetNumberOfProcesses() > 1) || bpvtk::offersOnlyPresent(inInfo))
  {
    return;
  }
  using SDDP = vtkStreamingDemandDrivenPipeline;
  std::vector<double> inputTimes;
  if (inInfo->Has(SDDP::TIME_STEPS()))
  {
    const double* steps = inInfo->Get(SDDP::TIME_STEPS());
    inputTimes.assign(steps, steps + inInfo->Length(SDDP::TIME_STEPS()));
  }
  if (this->AutomaticTimeLine(inputTimes))
  {
    this->PreferFittingVectors(inInfo->Get(vtkDataObject::DATA_OBJECT()), inInfo, inputTimes);
  }
}

void vtkBoundParticleTracer::PreferFittingVectors(
  vtkDataObject* data, vtkInformation* inInfo, const std::vector<double>& inputTimes)
{
  // A mesh is resampled for one array only: images and rectilinear grids.
  vtkDataSet* field = vtkImageData::SafeDownCast(data)
    ? static_cast<vtkDataSet*>(vtkImageData::SafeDownCast(data))
    : vtkRectilinearGrid::SafeDownCast(data);
  if (!field)
  {
    return;
  }
  std::vector<std::string> names;
  int active = -1;
  vtkPointData* points = field->GetPointData();
  for (int i = 0; i < points->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = points->GetArray(i);
    if (array && array->GetNumberOfComponents() == 3 && array->GetName() &&
      std::find(names.begin(), names.end(), array->GetName()) == names.end())
    {
      active = array == points->GetVectors() ? int(names.size()) : active;
      names.emplace_back(array->GetName());
    }
  }
  if (names.size() < 2)
  {
    return;
  }
  const bool framesOutOfRange =
    this->FramesPerInputStep < 0 || this->FramesPerInputStep > bp::MaxFramesPerInterval;
  std::vector<bp::VectorsCandidate> candidates(names.size());
  std::vector<std::string> warnings(names.size());
  const auto check = [&](std::size_t k)
  {
    const bpvtk::FieldProbe probe = bpvtk::probeDelivered(field, inInfo, inputTimes,
      [&](vtkDataObject* d, vtkSmartPointer<vtkDataObject>& grid, int& association)
      {
        grid = d;
        association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
        auto* set = vtkDataSet::SafeDownCast(d);
        return set ? set->GetPointData()->GetArray(names[k].c_str()) : nullptr;
      });
    const bp::TimeLine line = bp::resolveTimeLine(this->Duration,
      framesOutOfRange ? 0 : this->FramesPerInputStep, this->NumberOfTimeSteps, this->StepSize,
      this->StepSizeUnit == bp::StepUnit::CellLength, inputTimes, probe.scale);
    // An array that cannot be read, or does not move, is no better choice.
    candidates[k] = { names[k], probe.read && probe.scale.valid() && line.warnings.empty() };
    warnings[k] = line.warnings.empty() ? std::string() : line.warnings.front();
  };
  const int chosen = bp::pickDefaultVectors(names, active);
  check(std::size_t(chosen));
  if (candidates[std::size_t(chosen)].unitsFit || warnings[std::size_t(chosen)].empty())
  {
    return; // it fits, or it was not read: nothing to prefer it for
  }
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    if (int(k) != chosen)
    {
      check(k);
    }
  }
  const int preferred = bp::preferFittingUnits(candidates, chosen);
  if (preferred == chosen)
  {
    return;
  }
  vtkBoundParticleTracerInternals& I = *this->Internals;
  I.UnitsMismatchedVectors = names[std::size_t(chosen)];
  I.UnitsFittingVectors = names[std::size_t(preferred)];
  I.UnitsReason = bp::fittingUnitsReason(
    I.UnitsMismatchedVectors, chosen == active, warnings[std::size_t(chosen)]);
}
