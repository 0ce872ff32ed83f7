// SPDX-License-Identifier: BSD-3-Clause
// Release Weights from the input, per time step, and over the whole field
// of a distributed run (TracerReleaseWeights.h).
#include "TracerReleaseWeights.h"

#include "TracerInput.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"

#include <algorithm>
#include <sstream>

namespace bpvtk
{

std::string readReleaseWeights(vtkDataObject* input, const std::string& name,
  vtkMultiProcessController* controller, bp::FieldSlice& slice)
{
  vtkDataSet* data = vtkDataSet::SafeDownCast(input);
  vtkDataArray* array = data ? data->GetPointData()->GetArray(name.c_str()) : nullptr;
  float found[2] = { 0.0f, 0.0f }; // has the array; its largest weight
  if (array && array->GetNumberOfTuples() == data->GetNumberOfPoints())
  {
    std::vector<float> values;
    copyToFloats(array, values);
    auto weights = std::make_shared<const std::vector<float>>(
      bp::releaseWeightValues(values, array->GetNumberOfComponents()));
    found[0] = 1.0f;
    found[1] = weights->empty() ? 0.0f : *std::max_element(weights->begin(), weights->end());
    slice.releaseWeights = weights;
  }
  if (controller)
  {
    float all[2];
    controller->AllReduce(found, all, 2, vtkCommunicator::MAX_OP);
    std::copy_n(all, 2, found);
  }
  std::ostringstream say;
  if (found[0] == 0.0f)
  {
    say << "Release Weights: the input has no point array '" << name
        << "' (one value, or a vector whose magnitude is used, per point); releases are "
           "uniform.";
  }
  else if (!(found[1] > 0.0f))
  {
    say << "Release Weights: the array '" << name
        << "' is 0, NaN or Inf at every point of this time step; releases are uniform.";
  }
  return say.str();
}

std::shared_ptr<const bp::ReleaseWeights> gatherReleaseWeights(
  vtkMultiProcessController* controller, const bp::GridGeometry& whole,
  const bp::GridGeometry& piece, const int shift[3],
  const std::shared_ptr<const std::vector<float>>& local)
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
  return bp::releaseWeightsOf(whole, all);
}

} // namespace bpvtk
