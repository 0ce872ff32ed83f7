// SPDX-License-Identifier: BSD-3-Clause
#include "TracerResample.h"

#include "Memory.h"
#include "ReleaseWeights.h"
#include "TracerGeometryKey.h"
#include "TracerInput.h"
#include "TracerParallel.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkCharArray.h"
#include "vtkCommunicator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <mutex>
#include <sstream>

namespace
{
/// The datasets of `input` that have cells, in traversal order; for AMR the
/// finest level first, so that it wins where levels overlap.
std::vector<vtkDataSet*> blocksWithCells(vtkDataObject* input)
{
  std::vector<vtkDataSet*> blocks = bpvtk::leafDataSets(input);
  blocks.erase(std::remove_if(blocks.begin(), blocks.end(),
                 [](vtkDataSet* block) { return !block || block->GetNumberOfCells() == 0; }),
    blocks.end());
  if (vtkOverlappingAMR::SafeDownCast(input))
  {
    std::reverse(blocks.begin(), blocks.end());
  }
  return blocks;
}

/// The highest dimension of a cell of `data` (3 for a volume mesh).
int cellDimension(vtkDataSet* data)
{
  if (auto* structured = vtkStructuredGrid::SafeDownCast(data))
  {
    return structured->GetDataDimension();
  }
  int dimension = 0;
  const vtkIdType cells = data->GetNumberOfCells();
  for (vtkIdType c = 0; c < cells && dimension < 3; ++c)
  {
    dimension =
      std::max(dimension, vtkCellTypes::GetDimension((unsigned char)data->GetCellType(c)));
  }
  return dimension;
}

/// The cells of `data` that are not another piece's (ghost cells), which
/// every process counts once.
vtkIdType ownCells(vtkDataSet* data)
{
  vtkUnsignedCharArray* ghosts = data->GetCellGhostArray();
  if (!ghosts)
  {
    return data->GetNumberOfCells();
  }
  const auto values = vtk::DataArrayValueRange<1>(ghosts);
  const unsigned char others =
    vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  return vtkIdType(std::count_if(
    values.begin(), values.end(), [&](unsigned char g) { return (g & others) == 0; }));
}

/// The 3-component array `name` of `data`'s points or cells; null if none.
vtkDataArray* vectorArray(vtkDataSet* data, const std::string& name, bool cells)
{
  vtkDataSetAttributes* attributes =
    cells ? static_cast<vtkDataSetAttributes*>(data->GetCellData()) : data->GetPointData();
  vtkDataArray* array = attributes->GetArray(name.c_str());
  return array && array->GetNumberOfComponents() == 3 ? array : nullptr;
}

/// The first 3-component point (else cell) array's name among the blocks.
std::string firstVectorName(const std::vector<vtkDataSet*>& blocks, bool& cells)
{
  for (bool cellData : { false, true })
  {
    for (vtkDataSet* block : blocks)
    {
      vtkDataSetAttributes* attributes =
        cellData ? static_cast<vtkDataSetAttributes*>(block->GetCellData()) : block->GetPointData();
      for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
      {
        vtkDataArray* a = attributes->GetArray(i);
        if (a && a->GetName() && a->GetNumberOfComponents() == 3 &&
          std::strcmp(a->GetName(), "vtkValidPointMask") != 0)
        {
          cells = cellData;
          return a->GetName();
        }
      }
    }
  }
  return std::string();
}

/// The array the Vectors name (unnamed: the first 3-component point, else
/// cell array) and, in `cells`, whether it is a cell array, alike on every
/// process: the lowest process whose blocks hold it decides. Another process
/// may hold no cells (a serial file read by every process gives them all to
/// process 0) or other arrays, and the name and association decide which
/// collective steps follow (the weights' own interpolation when they are not
/// the vectors).
std::string agreedVectors(const std::vector<vtkDataSet*>& blocks,
  const bpvtk::VectorsChoice& vectors, vtkMultiProcessController* controller, bool& cells)
{
  cells = vectors.association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  std::string name = vectors.name.empty() ? firstVectorName(blocks, cells) : vectors.name;
  // A name given as point data that only the cells have (or the reverse) is taken where it is.
  const auto hasArray = [&](bool cellData)
  {
    return std::any_of(blocks.begin(), blocks.end(),
      [&](vtkDataSet* b) { return vectorArray(b, name, cellData) != nullptr; });
  };
  if (!hasArray(cells) && hasArray(!cells))
  {
    cells = !cells;
  }
  const std::string mine = hasArray(cells) ? (cells ? "c" : "p") + name : std::string();
  const std::string agreed = bpvtk::firstNonEmpty(controller, mine);
  if (!agreed.empty())
  {
    cells = agreed[0] == 'c';
    name = agreed.substr(1);
  }
  return name;
}

/// What a mesh whose `bounds` reach beyond the grid (chosen at an earlier
/// time step) loses; empty when they do not.
std::string beyondGrid(const bp::ResampleGrid& g, const std::array<double, 6>& bounds)
{
  std::ostringstream say;
  for (int a = 0; a < 3; ++a)
  {
    const double last = g.origin[a] + (g.dims[a] - 1) * g.spacing[a];
    const double slack = 1e-9 * std::max({ 1.0, std::abs(g.origin[a]), std::abs(last) });
    if (g.dims[a] > 1 && (bounds[2 * a] < g.origin[a] - slack || bounds[2 * a + 1] > last + slack))
    {
      say << (say.str().empty() ? "" : " and ") << "XYZ"[a];
    }
  }
  if (say.str().empty())
  {
    return std::string();
  }
  return "The mesh of a later time step reaches beyond the resampled grid along " + say.str() +
    ": the grid spans the mesh of the first time step read, and cells outside it are left out "
    "(outside the flow).";
}

/// Collective sum, min or max in place (nothing without a controller).
template <typename T>
void allReduce(vtkMultiProcessController* controller, std::vector<T>& values, int operation)
{
  if (controller && !values.empty())
  {
    std::vector<T> reduced(values.size());
    controller->AllReduce(values.data(), reduced.data(), vtkIdType(values.size()), operation);
    values.swap(reduced);
  }
}
} // namespace

namespace bpvtk
{

std::vector<vtkDataSet*> leafDataSets(vtkDataObject* data)
{
  std::vector<vtkDataSet*> leaves;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    it->SkipEmptyNodesOff(); // a null block is a leaf too: the numbers are the user's blocks
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      leaves.push_back(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()));
    }
  }
  else
  {
    leaves.push_back(vtkDataSet::SafeDownCast(data));
  }
  return leaves;
}

// The vectors and mask (13 bytes), the owner in parallel (4), while the cells
// are searched the winning cell and its weights (8 + 32) and whether a block
// took the point (1), then a sample and the weights of a cell of up to 8 points
// (12 bytes each).
const double FieldResampler::BytesPerGridPoint = 58.0 + sizeof(Sample) + 96.0;

bool FieldResampler::needed(vtkDataObject* input)
{
  return input && !vtkImageData::SafeDownCast(input) && !vtkRectilinearGrid::SafeDownCast(input);
}

void FieldResampler::clear()
{
  this->GeometryKey = 0;
  this->Hashed.clear();
  this->Samples.clear();
  this->WeightPoints.clear();
  this->Weights.clear();
  this->Inside.clear();
}

std::string FieldResampler::resample(vtkDataObject* input, const VectorsChoice& vectors,
  const std::array<int, 3>& requested, vtkMultiProcessController* controller,
  const bp::RangeRunner& run, vtkImageData* image, std::string& warning)
{
  warning.clear();
  this->Kept = false;
  const Selection selected = this->select(input, vectors, controller);
  if (selected.lacking > 0)
  {
    std::ostringstream say;
    say << selected.lacking << " block(s) of the input have no 3-component "
        << (selected.cellVectors ? "cell" : "point") << " array '" << this->ArrayName
        << "'; their cells count as outside the flow's domain.";
    warning = say.str();
  }
  // The same mesh as last time (by content) on every process: the same grid,
  // cells and weights; only the vectors are new.
  std::vector<HashedArray> hashed = this->Hashed;
  const std::uint64_t key = geometryKey(selected.blocks, requested, controller, run, hashed);
  std::vector<int> same(1, key == this->GeometryKey && !this->Inside.empty() ? 1 : 0);
  allReduce(controller, same, vtkCommunicator::MIN_OP);
  this->Kept = same[0] == 1;
  // The same mesh keeps its grid, chosen anew or not.
  this->GridKept = this->GridKept || this->Kept;
  if (!this->Kept)
  {
    this->clear();
    double offPlane = 0.0;
    std::string error = this->chooseGrid(selected, requested, controller, offPlane);
    if (error.empty())
    {
      error = agreeOnError(controller,
        bp::checkAllocatable(
          double(this->Grid.pointCount()) * BytesPerGridPoint, "The resampled grid of the input"));
      error = error.empty() ? error : error + ". Set Resample Dimensions to fewer points.";
    }
    if (!error.empty())
    {
      return error;
    }
    // A surface's cells are found as far off the grid's plane as they lie
    // (rounding, a slight tilt: the plane lies mid-way through its thickness).
    this->locate(selected.blocks, offPlane, run);
    this->keepOwnSamples(controller);
    this->GeometryKey = key;
  }
  this->Hashed = std::move(hashed);
  for (const std::string* note : { &this->GridNote, &this->BeyondNote })
  {
    warning += warning.empty() || note->empty() ? *note : " " + *note;
  }
  std::vector<float> values;
  this->interpolate(selected.blocks, selected.cellVectors, run, values);
  allReduce(controller, values, vtkCommunicator::SUM_OP);
  this->fillImage(values, image);
  // Weights by the Vectors themselves are the resampled vectors' magnitude.
  if (!this->WeightsName.empty() && this->WeightsName != this->ArrayName)
  {
    bool found = false;
    this->interpolateWeights(selected.blocks, controller, run, values, found);
    std::vector<int> any(1, found ? 1 : 0);
    allReduce(controller, any, vtkCommunicator::MAX_OP);
    allReduce(controller, values, vtkCommunicator::SUM_OP);
    if (any[0] == 1)
    {
      // Absent otherwise, so the tracer says the input has no such array.
      vtkNew<vtkFloatArray> weights;
      weights->SetName(this->WeightsName.c_str());
      weights->SetNumberOfTuples(vtkIdType(values.size()));
      std::copy(values.begin(), values.end(), weights->GetPointer(0));
      image->GetPointData()->AddArray(weights);
    }
  }
  return std::string();
}

FieldResampler::Selection FieldResampler::select(
  vtkDataObject* input, const VectorsChoice& vectors, vtkMultiProcessController* controller)
{
  Selection s;
  const std::vector<vtkDataSet*> blocks = blocksWithCells(input);
  const std::string name = agreedVectors(blocks, vectors, controller, s.cellVectors);
  this->ArrayName = name;
  // Only the blocks of the highest cell dimension carry the flow (every
  // process decides from the same global dimension).
  std::vector<int> dimension(1, 0);
  std::vector<int> dimensions;
  for (vtkDataSet* block : blocks)
  {
    dimensions.push_back(cellDimension(block));
    dimension[0] = std::max(dimension[0], dimensions.back());
  }
  allReduce(controller, dimension, vtkCommunicator::MAX_OP);
  s.dimension = dimension[0];
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    if (dimensions[b] != s.dimension)
    {
      continue;
    }
    if (vectorArray(blocks[b], name, s.cellVectors))
    {
      s.blocks.push_back(blocks[b]);
    }
    else
    {
      ++s.lacking;
    }
  }
  return s;
}

std::string FieldResampler::chooseGrid(const Selection& selected,
  const std::array<int, 3>& requested, vtkMultiProcessController* controller, double& offPlane)
{
  // Bounds as (-min, max) pairs reduced by max; the cells counted once (no ghosts).
  std::vector<double> extremes(6, -1e300);
  std::vector<double> cells(1, 0.0);
  for (vtkDataSet* block : selected.blocks)
  {
    double b[6];
    block->GetBounds(b);
    for (int a = 0; a < 3; ++a)
    {
      extremes[2 * a] = std::max(extremes[2 * a], -b[2 * a]);
      extremes[2 * a + 1] = std::max(extremes[2 * a + 1], b[2 * a + 1]);
    }
    cells[0] += double(ownCells(block));
  }
  allReduce(controller, extremes, vtkCommunicator::MAX_OP);
  allReduce(controller, cells, vtkCommunicator::SUM_OP);
  std::ostringstream err;
  if (cells[0] == 0.0 && this->ArrayName.empty())
  {
    err << "The input has no cells with a 3-component point or cell array: Bound Particle "
           "Tracer needs a grid or a mesh whose points or cells carry the flow's vectors "
           "(choose them in Vectors).";
  }
  else if (cells[0] == 0.0)
  {
    err << "The input has no cells with a 3-component " << (selected.cellVectors ? "cell" : "point")
        << " array '" << this->ArrayName
        << "' to resample: Bound Particle Tracer needs a mesh (cells) carrying the Vectors.";
  }
  else if (selected.dimension < 2)
  {
    err << "The input's cells are points or lines: a flow needs a mesh of surfaces (2D) or "
           "volumes (3D) to be resampled from. Give the tracer the mesh the vectors live on.";
  }
  if (!err.str().empty())
  {
    return err.str();
  }
  const std::array<double, 6> bounds = { -extremes[0], extremes[1], -extremes[2], extremes[3],
    -extremes[4], extremes[5] };
  const bool surface = selected.dimension == 2;
  // An automatic grid takes at most half of what this process can allocate
  // (every process decides alike from the smallest share).
  std::vector<double> affordable(1, 0.5 * bp::allocatableBytes() / BytesPerGridPoint);
  allReduce(controller, affordable, vtkCommunicator::MIN_OP);
  if (!this->GridKept || requested != this->GridRequested)
  {
    // Chosen once while time steps hold it: an adapting mesh (other cells,
    // another point count at each step) is resampled onto the same grid.
    this->Grid = bp::chooseResampleGrid(bounds, cells[0], requested, surface, affordable[0]);
    this->GridKept = this->Grid.error.empty();
    this->GridRequested = requested;
    this->GridNote = this->Grid.note;
  }
  offPlane = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    if (surface && this->Grid.dims[a] == 1)
    {
      offPlane = std::max(std::abs(bounds[2 * a] - this->Grid.origin[a]),
        std::abs(bounds[2 * a + 1] - this->Grid.origin[a]));
    }
  }
  this->BeyondNote = beyondGrid(this->Grid, bounds);
  return this->Grid.error;
}

void FieldResampler::fillImage(const std::vector<float>& values, vtkImageData* image) const
{
  const bp::ResampleGrid& grid = this->Grid;
  image->Initialize();
  image->SetDimensions(grid.dims.data());
  image->SetOrigin(grid.origin.data());
  image->SetSpacing(grid.spacing.data());
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName(this->ArrayName.c_str());
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(vtkIdType(grid.pointCount()));
  std::copy(values.begin(), values.end(), velocity->GetPointer(0));
  vtkNew<vtkCharArray> mask;
  mask->SetName("vtkValidPointMask");
  mask->SetNumberOfTuples(vtkIdType(grid.pointCount()));
  std::copy(this->Inside.begin(), this->Inside.end(), mask->GetPointer(0));
  image->GetPointData()->AddArray(velocity);
  image->GetPointData()->SetVectors(velocity);
  image->GetPointData()->AddArray(mask);
}

void FieldResampler::keepOwnSamples(vtkMultiProcessController* controller)
{
  const std::size_t n = this->Grid.pointCount();
  if (!controller)
  {
    this->Inside.assign(n, 0);
    for (const Sample& s : this->Samples)
    {
      this->Inside[s.point] = 1;
    }
    return;
  }
  // The lowest-ranked process that holds a point gives its value; the others drop theirs.
  const int me = controller->GetLocalProcessId();
  std::vector<int> owner(n, INT_MAX);
  for (const Sample& s : this->Samples)
  {
    owner[s.point] = me;
  }
  allReduce(controller, owner, vtkCommunicator::MIN_OP);
  this->Samples.erase(std::remove_if(this->Samples.begin(), this->Samples.end(),
                        [&](const Sample& s) { return owner[s.point] != me; }),
    this->Samples.end());
  this->Inside.resize(n);
  std::transform(owner.begin(), owner.end(), this->Inside.begin(),
    [](int rank) { return std::uint8_t(rank != INT_MAX ? 1 : 0); });
}

void FieldResampler::interpolate(const std::vector<vtkDataSet*>& blocks, bool cellVectors,
  const bp::RangeRunner& run, std::vector<float>& values) const
{
  std::vector<std::vector<float>> arrays(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    copyToFloats(vectorArray(blocks[b], this->ArrayName, cellVectors), arrays[b]);
  }
  values.assign(3 * this->Grid.pointCount(), 0.0f);
  run(this->Samples.size(),
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t s = begin; s < end; ++s)
      {
        const Sample& sample = this->Samples[s];
        const std::vector<float>& v = arrays[sample.block];
        float* out = &values[3 * std::size_t(sample.point)];
        if (cellVectors)
        {
          std::copy_n(&v[3 * std::size_t(sample.cell)], 3, out);
          continue;
        }
        double sum[3] = { 0, 0, 0 };
        for (std::uint32_t q = 0; q < sample.count; ++q)
        {
          const double w = this->Weights[sample.first + q];
          const float* x = &v[3 * std::size_t(this->WeightPoints[sample.first + q])];
          for (int a = 0; a < 3; ++a)
          {
            sum[a] += w * double(x[a]);
          }
        }
        for (int a = 0; a < 3; ++a)
        {
          out[a] = float(sum[a]);
        }
      }
    });
}

void FieldResampler::interpolateWeights(const std::vector<vtkDataSet*>& blocks,
  vtkMultiProcessController* controller, const bp::RangeRunner& run, std::vector<float>& values,
  bool& found) const
{
  // Per block: the weights are a point array (interpolated as point vectors
  // are) or a cell array (taken per cell, as cell vectors are), whichever the
  // block has, the cell array first where the user picked one.
  std::vector<vtkDataArray*> chosen(blocks.size(), nullptr);
  std::vector<char> perCell(blocks.size(), 0);
  double largest = 0.0; // the largest finite value, for one scale everywhere
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    vtkDataArray* points = blocks[b]->GetPointData()->GetArray(this->WeightsName.c_str());
    vtkDataArray* cells = blocks[b]->GetCellData()->GetArray(this->WeightsName.c_str());
    const bool pointsFit = points && points->GetNumberOfTuples() == blocks[b]->GetNumberOfPoints();
    const bool cellsFit = cells && cells->GetNumberOfTuples() == blocks[b]->GetNumberOfCells();
    const bool cellsFirst = this->WeightsAssociation == vtkDataObject::FIELD_ASSOCIATION_CELLS;
    perCell[b] = cellsFit && (cellsFirst || !pointsFit);
    chosen[b] = perCell[b] ? cells : (pointsFit ? points : nullptr);
    if (chosen[b])
    {
      largest = std::max(largest, largestFinite(chosen[b]));
    }
  }
  std::vector<double> top(1, largest);
  allReduce(controller, top, vtkCommunicator::MAX_OP);
  const double scale = bp::releaseWeightScale(top[0]);
  std::vector<std::vector<float>> arrays(blocks.size());
  found = false;
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    if (chosen[b])
    {
      std::vector<float> raw;
      copyToFloats(chosen[b], raw, scale);
      arrays[b] = bp::releaseWeightValues(raw, chosen[b]->GetNumberOfComponents());
      found = true;
    }
    else
    {
      // A block without them weighs nothing.
      arrays[b].assign(
        std::size_t(perCell[b] ? blocks[b]->GetNumberOfCells() : blocks[b]->GetNumberOfPoints()),
        0.0f);
    }
  }
  values.assign(this->Grid.pointCount(), 0.0f);
  run(this->Samples.size(),
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t s = begin; s < end; ++s)
      {
        const Sample& sample = this->Samples[s];
        const std::vector<float>& w = arrays[sample.block];
        if (perCell[sample.block])
        {
          values[sample.point] = w[std::size_t(sample.cell)];
          continue;
        }
        double sum = 0.0;
        for (std::uint32_t q = 0; q < sample.count; ++q)
        {
          sum += this->Weights[sample.first + q] *
            double(w[std::size_t(this->WeightPoints[sample.first + q])]);
        }
        values[sample.point] = float(sum);
      }
    });
}

} // namespace bpvtk
