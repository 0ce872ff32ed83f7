// SPDX-License-Identifier: BSD-3-Clause
// The resampler's cell search (TracerResample.h): which cell of the mesh
// holds each grid point, and its interpolation weights there, found cell by
// cell rather than point by point.
#include "TracerResample.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkExplicitStructuredGrid.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>

namespace
{
/// The range of grid indices along `a` within [low, high] (empty: first > last).
std::array<int, 2> indexRange(const bp::ResampleGrid& g, int a, double low, double high)
{
  if (g.dims[a] == 1)
  {
    const double slack = 1e-9 * std::max(1.0, std::abs(g.origin[a]) + (high - low));
    return g.origin[a] >= low - slack && g.origin[a] <= high + slack ? std::array<int, 2>{ 0, 0 }
                                                                     : std::array<int, 2>{ 1, 0 };
  }
  const double h = g.spacing[a];
  // A point on the block's boundary is in it: round inwards by a hair.
  const int first = int(std::ceil((low - g.origin[a]) / h - 1e-6));
  const int last = int(std::floor((high - g.origin[a]) / h + 1e-6));
  return { std::max(first, 0), std::min(last, g.dims[a] - 1) };
}

/// Grid point i's coordinate along axis a, computed as the search always has.
inline double coordinate(const bp::ResampleGrid& g, int a, int i)
{
  return g.origin[a] + i * g.spacing[a];
}

/// The grid points of a block's box: ranges per axis and local indices.
struct Box
{
  std::array<std::array<int, 2>, 3> range;

  bool empty() const
  {
    return range[0][0] > range[0][1] || range[1][0] > range[1][1] || range[2][0] > range[2][1];
  }
  int count(int a) const { return range[a][1] - range[a][0] + 1; }
  std::size_t size() const { return std::size_t(count(0)) * count(1) * count(2); }
  std::size_t local(int i, int j, int k) const
  {
    return std::size_t(i - range[0][0]) +
      std::size_t(count(0)) *
      (std::size_t(j - range[1][0]) + std::size_t(count(1)) * (k - range[2][0]));
  }
};

/**
 * The indices along `a` of the grid points within [low, high] (a cell's
 * bounds), clipped to the box: exactly those whose coordinate() passes
 * low <= x <= high, as vtkStaticCellLocator tests a point against a cell's
 * bounds. Empty when first > last.
 */
std::array<int, 2> pointsWithin(
  const bp::ResampleGrid& g, const Box& box, int a, double low, double high)
{
  int first = box.range[a][0], last = box.range[a][1];
  if (g.dims[a] > 1)
  {
    // A guess from the division, then moved to the exact test's answer.
    const double from = std::floor((low - g.origin[a]) / g.spacing[a]);
    const double to = std::ceil((high - g.origin[a]) / g.spacing[a]);
    first = int(std::max(double(first), std::min(from, double(last) + 1.0)));
    last = int(std::min(double(last), std::max(to, double(first) - 1.0)));
  }
  while (first <= last && !(coordinate(g, a, first) >= low))
    ++first;
  while (last >= first && !(coordinate(g, a, last) <= high))
    --last;
  return { first, last };
}

/// Whether `block`'s GetCellBounds(id, bounds) is its own (thread-safe):
/// vtkDataSet's falls back on the shared GetCell(id).
bool ownCellBounds(vtkDataSet* block)
{
  return vtkUnstructuredGrid::SafeDownCast(block) || vtkPolyData::SafeDownCast(block) ||
    vtkStructuredGrid::SafeDownCast(block) || vtkImageData::SafeDownCast(block) ||
    vtkRectilinearGrid::SafeDownCast(block) || vtkExplicitStructuredGrid::SafeDownCast(block);
}

/**
 * An unstructured grid's tetrahedra read straight from its arrays, without
 * a vtkGenericCell (whose GetCell copied the points through VTK's generic
 * tuple access and cost more than the search itself), and evaluated with
 * vtkTetra::EvaluatePosition's arithmetic, operation for operation: the
 * same weights and the same inside test (pcoords within [-0.001, 1.001]),
 * to the bit, which TestFieldResampler checks against vtkTetra.
 */
class Tetrahedra
{
public:
  explicit Tetrahedra(vtkDataSet* block)
    : Grid(vtkUnstructuredGrid::SafeDownCast(block))
  {
    vtkPoints* points = this->Grid ? this->Grid->GetPoints() : nullptr;
    if (points && this->Grid->GetCells())
    {
      if (auto* f = vtkFloatArray::FastDownCast(points->GetData()))
        this->Floats = f->GetPointer(0);
      else if (auto* d = vtkDoubleArray::FastDownCast(points->GetData()))
        this->Doubles = d->GetPointer(0);
    }
  }
  /// Whether cell c is a tetrahedron read here (else: vtkGenericCell).
  bool has(vtkIdType c) const
  {
    return (this->Floats || this->Doubles) && this->Grid->GetCellType(c) == VTK_TETRA;
  }
  /// Cell c's point ids and coordinates, in the cell's order (`scratch`:
  /// the thread's own, for connectivity not stored as vtkIdType).
  void load(vtkIdType c, vtkIdList* scratch, vtkIdType ids[4], double p[4][3]) const
  {
    vtkIdType n = 0;
    const vtkIdType* pts = nullptr;
    this->Grid->GetCells()->GetCellAtId(c, n, pts, scratch);
    for (int q = 0; q < 4; ++q)
    {
      ids[q] = pts[q];
      for (int a = 0; a < 3; ++a)
      {
        p[q][a] =
          this->Floats ? double(this->Floats[3 * pts[q] + a]) : this->Doubles[3 * pts[q] + a];
      }
    }
  }
  /// vtkTetra::EvaluatePosition (without the closest point): 1 inside,
  /// 0 outside, -1 degenerate; the weights in the cell's point order.
  static int evaluate(const double p[4][3], const double x[3], double weights[4])
  {
    double rhs[3], c1[3], c2[3], c3[3];
    for (int i = 0; i < 3; i++)
    {
      rhs[i] = x[i] - p[0][i];
      c1[i] = p[1][i] - p[0][i];
      c2[i] = p[2][i] - p[0][i];
      c3[i] = p[3][i] - p[0][i];
    }
    const double det = vtkMath::Determinant3x3(c1, c2, c3);
    if (det == 0.0)
    {
      return -1;
    }
    double pcoords[3];
    pcoords[0] = vtkMath::Determinant3x3(rhs, c2, c3) / det;
    pcoords[1] = vtkMath::Determinant3x3(c1, rhs, c3) / det;
    pcoords[2] = vtkMath::Determinant3x3(c1, c2, rhs) / det;
    const double p4 = 1.0 - pcoords[0] - pcoords[1] - pcoords[2];
    weights[0] = p4;
    weights[1] = pcoords[0];
    weights[2] = pcoords[1];
    weights[3] = pcoords[2];
    return pcoords[0] >= -0.001 && pcoords[0] <= 1.001 && pcoords[1] >= -0.001 &&
        pcoords[1] <= 1.001 && pcoords[2] >= -0.001 && pcoords[2] <= 1.001 && p4 >= -0.001 &&
        p4 <= 1.001
      ? 1
      : 0;
  }

private:
  vtkUnstructuredGrid* Grid;
  const float* Floats = nullptr;
  const double* Doubles = nullptr;
};

/// No cell holds the point (yet).
constexpr vtkIdType NoCell = std::numeric_limits<vtkIdType>::max();

/**
 * The cell search of one block: each cell tests the grid points within its
 * bounds (as vtkStaticCellLocator::FindCell tests a cell whose bounds hold
 * the point: EvaluatePosition says inside), and of the cells that hold a
 * point the lowest-numbered wins, with its weights kept, whatever the
 * threads did: a winner is written under a lock of its point's stripe.
 */
class CellSearch
{
public:
  CellSearch(const bp::ResampleGrid& grid, const Box& box, vtkDataSet* block, double offPlane,
    const std::vector<std::uint8_t>& taken)
    : Grid(grid)
    , Space(box)
    , Block(block)
    , Taken(taken)
    , OwnBounds(ownCellBounds(block))
    , Tetra(block)
    , Stride(std::size_t(std::max(4, block->GetMaxCellSize())))
    , Owner(new std::atomic<vtkIdType>[box.size()])
    , Weights(new float[box.size() * Stride])
  {
    // A surface's cells lie off the grid's plane by up to `offPlane` (its
    // thickness, a slight tilt): their bounds are widened that far across it.
    this->Flat = offPlane > 0.0
      ? int(std::find(grid.dims.begin(), grid.dims.end(), 1) - grid.dims.begin())
      : 3;
    this->Across = offPlane + 1e-9 * std::max(block->GetLength(), 1e-300);
    for (std::size_t q = 0; q < box.size(); ++q)
    {
      this->Owner[q].store(NoCell, std::memory_order_relaxed);
    }
    // Calls with side effects on first use (a polydata builds its cells)
    // run here, before the threads.
    double first[6];
    block->GetCellBounds(0, first);
  }

  /// Tests cells [begin, end) against the grid points within their bounds.
  void run(vtkIdType begin, vtkIdType end)
  {
    vtkNew<vtkGenericCell> cell;
    vtkNew<vtkIdList> scratch;
    std::vector<double> weights(this->Stride);
    for (vtkIdType c = begin; c < end; ++c)
    {
      double bounds[6], p[4][3];
      vtkIdType ids[4];
      const bool tetra = this->Tetra.has(c);
      if (tetra)
      {
        this->Tetra.load(c, scratch, ids, p);
        for (int a = 0; a < 3; ++a)
        {
          bounds[2 * a] = std::min(std::min(p[0][a], p[1][a]), std::min(p[2][a], p[3][a]));
          bounds[2 * a + 1] = std::max(std::max(p[0][a], p[1][a]), std::max(p[2][a], p[3][a]));
        }
      }
      else if (this->OwnBounds)
      {
        this->Block->GetCellBounds(c, bounds);
      }
      else
      {
        this->Block->GetCell(c, cell);
        cell->GetBounds(bounds);
      }
      std::array<std::array<int, 2>, 3> within;
      if (!this->pointsIn(bounds, within))
      {
        continue;
      }
      if (!tetra && this->OwnBounds)
      {
        this->Block->GetCell(c, cell);
      }
      this->test(
        c, within,
        [&](const double x[3])
        {
          int subId = 0;
          double pcoords[3], dist2;
          return tetra ? Tetrahedra::evaluate(p, x, weights.data())
                       : cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights.data());
        },
        weights);
    }
  }

  const std::atomic<vtkIdType>* owners() const { return this->Owner.get(); }
  const float* weights() const { return this->Weights.get(); }
  std::size_t stride() const { return this->Stride; }

private:
  /// The grid points within `bounds` (widened across a surface's plane);
  /// false if none.
  bool pointsIn(double bounds[6], std::array<std::array<int, 2>, 3>& within) const
  {
    if (this->Flat < 3)
    {
      bounds[2 * this->Flat] -= this->Across;
      bounds[2 * this->Flat + 1] += this->Across;
    }
    for (int a = 0; a < 3; ++a)
    {
      within[a] = pointsWithin(this->Grid, this->Space, a, bounds[2 * a], bounds[2 * a + 1]);
      if (within[a][0] > within[a][1])
      {
        return false;
      }
    }
    return true;
  }

  /// Cell c against the points `within`: `evaluate(x)` is 1 where c holds x
  /// (and has left x's weights in `weights`).
  template <typename Evaluate>
  void test(vtkIdType c, const std::array<std::array<int, 2>, 3>& within, const Evaluate& evaluate,
    const std::vector<double>& weights)
  {
    const bp::ResampleGrid& g = this->Grid;
    for (int k = within[2][0]; k <= within[2][1]; ++k)
      for (int j = within[1][0]; j <= within[1][1]; ++j)
        for (int i = within[0][0]; i <= within[0][1]; ++i)
        {
          const std::size_t q = this->Space.local(i, j, k);
          // An earlier block's, or a lower cell holds it already.
          if (this->Taken[g.index(i, j, k)] || this->Owner[q].load(std::memory_order_relaxed) < c)
          {
            continue;
          }
          const double x[3] = { coordinate(g, 0, i), coordinate(g, 1, j), coordinate(g, 2, k) };
          if (evaluate(x) != 1)
          {
            continue;
          }
          std::lock_guard<std::mutex> lock(this->Stripes[q % this->Stripes.size()]);
          if (c < this->Owner[q].load(std::memory_order_relaxed))
          {
            this->Owner[q].store(c, std::memory_order_relaxed);
            std::transform(weights.begin(), weights.end(), &this->Weights[q * this->Stride],
              [](double w) { return float(w); });
          }
        }
  }

  const bp::ResampleGrid& Grid;
  const Box& Space;
  vtkDataSet* Block;
  const std::vector<std::uint8_t>& Taken;
  const bool OwnBounds;
  const Tetrahedra Tetra;
  const std::size_t Stride; ///< weights kept per grid point: the largest cell's
  int Flat = 3;             ///< a surface's flat axis; 3 for none
  double Across = 0.0;
  std::unique_ptr<std::atomic<vtkIdType>[]> Owner; ///< per point of the box
  std::unique_ptr<float[]> Weights;                ///< Stride per point of the box
  std::array<std::mutex, 256> Stripes;
};
} // namespace

namespace bpvtk
{

void FieldResampler::locate(
  const std::vector<vtkDataSet*>& blocks, double offPlane, const bp::RangeRunner& run)
{
  std::vector<std::uint8_t> taken(this->Grid.pointCount(), 0);
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    this->locateBlock(blocks[b], std::uint32_t(b), offPlane, taken, run);
  }
}

void FieldResampler::locateBlock(vtkDataSet* block, std::uint32_t b, double offPlane,
  std::vector<std::uint8_t>& taken, const bp::RangeRunner& run)
{
  double bounds[6];
  block->GetBounds(bounds);
  Box box;
  for (int a = 0; a < 3; ++a)
  {
    box.range[a] = indexRange(this->Grid, a, bounds[2 * a], bounds[2 * a + 1]);
  }
  const vtkIdType cells = block->GetNumberOfCells();
  if (box.empty() || cells == 0)
  {
    return;
  }
  CellSearch search(this->Grid, box, block, offPlane, taken);
  run(std::size_t(cells),
    [&](std::size_t begin, std::size_t end) { search.run(vtkIdType(begin), vtkIdType(end)); });
  this->keepFound(
    block, b, box.range, search.owners(), search.weights(), search.stride(), taken, run);
}

void FieldResampler::keepFound(vtkDataSet* block, std::uint32_t b,
  const std::array<std::array<int, 2>, 3>& range, const std::atomic<vtkIdType>* owner,
  const float* weights, std::size_t stride, std::vector<std::uint8_t>& taken,
  const bp::RangeRunner& run)
{
  const Box box{ range };
  const int rowsY = box.count(1);
  const std::size_t rows = std::size_t(rowsY) * std::size_t(box.count(2));
  // The point ids of an unstructured grid's cells come from its connectivity;
  // other datasets' from their cells.
  auto* grid = vtkUnstructuredGrid::SafeDownCast(block);
  // Each range of grid rows gathers its samples apart; they are joined in
  // row order, so the samples come out the same whatever the threads did.
  std::mutex joining;
  std::vector<std::pair<std::size_t, Found>> parts;
  run(rows,
    [&](std::size_t begin, std::size_t end)
    {
      Found found;
      vtkNew<vtkGenericCell> cell;
      vtkNew<vtkIdList> scratch;
      std::vector<vtkIdType> ids(stride);
      // Sized once: growing them copied what they held, a tenth of the search.
      std::size_t held = 0;
      const std::size_t rowLength =
        std::size_t(box.count(0)); // row r's points follow r * rowLength
      for (std::size_t q = begin * rowLength; q < end * rowLength; ++q)
      {
        held += owner[q].load(std::memory_order_relaxed) != NoCell ? 1 : 0;
      }
      found.samples.reserve(held);
      found.points.reserve(held * stride);
      found.weights.reserve(held * stride);
      for (std::size_t row = begin; row < end; ++row)
      {
        const int j = range[1][0] + int(row % std::size_t(rowsY));
        const int k = range[2][0] + int(row / std::size_t(rowsY));
        for (int i = range[0][0]; i <= range[0][1]; ++i)
        {
          const std::size_t q = box.local(i, j, k);
          const vtkIdType c = owner[q].load(std::memory_order_relaxed);
          if (c == NoCell)
          {
            continue;
          }
          vtkIdType n = 0;
          if (grid)
          {
            const vtkIdType* pts = nullptr;
            grid->GetCells()->GetCellAtId(c, n, pts, scratch);
            std::copy_n(pts, n, ids.begin());
          }
          else
          {
            block->GetCell(c, cell);
            n = cell->GetNumberOfPoints();
            for (vtkIdType v = 0; v < n; ++v)
            {
              ids[std::size_t(v)] = cell->GetPointId(v);
            }
          }
          const std::size_t p = this->Grid.index(i, j, k);
          taken[p] = 1;
          found.add({ std::uint32_t(p), b, c, 0, 0 }, n, ids.data(), weights + q * stride);
        }
      }
      std::lock_guard<std::mutex> lock(joining);
      parts.emplace_back(begin, std::move(found));
    });
  std::sort(
    parts.begin(), parts.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::size_t samples = this->Samples.size(), entries = this->Weights.size();
  for (const auto& part : parts)
  {
    samples += part.second.samples.size();
    entries += part.second.weights.size();
  }
  this->Samples.reserve(samples);
  this->WeightPoints.reserve(entries);
  this->Weights.reserve(entries);
  for (auto& part : parts)
  {
    this->append(part.second);
  }
}

void FieldResampler::Found::add(
  Sample sample, vtkIdType n, const vtkIdType* ids, const float* cellWeights)
{
  sample.first = std::uint64_t(this->points.size());
  sample.count = std::uint32_t(n);
  this->samples.push_back(sample);
  for (vtkIdType q = 0; q < n; ++q)
  {
    this->points.push_back(ids[q]);
    this->weights.push_back(cellWeights[q]);
  }
}

void FieldResampler::append(const Found& found)
{
  const std::uint64_t shift = this->WeightPoints.size();
  for (Sample s : found.samples)
  {
    s.first += shift;
    this->Samples.push_back(s);
  }
  this->WeightPoints.insert(this->WeightPoints.end(), found.points.begin(), found.points.end());
  this->Weights.insert(this->Weights.end(), found.weights.begin(), found.weights.end());
}

} // namespace bpvtk
