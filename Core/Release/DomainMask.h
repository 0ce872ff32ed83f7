// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DomainMask.h
 * @brief Grid points outside the flow's domain, and the cells they spoil.
 *
 * Real data marks where it has no flow: ParaView's resampling writes
 * vtkValidPointMask = 0 outside the source's domain, and models write NaN
 * over land or terrain. Such a point is outside the domain; so is every
 * cell that has it as a corner, since interpolating there would mix in a
 * velocity that does not exist. Both engines treat an element whose centre
 * (or, per Reset When, any particle) lies in such a cell as having left the
 * field, exactly as one that left the grid's bounds.
 *
 * The velocity stored at an outside point is 0, so that a particle of an
 * element straddling the edge still samples finite values.
 */
#ifndef BoundParticles_DomainMask_h
#define BoundParticles_DomainMask_h

#include "ReleaseWeights.h"
#include "VectorField.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace bp
{

struct DomainMask
{
  /// Per grid point, as the lowest corner of a cell (the index sampling
  /// computes): 1 when that cell has a corner outside the domain. Null when
  /// every point is inside.
  std::shared_ptr<const std::vector<std::uint8_t>> outsideCells;
  std::size_t outsidePoints = 0;   ///< how many grid points are outside
  std::size_t nonFinitePoints = 0; ///< of those, how many had a non-finite vector
};

/**
 * Marks the points of `velocity` (3 floats per point of `grid`) that are
 * outside the domain: `valid` (one byte per point, may be null) is 0 there,
 * or a component is not finite. Sets their velocity to 0 and returns the
 * cells they spoil.
 */
DomainMask maskOutsidePoints(
  const GridGeometry& grid, std::vector<float>& velocity, const std::uint8_t* valid);

/**
 * Where releases may not land, per cell of `field`'s grid (indexed as
 * outsideCells): 1 where a corner is outside the domain in either time step,
 * or where no corner in either time step is as fast as `minSpeed` (stagnant
 * flow). Null when every cell is fit. Both engines place a release by
 * drawing candidates until one lands in a fit cell (Engine::place).
 */
std::shared_ptr<const std::vector<std::uint8_t>> releaseUnfitCells(
  const VectorField& field, float minSpeed);

/// Where releases may not land over a whole field (Engine::setReleaseMask).
struct ReleaseMask
{
  GridGeometry grid; ///< the whole field's, in engine coordinates
  std::shared_ptr<const std::vector<std::uint8_t>> unfit;
  /// Release Weights on `grid` (ReleaseWeights.h), or null.
  std::shared_ptr<const ReleaseWeights> weights;
};

/// The release mask of `field` alone (a process that holds the whole field):
/// releaseUnfitCells() and the first slice's Release Weights where they
/// reach a cell where releases may land (releaseWeightsOf).
ReleaseMask releaseMaskOf(const VectorField& field, float minSpeed);

/// Whether `mask` leaves no cell of its grid where a release may land (and
/// so no element could be released anywhere).
bool leavesNoCell(const ReleaseMask& mask);

/// What a release mask was made from: a field's time steps (held, so that a
/// freed and reused address never passes for them) and the minimum speed.
class ReleaseMaskSource
{
public:
  /// Whether the mask must be made again for `field` at `minSpeed`; then
  /// remembers them as the source of the mask about to be made.
  bool changes(const VectorField& field, float minSpeed)
  {
    if (field.firstSlice().velocity == this->First &&
      field.secondSlice().velocity == this->Second && minSpeed == this->Speed)
    {
      return false;
    }
    this->First = field.firstSlice().velocity;
    this->Second = field.secondSlice().velocity;
    this->Speed = minSpeed;
    return true;
  }

private:
  std::shared_ptr<const std::vector<float>> First, Second;
  float Speed = -1.0f;
};

/// The release mask of the whole field given this process's piece of it (a
/// distributed run gathers every piece's cells; collective).
using ReleaseMaskFunction = std::function<ReleaseMask(const VectorField& piece, float minSpeed)>;

} // namespace bp

#endif
