// SPDX-License-Identifier: BSD-3-Clause
#include "TracerTimeScale.h"

#include "TracerInput.h"
#include "VectorField.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>

namespace bpvtk
{

namespace
{
/// Updates the input for this process's piece (no ghosts) at `time`.
vtkDataObject* updateInput(vtkAlgorithmOutput* connection, vtkInformation* inInfo,
  const std::vector<double>& inputTimes, int piece, int pieces)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkAlgorithm* upstream = connection ? connection->GetProducer() : nullptr;
  if (!upstream)
  {
    return nullptr;
  }
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
  return inInfo->Get(vtkDataObject::DATA_OBJECT());
}

/// This process's share: (top speed, -lower, upper per axis, cell length).
std::array<double, 8> localScale(vtkDataObject* data, const GridOf& gridOf)
{
  std::array<double, 8> local = { 0, -1e300, -1e300, -1e300, -1e300, -1e300, -1e300, 0 };
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
  local[0] = bp::VectorField(grid, slice).maxSpeed();
  const std::array<double, 6> b = grid.bounds();
  for (int a = 0; a < 3; ++a)
  {
    local[1 + 2 * a] = -b[2 * a];
    local[2 + 2 * a] = b[2 * a + 1];
  }
  local[7] = grid.cellLength();
  return local;
}
} // namespace

bp::TimeScale probeTimeScale(vtkAlgorithmOutput* input, vtkInformation* inInfo,
  const std::vector<double>& inputTimes, const GridOf& gridOf)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int pieces = controller ? std::max(controller->GetNumberOfProcesses(), 1) : 1;
  const int piece = controller ? controller->GetLocalProcessId() : 0;
  std::array<double, 8> scale =
    localScale(updateInput(input, inInfo, inputTimes, piece, pieces), gridOf);
  if (pieces > 1)
  {
    std::array<double, 8> global;
    controller->AllReduce(scale.data(), global.data(), 8, vtkCommunicator::MAX_OP);
    scale = global;
  }
  // The whole field's extent and mean cell length, as the update's
  // (PieceLayout::cellLength): span over cells along each axis with cells.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int* whole =
    inInfo->Has(SDDP::WHOLE_EXTENT()) ? inInfo->Get(SDDP::WHOLE_EXTENT()) : nullptr;
  bp::TimeScale result;
  result.maxSpeed = scale[0];
  result.cellLength = scale[7];
  double sum = 0.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double span = scale[2 + 2 * a] + scale[1 + 2 * a];
    const int cells = whole ? whole[2 * a + 1] - whole[2 * a] : 1;
    if (cells >= 1 && span > 0.0)
    {
      result.extent = std::max(result.extent, span);
      sum += span / cells;
      ++axes;
    }
  }
  if (whole && axes > 0)
  {
    result.cellLength = sum / axes;
  }
  return result;
}

} // namespace bpvtk
