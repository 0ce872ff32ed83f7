// SPDX-License-Identifier: BSD-3-Clause
// vtkBoundParticleTracer's RequestInformation: the time line it offers, post
// hoc from the input's time steps, in situ one present step at a time
// (docs/design.md, "One update" and "In situ").
#include "vtkBoundParticleTracer.h"

#include "TraceSettings.h"
#include "TracerFieldProbe.h"
#include "TracerFtleMap.h"
#include "TracerInSitu.h"
#include "vtkBoundParticleTracerInternals.h"

#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

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
  const bpvtk::FieldProbe probe =
    (automatic || bpvtk::mapsLattice(config)) && inInfo->Has(vtkDataObject::DATA_OBJECT())
    ? this->ProbeField(inInfo, inputTimes)
    : bpvtk::FieldProbe();
  bp::TimeScale scale = automatic ? probe.scale : bp::TimeScale();
  if (automatic && probe.read)
  {
    // Heavy particles settle: the time line follows gravity where it is faster.
    scale.gravitySpeed = bp::gravityMotion(config.trace.engine, probe.facts).speed;
  }
  const bp::TimeLine line = this->ResolveTimeLine(inputTimes, scale);
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
  return bpvtk::probeField(this->GetInputConnection(0, 0), inInfo, inputTimes,
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
  const std::vector<double>& inputTimes, const bp::TimeScale& scale)
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
    this->StepSizeUnit == CELL_LENGTH, inputTimes, scale);
  // Said once: the pipeline asks for information again after every change
  // (the Vectors set after the filter is made, say), and the same warning
  // twice in a row says nothing new.
  for (const std::string& warning : this->Internals->unsaid(line.warnings))
  {
    vtkWarningMacro(<< warning);
  }
  return line;
}
