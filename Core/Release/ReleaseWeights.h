// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ReleaseWeights.h
 * @brief Release Weights: release centres drawn in proportion to |w|, w any
 * point array of the input, by rejection (Engine::releaseCenter).
 *
 * The weights are one float per grid point of the field (FieldSlice::
 * releaseWeights), their absolute value with NaN and Inf as 0. Candidates
 * are drawn in the part of the emitter box where the weights may be above 0
 * (weightedBox: the box that holds every cell with a corner above 0), so a
 * small region of interest still takes nearly every candidate it could. A
 * candidate centre c of a release is accepted when it fits and u * maximum <
 * w(c), w trilinear at c as the velocity is (VectorField::sampleWeighted) and
 * u the release's draw weightDraw(k): up to ReleaseTries candidates, then the
 * fitting one of the largest weight seen. The GPU engine holds the same
 * (w, 0, 0) per point as a 3D texture and samples it as a time step
 * (bpSampleSlice), so both engines accept the same candidates.
 */
#ifndef BoundParticles_ReleaseWeights_h
#define BoundParticles_ReleaseWeights_h

#include "VectorField.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace bp
{

/// The draw of the acceptance test of a release's k-th candidate: after
/// every candidate's (candidateDraw(ReleaseTries - 1) + 2 = 196).
constexpr std::uint32_t FirstWeightDraw = 200;
constexpr std::uint32_t weightDraw(int k)
{
  return FirstWeightDraw + std::uint32_t(k);
}

class ReleaseWeights
{
public:
  /// `values`: one weight per point of `grid` (already |w|, finite).
  ReleaseWeights(const GridGeometry& grid, const std::vector<float>& values);

  /// The largest weight (> 0 for weights that may be used).
  float maximum() const { return this->Maximum; }
  /// The weight at p, trilinear in the cell that holds p.
  float at(const float p[3]) const;
  /// The box of the cells with a corner above 0 (outside it every weight is
  /// 0), in the grid's coordinates.
  const std::array<float, 3>& supportMin() const { return this->SupportMin; }
  const std::array<float, 3>& supportMax() const { return this->SupportMax; }
  /// (w, 0, 0) per grid point: what the GPU engine uploads.
  const std::vector<float>& triples() const { return *this->Triples; }

private:
  std::shared_ptr<std::vector<float>> Triples;
  std::unique_ptr<VectorField> Field;
  float Maximum = 0.0f;
  std::array<float, 3> SupportMin = { 0, 0, 0 };
  std::array<float, 3> SupportMax = { 0, 0, 0 };
};

/// Where a weighted release draws its candidates: the emitter box
/// [emitterMin, emitterMax] cut to the weights' support, axis by axis (min
/// and max in float, as the GPU's bpWeightedCenter does); the emitter box itself
/// where the two do not meet.
void weightedBox(const std::array<float, 3>& emitterMin, const std::array<float, 3>& emitterMax,
  const ReleaseWeights& weights, float lo[3], float hi[3]);

/**
 * The power of two that brings weights whose largest finite component is
 * `largest` into float's range without losing them (2^-e for largest = 2^e
 * beyond 2^60 or below 2^-60; 1 otherwise, and for 0 or no finite value):
 * releases depend only on ratios of weights, and a power of two keeps them
 * exactly, so a double array of 1e39 or 1e300, or of 1e-50, weighs as it
 * should instead of reading as Inf or 0.
 */
double releaseWeightScale(double largest);

/**
 * Per point, |value| of a `components`-component array (its magnitude for
 * more than one), NaN and Inf as 0: what FieldSlice::releaseWeights holds.
 */
std::vector<float> releaseWeightValues(const std::vector<float>& values, int components);

/**
 * Whether some cell of `grid` where releases may land (not `unfit`, per
 * cell as releaseUnfitCells(); null: every cell) has a corner whose weight
 * in `values` (one per point) is above 0: where no such cell is left,
 * weighted releases would all fall where the mask forbids them.
 */
bool weightsReachFitCells(const GridGeometry& grid, const std::vector<float>& values,
  const std::vector<std::uint8_t>* unfit);

/**
 * The release weights `values` (releaseWeightValues: one per point of
 * `grid`, the field's or the whole field's of a distributed run); null when
 * there are none, they do not fit the grid, none is above 0, or none is
 * above 0 at a corner of a cell where releases may land (`unfit`, as
 * weightsReachFitCells): releases are then uniform (the filter warns).
 */
std::shared_ptr<const ReleaseWeights> releaseWeightsOf(const GridGeometry& grid,
  const std::shared_ptr<const std::vector<float>>& values,
  const std::vector<std::uint8_t>* unfit = nullptr);

} // namespace bp

#endif
