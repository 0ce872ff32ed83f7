// SPDX-License-Identifier: BSD-3-Clause
// The order step() visits elements in: a counting sort by a coarse grid over
// the field, so neighbouring elements sample neighbouring memory.
#include "Engine.h"

#include <algorithm>
#include <cmath>

namespace bp
{

const std::vector<std::uint32_t>& Engine::visitOrder(const VectorField& field)
{
  // Below a few thousand elements the field's sampled cells stay in cache anyway.
  constexpr std::size_t SmallestOrdered = 2048;
  // A sort costs a few per cent of a step, and elements move less than a cell
  // per step, so an order stays good for several steps.
  constexpr int StepsPerOrder = 8;
  const std::size_t E = this->elementCount(), n = this->Shape.particleCount();
  if (E < SmallestOrdered)
  {
    this->Scratch.visitOrder.clear();
    return this->Scratch.visitOrder;
  }
  if (this->Scratch.visitOrder.size() == E && this->Scratch.stepsSinceOrdered < StepsPerOrder)
  {
    ++this->Scratch.stepsSinceOrdered;
    return this->Scratch.visitOrder;
  }
  this->Scratch.stepsSinceOrdered = 1;
  // The bins: the grid's cells coarsened evenly to about one per element.
  const GridGeometry& grid = field.grid();
  const Domain& domain = field.domain();
  double cells = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    cells *= std::max(grid.dims[a] - 1, 1);
  }
  const double coarsening = std::min(1.0, std::cbrt(double(E) / cells));
  int bins[3];
  float binsPerUnit[3];
  std::size_t binStride[3], binCount = 1;
  for (int a = 0; a < 3; ++a)
  {
    const int axisCells = std::max(grid.dims[a] - 1, 1);
    bins[a] = domain.degenerate[a] ? 1 : std::max(1, int(axisCells * coarsening));
    const float width = domain.upper[a] - domain.lower[a];
    binsPerUnit[a] = width > 0.0f ? float(bins[a]) / width : 0.0f;
    binStride[a] = binCount;
    binCount *= std::size_t(bins[a]);
  }
  // A counting sort by the bin of each element's first particle.
  std::vector<std::uint32_t> binOf(E), start(binCount + 1, 0);
  for (std::size_t e = 0; e < E; ++e)
  {
    const float* p = this->Positions.data() + 3 * e * n;
    std::size_t bin = 0;
    for (int a = 0; a < 3; ++a)
    {
      const float u = (p[a] - domain.lower[a]) * binsPerUnit[a];
      // Outside the field (or not a number): the nearest bin.
      const int i = u >= 1.0f ? int(std::min(u, float(bins[a] - 1))) : 0;
      bin += std::size_t(i) * binStride[a];
    }
    binOf[e] = std::uint32_t(bin);
    ++start[bin + 1];
  }
  for (std::size_t b = 0; b < binCount; ++b)
  {
    start[b + 1] += start[b];
  }
  this->Scratch.visitOrder.resize(E);
  for (std::size_t e = 0; e < E; ++e)
  {
    this->Scratch.visitOrder[start[binOf[e]]++] = std::uint32_t(e);
  }
  return this->Scratch.visitOrder;
}

} // namespace bp
