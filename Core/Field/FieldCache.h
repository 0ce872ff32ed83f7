// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file FieldCache.h
 * @brief The field time steps a trace holds: at most three, by input index.
 *
 * Two time steps bracket the moment being stepped; a third is the one read
 * ahead of need (or the next one arriving before the oldest can go). Memory
 * stays bounded at three time steps whatever the pipeline asks for: making
 * room keeps only what the work in progress needs.
 */
#ifndef BoundParticles_FieldCache_h
#define BoundParticles_FieldCache_h

#include "VectorField.h"

#include <map>
#include <vector>

namespace bp
{

class FieldCache
{
public:
  static constexpr std::size_t Capacity = 3;

  bool has(int index) const { return this->Slices.count(index) != 0; }
  std::size_t size() const { return this->Slices.size(); }
  const FieldSlice& at(int index) const { return this->Slices.at(index); }

  /// The first of `indices` not held, or -1 when all are.
  int firstMissing(const std::vector<int>& indices) const;

  /// Holds `slice` as time step `index`; with Capacity held, first drops
  /// every time step not in `keep`.
  void insert(int index, const FieldSlice& slice, const std::vector<int>& keep);

  /// Drops the time steps before `index` (no later step needs them).
  void dropBefore(int index);

  void clear() { this->Slices.clear(); }

  /// In situ, the grid changed from `from` to `to`: every time step held is
  /// put on `to` (regridSlice). Returns how many of `to`'s points `from`
  /// does not cover.
  std::size_t regrid(const GridGeometry& from, const GridGeometry& to, const FieldSlice& present);

  /// The field of time step ids[0] (steady), or between ids[0] and ids[1].
  VectorField field(const GridGeometry& grid, const std::vector<int>& ids) const;

private:
  std::map<int, FieldSlice> Slices;
};

/**
 * A time step held on grid `from`, sampled at every point of grid `to` (both
 * in the engine's coordinates): what an in situ trace whose grid changes
 * keeps of its last step, so the interval to the present step still blends
 * two steps. Where `from` does not cover a point of `to`, `present`'s value
 * there is taken (the flow is steady there over the interval); `outside`
 * counts those points. The domain mask and the weights are `present`'s: they
 * describe the new grid. Velocities only: `slice`'s time is kept.
 */
FieldSlice regridSlice(const GridGeometry& from, const FieldSlice& slice, const GridGeometry& to,
  const FieldSlice& present, std::size_t& outside);

} // namespace bp

#endif
