// SPDX-License-Identifier: BSD-3-Clause
// In situ: an input that offers only its present time step, traced one step
// at a time (docs/design.md, "In situ").
#include "TracerInSitu.h"

#include "vtkAlgorithm.h"
#include "vtkBoundParticleTracerInternals.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationExecutivePortKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <sstream>

namespace
{
/// How far upstream the search for a trivial producer goes.
constexpr int MaxFiltersAbove = 16;
} // namespace

namespace bpvtk
{

bool offersOnlyPresent(vtkInformation* inInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  if (inInfo->Has(SDDP::NO_PRIOR_TEMPORAL_ACCESS()))
  {
    return true;
  }
#endif
  // A trivial producer holds one data object: whatever times it lists, only
  // the last is there (Catalyst's before VTK 9.3 flags nothing). Filters
  // between it and the tracer (ParaView's post filter, a Cell Data to Point
  // Data) pass its times on; what they give is what it holds.
  if (!inInfo->Has(SDDP::TIME_STEPS()) || inInfo->Length(SDDP::TIME_STEPS()) == 0)
  {
    return false;
  }
  vtkExecutive* executive = vtkExecutive::PRODUCER()->GetExecutive(inInfo);
  for (int depth = 0; executive && depth < MaxFiltersAbove; ++depth)
  {
    vtkAlgorithm* algorithm = executive->GetAlgorithm();
    if (vtkTrivialProducer::SafeDownCast(algorithm))
    {
      return true;
    }
    // Only a chain of single-input filters: anything else has another source.
    if (!algorithm || algorithm->GetNumberOfInputPorts() != 1 ||
      algorithm->GetNumberOfInputConnections(0) != 1)
    {
      return false;
    }
    executive = vtkExecutive::PRODUCER()->GetExecutive(executive->GetInputInformation(0, 0));
  }
  return false;
}

double presentTime(vtkInformation* inInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (inInfo->Has(SDDP::TIME_STEPS()) && inInfo->Length(SDDP::TIME_STEPS()) > 0)
  {
    return inInfo->Get(SDDP::TIME_STEPS())[inInfo->Length(SDDP::TIME_STEPS()) - 1];
  }
  vtkDataObject* data = inInfo->Get(vtkDataObject::DATA_OBJECT());
  if (data && data->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    return data->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP());
  }
  return 0.0;
}

std::vector<double> announcedGrid(vtkInformation* inInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  std::vector<double> grid;
  if (!inInfo->Has(SDDP::WHOLE_EXTENT()))
  {
    return grid;
  }
  const int* extent = inInfo->Get(SDDP::WHOLE_EXTENT());
  grid.assign(extent, extent + 6);
  // Under MPI a process may hold a piece with no points: its origin and
  // spacing are VTK's defaults, not the grid's (offerStreamTime takes
  // another process's).
  vtkDataSet* data = vtkDataSet::SafeDownCast(inInfo->Get(vtkDataObject::DATA_OBJECT()));
  if (data && data->GetNumberOfPoints() == 0)
  {
    return grid;
  }
  for (vtkInformationDoubleVectorKey* key : { vtkDataObject::ORIGIN(), vtkDataObject::SPACING() })
  {
    if (inInfo->Has(key) && inInfo->Length(key) == 3)
    {
      grid.insert(grid.end(), inInfo->Get(key), inInfo->Get(key) + 3);
    }
  }
  return grid;
}

bool gridChanged(const std::vector<double>& before, const std::vector<double>& now)
{
  // The whole extent always; the origin and spacing where both announce them.
  if (before.size() < 6 || now.size() < 6)
  {
    return before != now;
  }
  const std::size_t compared = before.size() == now.size() ? now.size() : 6;
  return !std::equal(now.begin(), now.begin() + std::ptrdiff_t(compared), before.begin());
}

} // namespace bpvtk

std::string vtkBoundParticleTracerInternals::offerStreamTime(
  vtkMTimeType settingsTime, double time, const std::vector<double>& grid, std::string& warning)
{
  using Arrival = bp::StreamTimeLine::Arrival;
  // Under MPI each process holds its block of the last step only, and the
  // blocks follow the whole grid: a trace cannot follow the grid's change
  // (one process alone re-locates, matchHeldGrid), so every process starts
  // again, alike. They decide alike from one grid: the whole extent (every
  // process's input announces the same) with the origin and spacing of the
  // first process whose piece has points (an empty piece announces VTK's
  // defaults). A change of how the processes split the same grid is no
  // change: each gathers its block from the new pieces (gatherPiece) and
  // the elements stay with the blocks that own them.
  std::vector<double> agreed = grid;
  if (this->Plan.streaming() && this->Layout.distributed())
  {
    std::vector<double> full = grid.size() > 6 ? grid : std::vector<double>();
    this->Layout.shareFirst(full); // collective
    agreed = full.empty() ? grid : full;
  }
  bool regridded = this->Plan.streaming() && this->Layout.distributed() &&
    !this->InSitu.grid.empty() && bpvtk::gridChanged(this->InSitu.grid, agreed);
  if (this->Plan.streaming() && this->Layout.distributed())
  {
    // A grid kept before the processes agreed (the first step's) may lack
    // the origin and spacing on one of them: one decision for all.
    regridded = this->Layout.globalMax(regridded ? 1.0 : 0.0) > 0.0; // collective
  }
  if (regridded)
  {
    std::ostringstream text;
    text << "The input's grid changed at t = " << time
         << ": under MPI the trace cannot follow a change of grid in situ (each process holds "
            "its block of the last step only), so it starts again at the present step.";
    warning = text.str();
  }
  this->InSitu.grid = agreed;
  // Upstream changes with every step that arrives; only a change of the
  // filter's settings (or a first step, or a post hoc line before, or a
  // change of grid under MPI) starts the trace again, at the present step.
  if (!this->Plan.streaming() || settingsTime != this->InSitu.settingsTime || regridded)
  {
    this->forgetTrace();
    this->InSitu.stream.clear();
    this->InSitu.settingsTime = settingsTime;
  }
  const Arrival arrival = this->InSitu.stream.offer(time);
  if (this->InSitu.stream.empty())
  {
    // A first step with no usable time: nothing to start from.
    this->Plan = bp::TracePlan();
    std::ostringstream error;
    error << "The input's present time step is at t = " << time
          << "; a time step handed in situ must have a finite time.";
    return error.str();
  }
  // The first step announced again is no step lost (5.11's Catalyst hands
  // its producer the first step twice, and says so itself): refused quietly.
  const bool firstAgain = arrival == Arrival::Repeat && this->InSitu.stream.times().size() == 1;
  warning += firstAgain ? std::string() : this->InSitu.stream.refusal(arrival, time);
  this->Plan.setStreamTimes(this->InSitu.stream.times());
  return std::string();
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::skipPresentStep(const std::string& error)
{
  const bool kept = this->Plan.streaming() && !this->Update.decision.replay &&
    this->stepper().cursor.valid && this->InSitu.stream.times().size() > 1;
  if (!kept)
  {
    return Pass::fail(error);
  }
  const double skipped = this->InSitu.stream.present();
  this->InSitu.stream.dropPresent();
  this->Plan.setStreamTimes(this->InSitu.stream.times());
  std::ostringstream text;
  text << error << " The step at t = " << skipped
       << " is skipped: the trace stays at t = " << this->InSitu.stream.present()
       << " and the next good step goes on from there.";
  return { Pass::Skipped, -1, text.str() };
}

void vtkBoundParticleTracerInternals::relocate(
  const bp::GridGeometry& grid, const bp::FieldSlice& slice)
{
  const std::size_t beyond = this->Held.cache.regrid(this->Held.grid, grid, slice);
  this->releaseIntoGrid(grid);
  // Once per configuration, as the mask's: a simulation that adapts its
  // grid would say it every step.
  if (!this->Said.first(bpvtk::Topic::GridChange))
  {
    return;
  }
  std::ostringstream text;
  text << "The input's grid changed at t = " << this->InSitu.stream.present() << " ("
       << this->Held.grid.dims[0] << " x " << this->Held.grid.dims[1] << " x "
       << this->Held.grid.dims[2] << " points to " << grid.dims[0] << " x " << grid.dims[1] << " x "
       << grid.dims[2]
       << ", or their coordinates): the elements keep their places and go on in the new grid. "
          "Until then the field blends the last step, resampled onto the new grid, with the "
          "present one";
  if (beyond > 0)
  {
    text << " (" << beyond << " of " << grid.pointCount()
         << " new points lie beyond the old grid; there the present step's velocity holds)";
  }
  text << "; elements outside the new grid are released again, into the new grid (the emitter "
          "box cut to it). Later changes of grid are followed alike, unannounced.";
  vtkWarningWithObjectMacro(this->Owner, << text.str());
}

void vtkBoundParticleTracerInternals::releaseIntoGrid(const bp::GridGeometry& grid)
{
  // Only a trace under way has an emitter box to move (a replay resolves
  // its own from the present grid); seed points are taken where they fit
  // in the new grid, and a lattice's points outside it stay hidden.
  if (!this->stepper().cursor.valid || this->Resolved.settings.seeded)
  {
    return;
  }
  bp::FieldFacts facts;
  facts.bounds = grid.bounds(); // in the engine's frame, which stays the trace's
  facts.offset = this->Held.offset;
  facts.dims = grid.dims;
  const bp::EmitterBox box =
    bp::emitterInChangedField(this->Resolved.settings, facts, this->Resolved.elementSize);
  this->Resolved.parameters.emitterMin = box.min;
  this->Resolved.parameters.emitterMax = box.max;
  this->stepper().setEmitter(box.min, box.max);
  // Said again only when it says something new (recorded even when empty).
  if (this->Said.first(bpvtk::Topic::Emitter, box.warning) && !box.warning.empty())
  {
    vtkWarningWithObjectMacro(this->Owner, << box.warning);
  }
}
