// SPDX-License-Identifier: BSD-3-Clause
#include "DomainMask.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace bp
{

DomainMask maskOutsidePoints(
  const GridGeometry& grid, std::vector<float>& velocity, const std::uint8_t* valid)
{
  DomainMask mask;
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  const std::size_t points = grid.pointCount();
  std::vector<std::uint8_t>* cells = nullptr;
  std::shared_ptr<std::vector<std::uint8_t>> owned;
  for (std::size_t id = 0; id < points && 3 * id + 2 < velocity.size(); ++id)
  {
    float* v = velocity.data() + 3 * id;
    const bool finite = std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
    if (finite && (!valid || valid[id] != 0))
    {
      continue;
    }
    mask.nonFinitePoints += finite ? 0 : 1;
    v[0] = v[1] = v[2] = 0.0f;
    ++mask.outsidePoints;
    if (!cells)
    {
      owned = std::make_shared<std::vector<std::uint8_t>>(points, std::uint8_t(0));
      cells = owned.get();
    }
    // The cells with this point as a corner: their lowest corners lie up to
    // one point below it along each axis with cells (sampling's last cell
    // starts at dims - 2; a flat axis has the one cell 0).
    const int i = int(id % std::size_t(nx));
    const int j = int((id / std::size_t(nx)) % std::size_t(ny));
    const int k = int(id / (std::size_t(nx) * std::size_t(ny)));
    const int at[3] = { i, j, k };
    const int dims[3] = { nx, ny, nz };
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      const int lastCell = std::max(dims[a] - 2, 0);
      lo[a] = std::max(at[a] - 1, 0);
      hi[a] = std::min(at[a], lastCell);
    }
    for (int c = lo[2]; c <= hi[2]; ++c)
    {
      for (int b = lo[1]; b <= hi[1]; ++b)
      {
        for (int a = lo[0]; a <= hi[0]; ++a)
        {
          (*cells)[std::size_t(a) + std::size_t(nx) * (std::size_t(b) + std::size_t(ny) * c)] = 1;
        }
      }
    }
  }
  mask.outsideCells = owned;
  return mask;
}

ReleaseMask releaseMaskOf(const VectorField& field, float minSpeed)
{
  auto unfit = releaseUnfitCells(field, minSpeed);
  auto weights = releaseWeightsOf(field.grid(), field.firstSlice().releaseWeights, unfit.get());
  return { field.grid(), std::move(unfit), std::move(weights) };
}

bool leavesNoCell(const ReleaseMask& mask)
{
  if (!mask.unfit)
  {
    return false;
  }
  const GridGeometry& grid = mask.grid;
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  // Cells are indexed by their lowest corner; along an axis of one point, by it.
  for (int k = 0; k < std::max(nz - 1, 1); ++k)
  {
    for (int j = 0; j < std::max(ny - 1, 1); ++j)
    {
      for (int i = 0; i < std::max(nx - 1, 1); ++i)
      {
        if (!(*mask
                 .unfit)[std::size_t(i) + std::size_t(nx) * (std::size_t(j) + std::size_t(ny) * k)])
        {
          return false;
        }
      }
    }
  }
  return true;
}

std::shared_ptr<const std::vector<std::uint8_t>> releaseUnfitCells(
  const VectorField& field, float minSpeed)
{
  const GridGeometry& grid = field.grid();
  const std::size_t points = grid.pointCount();
  const FieldSlice* slices[2] = { &field.firstSlice(), &field.secondSlice() };
  bool anyOutside = false;
  for (const FieldSlice* s : slices)
  {
    anyOutside = anyOutside || (s->velocity && s->outsideCells);
  }
  if (!anyOutside && !(minSpeed > 0.0f))
  {
    return nullptr;
  }
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  // Along an axis of one point the cell's "next" corner is the point itself.
  const std::size_t step[3] = { nx > 1 ? 1u : 0u, ny > 1 ? std::size_t(nx) : 0u,
    nz > 1 ? std::size_t(nx) * std::size_t(ny) : 0u };
  const float limit = minSpeed * minSpeed;
  auto unfit = std::make_shared<std::vector<std::uint8_t>>(points, std::uint8_t(0));
  bool any = false;
  for (int k = 0; k < std::max(nz - 1, 1); ++k)
  {
    for (int j = 0; j < std::max(ny - 1, 1); ++j)
    {
      for (int i = 0; i < std::max(nx - 1, 1); ++i)
      {
        const std::size_t base =
          std::size_t(i) + std::size_t(nx) * (std::size_t(j) + std::size_t(ny) * k);
        bool outside = false, moving = !(minSpeed > 0.0f);
        for (const FieldSlice* s : slices)
        {
          if (!s->velocity)
          {
            continue;
          }
          outside = outside || (s->outsideCells && (*s->outsideCells)[base]);
          for (int c = 0; c < 8 && !moving; ++c)
          {
            const std::size_t id =
              base + ((c & 1) ? step[0] : 0) + ((c & 2) ? step[1] : 0) + ((c & 4) ? step[2] : 0);
            const float* v = s->velocity->data() + 3 * id;
            moving = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] >= limit;
          }
        }
        (*unfit)[base] = outside || !moving ? 1 : 0;
        any = any || (*unfit)[base];
      }
    }
  }
  return any ? unfit : nullptr;
}

} // namespace bp
