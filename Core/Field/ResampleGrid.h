// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ResampleGrid.h
 * @brief The uniform grid a mesh is resampled onto: how many points, where,
 * and how far apart, before any point is placed.
 *
 * Unstructured, curvilinear and composite input is traced on a uniform grid
 * over the data's bounds (the filter's resampler fills it). Automatic: about
 * as many points as the input has cells, so the grid resolves the flow about
 * as finely as the mesh does on average, with cells as close to cubes as the
 * bounds allow. An axis along which the data is flat stays one point thick, so
 * a 2D mesh gives a 2D grid. Pure arithmetic, the same on every process given
 * the same global bounds and cell count.
 */
#ifndef BoundParticles_ResampleGrid_h
#define BoundParticles_ResampleGrid_h

#include <array>
#include <cstddef>
#include <string>

namespace bp
{

struct ResampleGrid
{
  std::array<int, 3> dims = { 0, 0, 0 };
  std::array<double, 3> origin = { 0, 0, 0 };
  std::array<double, 3> spacing = { 1, 1, 1 };
  std::string error; ///< why no grid could be chosen; empty on success
  /// What the automatic choice had to give up (a thin axis, the cap), for a
  /// warning; empty when it chose freely.
  std::string note;

  std::size_t pointCount() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
  /// Point (i, j, k) of the grid, i fastest, as a linear index.
  std::size_t index(int i, int j, int k) const
  {
    return std::size_t(i) + std::size_t(dims[0]) * (std::size_t(j) + std::size_t(dims[1]) * k);
  }
};

/// The most points an automatic grid takes (16.8 M: 200 MB of float vectors
/// per cached time step); a mesh with more cells is resampled coarser.
constexpr std::size_t MaxAutomaticResamplePoints = std::size_t(1) << 24;
/// The fewest points an automatic grid gives each axis with extent: a mesh
/// of a handful of cells still gets a grid a flow can be traced on.
constexpr int MinAutomaticResampleAxisPoints = 8;
/// The most points a grid the user sets may have (2^31: indices fit an int).
constexpr double MaxResamplePoints = 2147483647.0;

/**
 * The grid over `bounds` (xmin, xmax, ymin, ymax, zmin, zmax; the whole
 * data's) for a mesh of `cellCount` cells. `requested` gives the points per
 * axis; 0 on an axis (all 0 by default) chooses that axis automatically
 * (automaticDimensions()), and an axis along which the data is flat (extent
 * at most 1e-9 of the largest) always has one point. A `surface` (a mesh of 2D cells) lies in a
 * plane of constant X, Y or Z: its thinnest axis is flat if its extent is at most
 * MaxSurfaceThickness of the largest (rounding or a slight tilt), and an error
 * says what to do otherwise. Also an error for bounds that are empty or not
 * finite, a requested count below 2 on an axis with extent (other than 0), or
 * more than MaxResamplePoints in all. `automaticCap` lowers the automatic
 * grid's points below MaxAutomaticResamplePoints (to what memory allows).
 */
ResampleGrid chooseResampleGrid(const std::array<double, 6>& bounds, double cellCount,
  const std::array<int, 3>& requested, bool surface = false,
  double automaticCap = double(MaxAutomaticResamplePoints));

/**
 * The points per axis: `requested` where set, 1 along an axis that does not
 * span, and on the others about `cellCount` points in all over the spanning
 * `volume`, in cells close to cubes. An axis that would get fewer than
 * MinAutomaticResampleAxisPoints (a slab's thickness, a rod's width) gets
 * that many, and the grid then keeps to at most 8 times the cells for each
 * such axis (the others are not refined to make up for it: a slab of 40,000
 * hexahedra gets about 200 x 200 x 8); always at most `cap` points (the cap,
 * or what memory allows), coarsening the automatic axes together, none below
 * the minimum. `note` says what was given up, when anything was.
 */
std::array<int, 3> automaticDimensions(const std::array<double, 3>& extent,
  const std::array<bool, 3>& spans, const std::array<int, 3>& requested, double cellCount,
  double volume, int spanning, double cap, std::string& note);

/// How thick, relative to its largest extent, a surface mesh may be and still
/// be resampled as flat.
constexpr double MaxSurfaceThickness = 1e-3;

} // namespace bp

#endif
