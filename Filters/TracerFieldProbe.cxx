// SPDX-License-Identifier: BSD-3-Clause
#include "TracerFieldProbe.h"

#include "TracerInput.h"
#include "VectorField.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationIntegerVectorKey.h"
#include "vtkMultiProcessController.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>

namespace bpvtk
{

namespace
{
/// This process's share, reduced with MAX over processes: top speed; lower
/// bounds negated and upper bounds per axis; the cell length; points per
/// axis (this grid's, or the image's whole extent's: each process holds a
/// piece of an image, a resampled mesh is whole everywhere); read (1 or 0);
/// the typical speed (the largest of the processes' own).
using Share = std::array<double, 13>;

Share localShare(vtkDataObject* data, vtkInformation* inInfo, const GridOf& gridOf)
{
  Share local = { 0, -1e300, -1e300, -1e300, -1e300, -1e300, -1e300, 0, 0, 0, 0, 0, 0 };
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkSmartPointer<vtkDataObject> field;
  vtkDataArray* vectors = gridOf(data, field, association);
  if (!field)
  {
    return local;
  }
  bp::GridGeometry grid;
  bp::FieldSlice slice;
  int extent[6];
  std::size_t nonFinite = 0;
  if (!readSlice(field, vectors, association, grid, slice, extent, nonFinite).empty() ||
    !grid.validate().empty())
  {
    return local;
  }
  const bp::VectorField sampled(grid, slice);
  local[0] = sampled.maxSpeed();
  local[12] = sampled.typicalSpeed();
  const std::array<double, 6> b = grid.bounds();
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int* whole = field == data && inInfo->Has(SDDP::WHOLE_EXTENT())
    ? inInfo->Get(SDDP::WHOLE_EXTENT())
    : nullptr;
  for (int a = 0; a < 3; ++a)
  {
    local[1 + 2 * a] = -b[2 * a];
    local[2 + 2 * a] = b[2 * a + 1];
    local[8 + a] = whole ? whole[2 * a + 1] - whole[2 * a] + 1 : grid.dims[a];
  }
  local[7] = grid.cellLength();
  local[11] = 1.0;
  return local;
}
} // namespace

namespace
{
using SDDP = vtkStreamingDemandDrivenPipeline;

/// The time of the data `info` (an output port's information) holds, if any.
bool heldTime(vtkInformation* info, double& time)
{
  vtkDataObject* data = info->Get(vtkDataObject::DATA_OBJECT());
  vtkInformation* dataInfo = data ? data->GetInformation() : nullptr;
  if (!dataInfo || !dataInfo->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    return false;
  }
  time = dataInfo->Get(vtkDataObject::DATA_TIME_STEP());
  return true;
}

/// The keys of a consumer's request.
std::array<vtkInformationKey*, 5> requestKeys()
{
  return { SDDP::UPDATE_TIME_STEP(), SDDP::UPDATE_EXTENT(), SDDP::UPDATE_PIECE_NUMBER(),
    SDDP::UPDATE_NUMBER_OF_PIECES(), SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS() };
}
} // namespace

DeliveredInput::DeliveredInput(
  vtkAlgorithmOutput* connection, vtkInformation* inInfo, const std::vector<double>& inputTimes)
  : Connection(connection)
  , Info(inInfo)
{
  vtkAlgorithm* upstream = connection ? connection->GetProducer() : nullptr;
  if (!upstream)
  {
    return;
  }
  // What the input's consumers asked for last (`inInfo` is the producer's
  // output information, shared by all of them).
  this->HeldOffered = heldTime(inInfo, this->HeldTime) && !inputTimes.empty() &&
    this->HeldTime >= inputTimes.front() && this->HeldTime <= inputTimes.back();
  this->Request = vtkSmartPointer<vtkInformation>::New();
  for (vtkInformationKey* key : requestKeys())
  {
    if (inInfo->Has(key))
    {
      this->Request->CopyEntry(inInfo, key);
    }
  }

  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int pieces = controller ? std::max(controller->GetNumberOfProcesses(), 1) : 1;
  const int piece = controller ? controller->GetLocalProcessId() : 0;
  if (inInfo->Has(SDDP::WHOLE_EXTENT()))
  {
    inInfo->Set(SDDP::UPDATE_EXTENT(), inInfo->Get(SDDP::WHOLE_EXTENT()), 6);
  }
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), piece);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), pieces);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  if (!inputTimes.empty())
  {
    inInfo->Set(SDDP::UPDATE_TIME_STEP(), inputTimes.front());
  }
  upstream->Update(connection->GetIndex());
  this->Data = inInfo->Get(vtkDataObject::DATA_OBJECT());
}

DeliveredInput::~DeliveredInput()
{
  if (!this->Request)
  {
    return;
  }
  // The consumers' request again; where the input held another time step
  // for them (a display, a downstream filter, shown at the view's time), the
  // input updated at that time again: its output is updated in place, and a
  // consumer that reads it without asking (a downstream filter's output)
  // would otherwise hold the probe's time step.
  for (vtkInformationKey* key : requestKeys())
  {
    this->Info->Remove(key);
    if (this->Request->Has(key))
    {
      this->Info->CopyEntry(this->Request, key);
    }
  }
  double delivered = 0.0;
  if (this->HeldOffered && this->Request->Has(SDDP::UPDATE_TIME_STEP()) &&
    (!heldTime(this->Info, delivered) || delivered != this->HeldTime))
  {
    this->Connection->GetProducer()->Update(this->Connection->GetIndex());
  }
}

FieldProbe probeDelivered(vtkDataObject* data, vtkInformation* inInfo,
  const std::vector<double>& inputTimes, const GridOf& gridOf)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int pieces = controller ? std::max(controller->GetNumberOfProcesses(), 1) : 1;
  Share share = localShare(data, inInfo, gridOf);
  if (pieces > 1)
  {
    Share global;
    controller->AllReduce(
      share.data(), global.data(), vtkIdType(share.size()), vtkCommunicator::MAX_OP);
    share = global;
  }
  FieldProbe probe;
  probe.read = share[11] > 0.5;
  if (!probe.read)
  {
    return probe;
  }
  // The whole field's bounds (grid-local: the engine's origin is the whole
  // grid's first point) and points per axis; its cell length as the
  // update's (PieceLayout::cellLength).
  bp::FieldFacts& f = probe.facts;
  for (int a = 0; a < 3; ++a)
  {
    const double lo = -share[1 + 2 * a], hi = share[2 + 2 * a];
    f.offset[a] = lo;
    f.bounds[2 * a] = 0.0;
    f.bounds[2 * a + 1] = hi - lo;
    f.dims[a] = int(share[8 + a]);
  }
  f.cellLength = share[7];
  f.maxSpeed = share[0];
  if (!inputTimes.empty())
  {
    f.timeSpan = inputTimes.back() - inputTimes.front();
  }
  // The time line's scale: the longest side, and the mean cell length over
  // the input's whole extent where it has one.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int* whole =
    inInfo->Has(SDDP::WHOLE_EXTENT()) ? inInfo->Get(SDDP::WHOLE_EXTENT()) : nullptr;
  bp::TimeScale& scale = probe.scale;
  scale.maxSpeed = share[0];
  scale.typicalSpeed = share[12];
  scale.cellLength = share[7];
  double sum = 0.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double span = share[2 + 2 * a] + share[1 + 2 * a];
    const int cells = whole ? whole[2 * a + 1] - whole[2 * a] : 1;
    if (cells >= 1 && span > 0.0)
    {
      scale.extent = std::max(scale.extent, span);
      sum += span / cells;
      ++axes;
    }
  }
  if (whole && axes > 0)
  {
    scale.cellLength = sum / axes;
  }
  return probe;
}

} // namespace bpvtk
