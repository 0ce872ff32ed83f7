// SPDX-License-Identifier: BSD-3-Clause
// Release Weights (ReleaseWeights.h): the weights as a field the engine
// samples exactly as it samples the flow, so both engines agree.
#include "ReleaseWeights.h"

#include <algorithm>
#include <cmath>

namespace bp
{

ReleaseWeights::ReleaseWeights(const GridGeometry& grid, const std::vector<float>& values)
  : Triples(std::make_shared<std::vector<float>>(3 * values.size(), 0.0f))
{
  // The lowest and highest point index, per axis, of a weight above 0.
  std::array<int, 3> first = { grid.dims[0], grid.dims[1], grid.dims[2] }, last = { -1, -1, -1 };
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const float w = std::isfinite(values[i]) ? std::abs(values[i]) : 0.0f;
    (*this->Triples)[3 * i] = w;
    this->Maximum = std::max(this->Maximum, w);
    if (w > 0.0f)
    {
      std::size_t r = i;
      for (int a = 0; a < 3; ++a)
      {
        const int index = int(r % std::size_t(grid.dims[a]));
        r /= std::size_t(grid.dims[a]);
        first[a] = std::min(first[a], index);
        last[a] = std::max(last[a], index);
      }
    }
  }
  // Trilinear weights are above 0 in every cell with such a corner: one
  // point further each way.
  for (int a = 0; a < 3 && this->Maximum > 0.0f; ++a)
  {
    this->SupportMin[a] = float(grid.coordinate(a, std::max(first[a] - 1, 0)));
    this->SupportMax[a] = float(grid.coordinate(a, std::min(last[a] + 1, grid.dims[a] - 1)));
  }
  FieldSlice slice;
  slice.velocity = this->Triples;
  this->Field.reset(new VectorField(grid, slice));
}

float ReleaseWeights::at(const float p[3]) const
{
  float v[3];
  this->Field->sampleWeighted(p, 0.0f, v);
  return v[0];
}

void weightedBox(const std::array<float, 3>& emitterMin, const std::array<float, 3>& emitterMax,
  const ReleaseWeights& weights, float lo[3], float hi[3])
{
  bool meet = true;
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(emitterMin[a], weights.supportMin()[a]);
    hi[a] = std::min(emitterMax[a], weights.supportMax()[a]);
    meet = meet && lo[a] <= hi[a];
  }
  for (int a = 0; a < 3 && !meet; ++a)
  {
    lo[a] = emitterMin[a];
    hi[a] = emitterMax[a];
  }
}

double releaseWeightScale(double largest)
{
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    return 1.0;
  }
  const int e = std::ilogb(largest);
  return e > 60 || e < -60 ? std::ldexp(1.0, -e) : 1.0;
}

std::vector<float> releaseWeightValues(const std::vector<float>& values, int components)
{
  const std::size_t n = components > 0 ? values.size() / std::size_t(components) : 0;
  std::vector<float> out(n, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    double sum = 0.0;
    for (int k = 0; k < components; ++k)
    {
      const double x = values[i * std::size_t(components) + std::size_t(k)];
      sum += x * x;
    }
    // One component keeps its own value's magnitude, to the bit.
    const float w = components == 1 ? std::abs(values[i]) : float(std::sqrt(sum));
    out[i] = std::isfinite(w) ? w : 0.0f;
  }
  return out;
}

bool weightsReachFitCells(const GridGeometry& grid, const std::vector<float>& values,
  const std::vector<std::uint8_t>* unfit)
{
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  if (values.size() != grid.pointCount() || (unfit && unfit->size() != grid.pointCount()))
  {
    return false;
  }
  // Cells are indexed by their lowest corner; along an axis of one point the
  // cell's "next" corner is the point itself (as releaseUnfitCells).
  const std::size_t step[3] = { nx > 1 ? 1u : 0u, ny > 1 ? std::size_t(nx) : 0u,
    nz > 1 ? std::size_t(nx) * std::size_t(ny) : 0u };
  for (int k = 0; k < std::max(nz - 1, 1); ++k)
  {
    for (int j = 0; j < std::max(ny - 1, 1); ++j)
    {
      for (int i = 0; i < std::max(nx - 1, 1); ++i)
      {
        const std::size_t base =
          std::size_t(i) + std::size_t(nx) * (std::size_t(j) + std::size_t(ny) * k);
        if (unfit && (*unfit)[base])
        {
          continue;
        }
        for (int c = 0; c < 8; ++c)
        {
          const std::size_t id =
            base + ((c & 1) ? step[0] : 0) + ((c & 2) ? step[1] : 0) + ((c & 4) ? step[2] : 0);
          if (std::isfinite(values[id]) && std::abs(values[id]) > 0.0f)
          {
            return true;
          }
        }
      }
    }
  }
  return false;
}

std::shared_ptr<const ReleaseWeights> releaseWeightsOf(const GridGeometry& grid,
  const std::shared_ptr<const std::vector<float>>& values, const std::vector<std::uint8_t>* unfit)
{
  if (!values || values->size() != grid.pointCount() || values->empty() ||
    (unfit && !weightsReachFitCells(grid, *values, unfit)))
  {
    return nullptr;
  }
  auto weights = std::make_shared<const ReleaseWeights>(grid, *values);
  return weights->maximum() > 0.0f ? weights : nullptr;
}

} // namespace bp
