// SPDX-License-Identifier: BSD-3-Clause
#include "TracerTimeLine.h"

#include "TracerConfig.h"
#include "TracerFieldProbe.h"
#include "TracerFtleMap.h"
#include "TracerInSitu.h"
#include "VelocityNames.h"

#include "vtkAlgorithm.h"
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

namespace bpvtk
{

bool TimeLineSettings::automatic(const std::vector<double>& inputTimes) const
{
  return inputTimes.size() >= 2
    ? this->framesPerInputStep <= 0 || this->framesPerInputStep > bp::MaxFramesPerInterval
    : this->duration <= 0.0;
}

bool TimeLineSettings::framesOutOfRange() const
{
  return this->framesPerInputStep < 0 || this->framesPerInputStep > bp::MaxFramesPerInterval;
}

bp::TimeLine TimeLineSettings::resolve(
  const std::vector<double>& inputTimes, const bp::TimeScale& scale) const
{
  return bp::resolveTimeLine(this->duration,
    this->framesOutOfRange() ? 0 : this->framesPerInputStep, this->numberOfTimeSteps,
    this->stepSize, this->stepInCellLengths, inputTimes, scale);
}

TracerTimeLine::TracerTimeLine(vtkAlgorithm* owner)
  : Owner(owner)
{
}

std::vector<double> TracerTimeLine::inputTimeSteps(vtkInformation* inInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  std::vector<double> inputTimes;
  if (inInfo && inInfo->Has(SDDP::TIME_STEPS()))
  {
    const double* steps = inInfo->Get(SDDP::TIME_STEPS());
    inputTimes.assign(steps, steps + inInfo->Length(SDDP::TIME_STEPS()));
  }
  return inputTimes;
}

bool TracerTimeLine::isSerialRun()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return !(controller && controller->GetNumberOfProcesses() > 1);
}

void TracerTimeLine::announce(vtkInformationVector* outputVector, const std::vector<double>* times,
  const TracerConfig& config, const FieldProbe& probe)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* mapInfo = outputVector->GetInformationObject(1);
  // The FTLE map and the state share the time line; the map's extent is the
  // lattice's, known from the settings and the field (empty for other releases).
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    if (!times)
    {
      info->Remove(SDDP::TIME_STEPS());
      info->Remove(SDDP::TIME_RANGE());
      continue;
    }
    const double range[2] = { times->front(), times->back() };
    info->Set(SDDP::TIME_STEPS(), times->data(), int(times->size()));
    info->Set(SDDP::TIME_RANGE(), range, 2);
  }
  bpvtk::announceFtleMap(mapInfo, config, times ? probe : bpvtk::FieldProbe());
}

TracerTimeLine::InputKey TracerTimeLine::inputKey() const
{
  vtkAlgorithmOutput* connection = this->Owner->GetNumberOfInputConnections(0) > 0
    ? this->Owner->GetInputConnection(0, 0)
    : nullptr;
  vtkAlgorithm* upstream = connection ? connection->GetProducer() : nullptr;
  auto* executive =
    upstream ? vtkDemandDrivenPipeline::SafeDownCast(upstream->GetExecutive()) : nullptr;
  return { upstream, connection ? connection->GetIndex() : -1,
    executive ? executive->GetPipelineMTime() : 0 };
}

void TracerTimeLine::restartUnitsCheck(const InputKey& key)
{
  this->Checked = key;
  this->Mismatched.clear();
  this->Fitting.clear();
  this->Reason.clear();
}

bool TracerTimeLine::beginUnitsCheck(bool unchosen)
{
  // Found while Vectors is not chosen, on the data the probe delivered
  // (nothing else updates for it); kept once it is (the note of why) while
  // the input is the same.
  const InputKey key = this->inputKey();
  const bool checks = key != this->Checked || unchosen;
  if (checks)
  {
    this->restartUnitsCheck(key);
  }
  return checks;
}

void TracerTimeLine::checkHeldInput(const TimeLineSettings& settings)
{
  // Found by RequestInformation on the input it saw. Asked before that (pvpython
  // sets the Vectors default as soon as Input is set, before it updates the
  // tracer's pipeline information): the data the input holds, as it holds
  // it, read without updating anything.
  const InputKey key = this->inputKey();
  if (key == this->Checked)
  {
    return;
  }
  this->restartUnitsCheck(key);
  vtkInformation* inInfo =
    std::get<0>(key) ? this->Owner->GetExecutive()->GetInputInformation(0, 0) : nullptr;
  vtkInformation* vectors = this->Owner->GetInputArrayInformation(0);
  const char* name = vectors && vectors->Has(vtkDataObject::FIELD_NAME())
    ? vectors->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  if (!inInfo || !inInfo->Has(vtkDataObject::DATA_OBJECT()) || (name && *name) || !isSerialRun() ||
    bpvtk::offersOnlyPresent(inInfo))
  {
    return;
  }
  const std::vector<double> inputTimes = inputTimeSteps(inInfo);
  if (settings.automatic(inputTimes))
  {
    this->preferFittingVectors(
      settings, inInfo->Get(vtkDataObject::DATA_OBJECT()), inInfo, inputTimes);
  }
}

void TracerTimeLine::preferFittingVectors(const TimeLineSettings& settings, vtkDataObject* data,
  vtkInformation* inInfo, const std::vector<double>& inputTimes)
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
    const bp::TimeLine line = settings.resolve(inputTimes, probe.scale);
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
  this->Mismatched = names[std::size_t(chosen)];
  this->Fitting = names[std::size_t(preferred)];
  this->Reason =
    bp::fittingUnitsReason(this->Mismatched, chosen == active, warnings[std::size_t(chosen)]);
}

std::string TracerTimeLine::reasonFor(const std::string& vectors, int association) const
{
  const bool preferred = !this->Fitting.empty() && vectors == this->Fitting &&
    association == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  return preferred ? this->Reason : std::string();
}

bp::TimeLine TracerTimeLine::resolve(const TimeLineSettings& settings,
  const std::vector<double>& inputTimes, const bp::TimeScale& scale, bool unchosen)
{
  if (inputTimes.size() >= 2 && settings.framesOutOfRange())
  {
    vtkErrorWithObjectMacro(this->Owner,
      "FramesPerInputStep must be 0 (automatic) to " << bp::MaxFramesPerInterval << " (it is "
                                                     << settings.framesPerInputStep
                                                     << "); using automatic frames.");
  }
  const bp::TimeLine line = settings.resolve(inputTimes, scale);
  // Of the array traced while Vectors is not chosen: said by an update that
  // still has none (ParaView sets the Vectors default just after this
  // request, and a warning of an array not traced misleads).
  this->Pending.clear();
  if (unchosen)
  {
    this->Pending = line.warnings;
    return line;
  }
  this->sayOnce(line.warnings);
  return line;
}

void TracerTimeLine::sayPending()
{
  if (!this->Pending.empty())
  {
    this->sayOnce(this->Pending);
    this->Pending.clear();
  }
}

void TracerTimeLine::sayOnce(const std::vector<std::string>& warnings)
{
  // Said once: the pipeline asks for information again after every change
  // (the Vectors set after the filter is made, say), and the same warning
  // twice in a row says nothing new.
  for (const std::string& warning : warnings)
  {
    if (std::find(this->Said.begin(), this->Said.end(), warning) == this->Said.end())
    {
      vtkWarningWithObjectMacro(this->Owner, << warning);
    }
  }
  this->Said = warnings;
}

} // namespace bpvtk
