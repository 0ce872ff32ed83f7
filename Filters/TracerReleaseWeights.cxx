// SPDX-License-Identifier: BSD-3-Clause
// Release Weights from the input, per time step, and over the whole field
// of a distributed run (TracerReleaseWeights.h).
#include "TracerReleaseWeights.h"

#include "TracerInput.h"

#include "vtkCellData.h"
#include "vtkCellDataToPointData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <sstream>

namespace bpvtk
{

namespace
{
/// The weights `name` of `data` as a point array: the point array where the
/// association asks for points and there is one; else the cell array of that
/// name averaged onto the points around each cell, as ParaView's Cell Data
/// to Point Data does (and as its panel offers a cell array for points).
vtkSmartPointer<vtkDataArray> weightsOnPoints(
  vtkDataSet* data, const std::string& name, int association)
{
  vtkDataArray* points = data->GetPointData()->GetArray(name.c_str());
  if (association != vtkDataObject::FIELD_ASSOCIATION_CELLS && points &&
    points->GetNumberOfTuples() == data->GetNumberOfPoints())
  {
    return points;
  }
  vtkDataArray* cells = data->GetCellData()->GetArray(name.c_str());
  if (!cells || cells->GetNumberOfTuples() != data->GetNumberOfCells() ||
    data->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataSet> alone;
  alone.TakeReference(data->NewInstance());
  alone->CopyStructure(data);
  alone->GetCellData()->AddArray(cells);
  vtkNew<vtkCellDataToPointData> toPoints;
  toPoints->SetInputData(alone);
  toPoints->ProcessAllArraysOn();
  toPoints->Update();
  return toPoints->GetOutput()->GetPointData()->GetArray(name.c_str());
}
} // namespace

std::string readReleaseWeights(vtkDataObject* input, const std::string& name, int association,
  vtkMultiProcessController* controller, bp::FieldSlice& slice)
{
  vtkDataSet* data = vtkDataSet::SafeDownCast(input);
  const vtkSmartPointer<vtkDataArray> array =
    data ? weightsOnPoints(data, name, association) : nullptr;
  // Has the array; its largest finite component (so that values beyond
  // float's range scale into it, bp::releaseWeightScale, alike everywhere).
  double found[2] = { array ? 1.0 : 0.0, array ? largestFinite(array) : 0.0 };
  if (controller)
  {
    double all[2];
    controller->AllReduce(found, all, 2, vtkCommunicator::MAX_OP);
    std::copy_n(all, 2, found);
  }
  float top = 0.0f; // the largest weight, after scaling
  if (array)
  {
    std::vector<float> values;
    copyToFloats(array, values, bp::releaseWeightScale(found[1]));
    auto weights = std::make_shared<const std::vector<float>>(
      bp::releaseWeightValues(values, array->GetNumberOfComponents()));
    top = weights->empty() ? 0.0f : *std::max_element(weights->begin(), weights->end());
    slice.releaseWeights = weights;
  }
  if (controller)
  {
    float all = 0.0f;
    controller->AllReduce(&top, &all, 1, vtkCommunicator::MAX_OP);
    top = all;
  }
  std::ostringstream say;
  if (found[0] == 0.0)
  {
    say << "Release Weights: the input has no "
        << (association == vtkDataObject::FIELD_ASSOCIATION_CELLS ? "cell" : "point or cell")
        << " array '" << name
        << "' (one value, or a vector whose magnitude is used, per point or cell); releases are "
           "uniform.";
  }
  else if (!(top > 0.0f))
  {
    say << "Release Weights: the array '" << name
        << "' is 0, NaN or Inf at every point of this time step; releases are uniform.";
  }
  return say.str();
}

std::shared_ptr<const bp::ReleaseWeights> gatherReleaseWeights(
  vtkMultiProcessController* controller, const bp::GridGeometry& whole,
  const bp::GridGeometry& piece, const int shift[3],
  const std::shared_ptr<const std::vector<float>>& local, const std::vector<std::uint8_t>* unfit)
{
  // A feature that is off costs one small reduction per time step.
  const bool mine = local && local->size() == piece.pointCount();
  int any = mine ? 1 : 0, anyAll = any;
  controller->AllReduce(&any, &anyAll, 1, vtkCommunicator::MAX_OP);
  if (anyAll == 0)
  {
    return nullptr;
  }
  // Each piece gives its points (ghosts included: the same values where
  // pieces overlap), the others 0; weights are never below 0.
  std::vector<float> values(whole.pointCount(), 0.0f);
  const int nx = piece.dims[0], ny = piece.dims[1];
  for (int k = 0; mine && k < piece.dims[2]; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t to = std::size_t(i + shift[0]) +
          std::size_t(whole.dims[0]) *
            (std::size_t(j + shift[1]) + std::size_t(whole.dims[1]) * std::size_t(k + shift[2]));
        values[to] =
          (*local)[std::size_t(i) + std::size_t(nx) * (std::size_t(j) + std::size_t(ny) * k)];
      }
  auto all = std::make_shared<std::vector<float>>(values.size());
  controller->AllReduce(
    values.data(), all->data(), vtkIdType(values.size()), vtkCommunicator::MAX_OP);
  return bp::releaseWeightsOf(whole, all, unfit);
}

} // namespace bpvtk
