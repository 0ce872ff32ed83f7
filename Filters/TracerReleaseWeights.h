// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerReleaseWeights.h
 * @brief Release Weights from the tracer's input: the chosen array read
 * with each field time step (FieldSlice::releaseWeights, one |w| per grid
 * point, bp::releaseWeightValues) and, in a distributed run, gathered over
 * the whole field so every process draws the same releases.
 *
 * An image or rectilinear grid gives its point array as it is (a cell array
 * averaged onto its points); any other input is resampled first
 * (FieldResampler::setReleaseWeights adds the array to the resampled image:
 * a point array interpolated, a cell array taken per cell).
 */
#ifndef BoundParticles_TracerReleaseWeights_h
#define BoundParticles_TracerReleaseWeights_h

#include "ReleaseWeights.h"
#include "VectorField.h"

#include <memory>
#include <string>
#include <vector>

class vtkDataObject;
class vtkMultiProcessController;

namespace bpvtk
{

/**
 * Sets `slice.releaseWeights` from the array `name` of `input` (the field's
 * image or rectilinear grid): its point array, or (for `association` CELLS,
 * or where it has no such point array) its cell array averaged onto the
 * points. Values beyond float's range are scaled by a power of two over
 * every process (bp::releaseWeightScale). Returns a warning when no
 * process's input has that array, or when every weight is 0 (or not
 * finite): releases are then uniform. With a `controller` every process
 * must call it (the warning is agreed).
 */
std::string readReleaseWeights(vtkDataObject* input, const std::string& name, int association,
  vtkMultiProcessController* controller, bp::FieldSlice& slice);

/**
 * The whole field's weights on `whole` from every process's piece:
 * `local` (one per point of the piece's grid `piece`, or null) placed at
 * `shift` (the piece's first point in the whole grid). Collective; null
 * when no process has weights, or they reach no cell of `whole` where
 * releases may land (`unfit`, the whole field's, as bp::releaseWeightsOf).
 */
std::shared_ptr<const bp::ReleaseWeights> gatherReleaseWeights(
  vtkMultiProcessController* controller, const bp::GridGeometry& whole,
  const bp::GridGeometry& piece, const int shift[3],
  const std::shared_ptr<const std::vector<float>>& local, const std::vector<std::uint8_t>* unfit);

} // namespace bpvtk

#endif
