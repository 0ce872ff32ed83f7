// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ReleaseLattice.h
 * @brief The lattice of release centres of Release Pattern = Lattice.
 *
 * A regular lattice filling the emitter box, one point per element: the box
 * is cut into counts[a] equal cells along each axis and each point sits at
 * its cell's centre, so the lattice is the box's image at those dimensions
 * (the FTLE map's image, Filters/TracerFtleMap.cxx, has exactly these points).
 * A flat axis of the box (min = max, as on a 2D slice) has one point, on the
 * box's plane. Element e sits at point e (x fastest, then y, then z), on
 * both engines and on every process, release after release.
 */
#ifndef BoundParticles_ReleaseLattice_h
#define BoundParticles_ReleaseLattice_h

#include <array>
#include <cstddef>

namespace bp
{

/// The most points a lattice may have along one axis (so a tiny spacing is
/// refused with a message rather than overflowing a count).
constexpr int MaxLatticeCount = 1 << 20;

struct ReleaseLattice
{
  std::array<int, 3> counts = { 1, 1, 1 };
  std::array<float, 3> origin = { 0, 0, 0 };  ///< point 0: the first cell's centre
  std::array<float, 3> spacing = { 0, 0, 0 }; ///< between neighbours; 0 along a flat axis

  /// counts[0] * counts[1] * counts[2].
  std::size_t size() const;
  /// Point `id` (taken modulo size()): origin + index * spacing per axis, in
  /// float arithmetic as the GPU's bpLatticePoint does it.
  std::array<float, 3> point(std::size_t id) const;
};

/**
 * The lattice over the box [emitterMin, emitterMax]. With `spacing` > 0 the
 * counts are the box's extents over it, rounded (at least 1, at most
 * MaxLatticeCount); otherwise they come from `elements`: the spacing s that
 * gives the box's volume (area, length) over `elements` cells on its
 * non-flat axes, each count its extent over s rounded, so size() is close to
 * `elements` but not always equal to it (the engine then holds size()
 * elements). An axis is flat when its extent is not above 0. An axis of
 * one point that is not flat has it at its middle (one element in a cube:
 * the cube's centre).
 */
ReleaseLattice releaseLattice(const std::array<float, 3>& emitterMin,
  const std::array<float, 3>& emitterMax, std::size_t elements, double spacing);

} // namespace bp

#endif
