// SPDX-License-Identifier: BSD-3-Clause
// The resampler's geometry key: a fast hash of the sampled blocks' points
// and cells (see TracerGeometryKey.h).
#include "TracerGeometryKey.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>

namespace
{
/// A 64-bit hash of memory: FNV-1a over 8-byte words in four lanes (so the
/// multiplications overlap), chunks of 1 MiB hashed on the runner's threads
/// and combined in order.
class Hash
{
public:
  using Known = std::vector<bpvtk::HashedArray>;

  /// `known`: arrays hashed before, whose hashes stand while they are unmodified.
  Hash(const bp::RangeRunner& run, const Known& known)
    : Run(run)
    , Before(known)
  {
  }
  /// The arrays hashed (or recognised) by this hash.
  Known Seen;
  std::uint64_t value = 1469598103934665603ull;

  void mix(std::uint64_t word) { this->value = (this->value ^ word) * Prime; }

  void add(const void* data, std::size_t bytes)
  {
    const auto* p = static_cast<const unsigned char*>(data);
    constexpr std::size_t chunk = std::size_t(1) << 20;
    const std::size_t chunks = (bytes + chunk - 1) / chunk;
    std::vector<std::uint64_t> parts(chunks);
    this->Run(chunks,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t c = begin; c < end; ++c)
        {
          parts[c] = lanes(p + c * chunk, std::min(chunk, bytes - c * chunk));
        }
      });
    this->mix(bytes);
    for (std::uint64_t part : parts)
    {
      this->mix(part);
    }
  }

  /// An array's values, through its memory where it has a plain layout.
  void add(vtkDataArray* array)
  {
    if (!array)
    {
      this->mix(0);
      return;
    }
    const vtkMTimeType time = array->GetMTime();
    for (const bpvtk::HashedArray& known : this->Before)
    {
      if (known.array == array && known.time == time)
      {
        this->mix(known.hash);
        this->Seen.push_back(known);
        return;
      }
    }
    Hash own(this->Run, Known());
    if (array->HasStandardMemoryLayout())
    {
      own.add(array->GetVoidPointer(0),
        std::size_t(array->GetDataSize()) * std::size_t(array->GetDataTypeSize()));
    }
    else
    {
      std::vector<double> values(std::size_t(array->GetDataSize()));
      for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
      {
        array->GetTuple(t, &values[std::size_t(t) * array->GetNumberOfComponents()]);
      }
      own.add(values.data(), values.size() * sizeof(double));
    }
    this->mix(own.value);
    this->Seen.push_back({ array, time, own.value });
  }
  void add(vtkCellArray* cells)
  {
    this->add(cells->GetOffsetsArray());
    this->add(cells->GetConnectivityArray());
  }

private:
  static constexpr std::uint64_t Prime = 1099511628211ull;

  static std::uint64_t lanes(const unsigned char* p, std::size_t bytes)
  {
    std::uint64_t h[4] = { 1469598103934665603ull, 2, 3, 4 };
    std::size_t i = 0;
    for (; i + 32 <= bytes; i += 32)
    {
      std::uint64_t w[4];
      std::memcpy(w, p + i, 32);
      for (int l = 0; l < 4; ++l)
      {
        h[l] = (h[l] ^ w[l]) * Prime;
      }
    }
    std::uint64_t tail[4] = { 0, 0, 0, 0 };
    std::memcpy(tail, p + i, bytes - i);
    std::uint64_t all = 1469598103934665603ull;
    for (int l = 0; l < 4; ++l)
    {
      all = (((all ^ h[l]) * Prime) ^ tail[l]) * Prime;
    }
    return all;
  }

  const bp::RangeRunner& Run;
  const Known& Before;
};

/// What locating depends on in a block: its points, its cells.
void addGeometry(Hash& h, vtkDataSet* block)
{
  h.mix(std::uint64_t(block->GetNumberOfPoints()));
  h.mix(std::uint64_t(block->GetNumberOfCells()));
  if (auto* image = vtkImageData::SafeDownCast(block))
  {
    h.add(image->GetExtent(), 6 * sizeof(int));
    h.add(image->GetOrigin(), 3 * sizeof(double));
    h.add(image->GetSpacing(), 3 * sizeof(double));
    return;
  }
  if (auto* rectilinear = vtkRectilinearGrid::SafeDownCast(block))
  {
    h.add(rectilinear->GetExtent(), 6 * sizeof(int));
    h.add(rectilinear->GetXCoordinates());
    h.add(rectilinear->GetYCoordinates());
    h.add(rectilinear->GetZCoordinates());
    return;
  }
  auto* pointSet = vtkPointSet::SafeDownCast(block);
  h.add(pointSet && pointSet->GetPoints() ? pointSet->GetPoints()->GetData() : nullptr);
  if (auto* structured = vtkStructuredGrid::SafeDownCast(block))
  {
    h.add(structured->GetExtent(), 6 * sizeof(int));
  }
  else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(block))
  {
    h.add(grid->GetCells());
    h.add(grid->GetCellTypesArray());
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(block))
  {
    for (vtkCellArray* cells :
      { poly->GetVerts(), poly->GetLines(), poly->GetPolys(), poly->GetStrips() })
    {
      h.add(cells);
    }
  }
  else
  {
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c)
    {
      block->GetCellPoints(c, ids);
      h.mix(std::uint64_t(block->GetCellType(c)));
      h.add(ids->GetPointer(0), std::size_t(ids->GetNumberOfIds()) * sizeof(vtkIdType));
    }
  }
}

} // namespace

namespace bpvtk
{

std::uint64_t geometryKey(const std::vector<vtkDataSet*>& blocks,
  const std::array<int, 3>& requested, vtkMultiProcessController* controller,
  const bp::RangeRunner& run, std::vector<HashedArray>& hashed)
{
  Hash key(run, hashed);
  key.mix(blocks.size());
  for (vtkDataSet* block : blocks)
  {
    addGeometry(key, block);
  }
  for (int n : requested)
  {
    key.mix(std::uint64_t(std::max(n, 0)));
  }
  key.mix(std::uint64_t(controller ? controller->GetNumberOfProcesses() : 1));
  hashed = std::move(key.Seen);
  return key.value;
}

} // namespace bpvtk
