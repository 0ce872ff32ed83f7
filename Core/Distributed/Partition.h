// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Partition.h
 * @brief How a distributed trace splits its elements among the pieces of a
 * field, and moves them between pieces after a step.
 *
 * Each process holds one piece of the field (a box of its grid points) with
 * ghost layers around it, and owns the elements whose centres lie in its box.
 * The boxes tile the field's domain; a box is closed below and open above
 * except on the domain's upper faces, so every position has exactly one
 * owner. A position outside the domain belongs to the owner of the nearest
 * point of the domain, whose piece samples the field's boundary there as the
 * whole field does. Nothing here communicates: migrate() hands the records to
 * an exchange function (the filter's goes through vtkMultiProcessController,
 * the tests' through memory).
 */
#ifndef BoundParticles_Partition_h
#define BoundParticles_Partition_h

#include "Engine.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace bp
{

/// x min, x max, y min, y max, z min, z max.
using Box = std::array<double, 6>;

/// A box with min > max along an axis: a piece that owns nothing (more
/// processes than the field has cells to split).
bool isEmptyBox(const Box& b);

class Partition
{
public:
  /// One piece per box, in one coordinate frame; the boxes should tile their
  /// union. Empty boxes own nothing.
  explicit Partition(std::vector<Box> pieces);

  /// Empty when the boxes can be a partition (at least one not empty, none
  /// non-finite), otherwise what is wrong.
  static std::string validate(const std::vector<Box>& pieces);

  int pieceCount() const { return int(this->Pieces.size()); }
  const Box& piece(int k) const { return this->Pieces[std::size_t(k)]; }
  /// The union's bounding box: the field's domain.
  const Box& domain() const { return this->Bounds; }

  /// The piece that owns an element centred at x (-1 only without pieces).
  int ownerOf(const float x[3]) const;

private:
  std::vector<Box> Pieces;
  Box Bounds;
};

/**
 * Ghost layers (in cells of length `cellLength`) a piece needs so that every
 * particle of the elements it owns samples the field as the whole field
 * would: an element reaches `reach` element sizes from its centre (deformed
 * elements stretch beyond their rest radius of half a size), a step moves it
 * by up to maxSpeed * dt (an RK4 sub-step by less), trilinear sampling (the
 * velocity, and the Vorticity output's gradient of the same cell) takes the
 * next grid point, and one more cell is kept as a margin.
 */
int ghostCellsNeeded(
  double elementSize, double maxSpeed, double dt, double cellLength, double reach = 1.0);

/**
 * Sends each piece the records of the elements it now owns and returns those
 * sent to this one: outgoing[k] holds the records for piece k (the entry for
 * this piece is empty). Collective: every piece calls it once per exchange.
 */
using ExchangeFunction = std::function<std::vector<std::uint32_t>(
  const std::vector<std::vector<std::uint32_t>>& outgoing)>;

/// Moves the elements whose centres lie in another piece there; returns how
/// many left this one, or -1 with `error` set.
long long migrate(Engine& engine, const Partition& partition, int piece,
  const ExchangeFunction& exchange, std::string& error);

/// Keeps only the elements whose centres lie in `piece` (after initialize()).
void keepOwned(Engine& engine, const Partition& partition, int piece);

} // namespace bp

#endif
