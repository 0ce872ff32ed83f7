// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SuperSet.h
 * @brief Super sets (thesis §5.1): springs between neighbouring elements, so
 * that all elements of a system form one deformable structure.
 *
 * Elements sit on a lattice of W x H sites, element e at (e % W, e / W): a
 * chain or ring is one row, a sheet, tube or torus is W x H. Each element is
 * linked to its lattice neighbours along u (within a row) and along v (within
 * a column); a ring and a tube wrap along u, a torus along u and v. A link
 * joins particle i of one element to particle i of the other, for every i.
 *
 * The structure is released as a whole: every element of a generation sits at
 * its lattice site, all with the same orientation and lifetime, so a link's
 * rest length is the distance between the two sites. The sites fill the
 * emitter box: a chain along its longest axis, a ring as the ellipse in the
 * plane of its two longest axes, a sheet over those two axes, a tube around
 * the longest axis, a torus around the shortest one.
 */
#ifndef BoundParticles_SuperSet_h
#define BoundParticles_SuperSet_h

#include "BoundParticlesChoices.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace bp
{

/// The links of a super set, in the engines' element order.
struct LinkTable
{
  int width = 0, height = 0; ///< the lattice, W x H sites (the last row may be partial)
  /// Per element, 3 floats: its lattice site, the centre it is released at.
  std::vector<float> sites;
  /// Per element, 4 neighbours in the order +u, -u, +v, -v; -1 where none.
  std::vector<std::int32_t> neighbours;
  /// Per element, the rest length of each of those 4 links (0 where none).
  std::vector<float> rest;

  bool empty() const { return this->sites.empty(); }
  /// The number of links between elements (each counted once).
  std::size_t linkCount() const;
};

/// Directions of LinkTable::neighbours.
constexpr int LinkDirections = 4;

/**
 * The lattice of `elements` sites for `linking` in the emitter box [lo, hi].
 * `width` is the lattice width W for sheets, tubes and tori (0: the smallest
 * W with W * W >= elements); chains and rings are one row. Empty for None.
 */
LinkTable makeLinkTable(Linking linking, std::size_t elements, int width,
  const std::array<float, 3>& lo, const std::array<float, 3>& hi);

} // namespace bp

#endif
