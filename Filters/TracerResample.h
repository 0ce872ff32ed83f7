// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerResample.h
 * @brief Any mesh the tracer is given, as the uniform grid the engines trace
 * on: unstructured, curvilinear, polygonal and composite input (multiblock,
 * partitioned, AMR), point or cell vectors.
 *
 * The grid is bp::chooseResampleGrid()'s over the whole data's bounds. Each
 * grid point takes the interpolation weights of the cell that holds it
 * (vtkProbeFilter's rule, which vtkResampleToImage applies: point vectors
 * interpolated with the cell's weights, cell vectors the cell's value). The
 * cells are searched cell by cell, in parallel: each cell tests the grid
 * points within its bounds with VTK's own EvaluatePosition, the test
 * vtkStaticCellLocator::FindCell makes, so a point is inside exactly where a
 * FindCell per point finds it; where several cells hold a point (on a shared
 * face, or within a tetrahedron's 0.001 parametric tolerance of one) the
 * lowest-numbered cell gives its weights, the same on every VTK and thread
 * count (the locator took whichever its bin's unstable sort put first). A
 * point in no cell lies outside the
 * flow's domain: vtkValidPointMask 0, as ParaView's resamplers write it, so the
 * masked-grid machinery (releases, resets, both engines) applies unchanged.
 *
 * Unlike vtkResampleToImage, which locates every point again for every time
 * step, the located cells and weights are kept while the mesh stays the same
 * (same points and cells, by content): a static mesh with changing vectors
 * costs one weighted sum per grid point and time step.
 *
 * Only the blocks of the highest cell dimension are sampled: the boundary
 * patches of an OpenFOAM case or the side sets of an Exodus file lie on the
 * volume's surface and carry no flow of their own. Where blocks overlap, the
 * first in traversal order wins; for AMR the finest level.
 *
 * In a distributed run each process locates the grid points in its own part
 * of the mesh; of the processes that hold a point, the lowest-ranked gives
 * its value, and every process ends with the whole grid (collective).
 */
#ifndef BoundParticles_TracerResample_h
#define BoundParticles_TracerResample_h

#include "Parallel.h"
#include "ResampleGrid.h"
#include "TracerGeometryKey.h"

#include "vtkType.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDataObject;
class vtkDataSet;
class vtkImageData;
class vtkMultiProcessController;

namespace bpvtk
{

/// The leaves of `data` in the composite's traversal order (a data set alone
/// is the one leaf), null blocks included, so that leaf k is the k-th leaf
/// of the Multiblock Inspector's tree, from 0 (the Surfaces' SurfaceId 6 + k);
/// a leaf that is not a data set, or no data, is null.
std::vector<vtkDataSet*> leafDataSets(vtkDataObject* data);

/// Which input array moves the elements: the Vectors property's choice.
struct VectorsChoice
{
  std::string name;    ///< empty: the first 3-component point array, else cell array
  int association = 0; ///< vtkDataObject::FIELD_ASSOCIATION_POINTS or _CELLS
};

class FieldResampler
{
public:
  /// Whether `input` is traced through a resampled grid: anything but an
  /// image or a rectilinear grid (decided by type alone, so every process of
  /// a distributed run decides alike, whatever data it holds).
  static bool needed(vtkDataObject* input);

  /**
   * Resamples this process's `input` onto the grid of `requested` points per
   * axis (0: automatic): `image` gets the grid, the vectors as 3-component
   * float point data named as in the input, and vtkValidPointMask. With a
   * `controller` every process must call this, and all get the whole grid.
   * `run` spreads the cell search and the sums over threads. Returns the
   * error, if any (every process fails alike); `warning` says what was left
   * out (blocks without the array).
   */
  std::string resample(vtkDataObject* input, const VectorsChoice& vectors,
    const std::array<int, 3>& requested, vtkMultiProcessController* controller,
    const bp::RangeRunner& run, vtkImageData* image, std::string& warning);

  /// The grid of the last resample.
  const bp::ResampleGrid& grid() const { return this->Grid; }
  /// Whether the last resample kept the located cells and weights of the one before.
  bool keptWeights() const { return this->Kept; }
  /// The name of the array the last resample took (the choice, or the first
  /// vector array found).
  const std::string& arrayName() const { return this->ArrayName; }
  /// Forgets the kept weights.
  void clear();
  /**
   * The grid of the next resample is chosen anew. Until then it is kept,
   * whatever the mesh: the tracer's time steps must share one grid, and an
   * adapting mesh (cells refined or coarsened, another point count) or a
   * moving one is resampled at every time step onto the grid chosen for the
   * first one read. The tracer calls this while it holds no time step.
   */
  void forgetGrid() { this->GridKept = false; }
  /// Release Weights: the input's array (its magnitude), a point array
  /// interpolated as point vectors are or a cell array taken per cell
  /// (`association` CELLS takes the cell array first, otherwise the point
  /// array is taken where a block has one), that resample() also puts on the
  /// grid under that name, one float per point; empty for none. Values
  /// beyond float's range are scaled into it alike on every process.
  void setReleaseWeights(const std::string& name, int association)
  {
    this->WeightsName = name;
    this->WeightsAssociation = association;
  }

  /// About what resampling takes per grid point, while a grid is located.
  static const double BytesPerGridPoint;

private:
  /// Where one grid point takes its vector from: a cell of a block, and for
  /// point vectors the cell's points' weights (entries [first, first + count)).
  struct Sample
  {
    std::uint32_t point; ///< the grid point
    std::uint32_t block; ///< index into the sampled blocks
    vtkIdType cell;
    std::uint64_t first;
    std::uint32_t count;
  };

  /// The blocks that carry the flow and how their vectors are found.
  struct Selection
  {
    std::vector<vtkDataSet*> blocks; ///< of the highest cell dimension, with the array
    bool cellVectors = false;
    int dimension = 0;       ///< the highest cell dimension over every process
    std::size_t lacking = 0; ///< blocks of that dimension without the array
  };
  /// The blocks of `input` to sample, and the array's name (ArrayName).
  Selection select(
    vtkDataObject* input, const VectorsChoice& vectors, vtkMultiProcessController* controller);
  /// Grid: chooseResampleGrid() over every process's blocks, or the grid
  /// kept (forgetGrid()); `offPlane`: how far a surface's cells lie off the
  /// grid's plane. Returns the error, if any.
  /// The Release Weights interpolated onto the grid as the vectors are
  /// (zero where a block lacks the array); `found` whether any block has it.
  /// Collective with a `controller` (the scale for values beyond float).
  void interpolateWeights(const std::vector<vtkDataSet*>& blocks,
    vtkMultiProcessController* controller, const bp::RangeRunner& run, std::vector<float>& values,
    bool& found) const;
  std::string chooseGrid(const Selection& selected, const std::array<int, 3>& requested,
    vtkMultiProcessController* controller, double& offPlane);
  /// What a range of grid rows located in one block: its samples and their
  /// cells' point ids and weights (Sample::first indexes these).
  struct Found
  {
    std::vector<Sample> samples;
    std::vector<vtkIdType> points;
    std::vector<float> weights;
    /// Appends `sample` (its point, block and cell) with its cell's `n`
    /// point `ids` and their `cellWeights`.
    void add(Sample sample, vtkIdType n, const vtkIdType* ids, const float* cellWeights);
  };
  /// Finds each grid point's cell (the first block's that holds it) and
  /// weights; a surface's cells up to `offPlane` from the grid's plane
  /// (TracerResampleLocate.cxx).
  void locate(const std::vector<vtkDataSet*>& blocks, double offPlane, const bp::RangeRunner& run);
  /**
   * locate() in block `b`: the grid points it holds that no earlier block
   * took (`taken`, per grid point). Cell by cell, in parallel: each cell
   * tests the grid points within its bounds (EvaluatePosition, as
   * vtkStaticCellLocator::FindCell tests a cell whose bounds hold the point),
   * and of the cells that hold a point the lowest-numbered wins.
   */
  void locateBlock(vtkDataSet* block, std::uint32_t b, double offPlane,
    std::vector<std::uint8_t>& taken, const bp::RangeRunner& run);
  /// locateBlock()'s samples: the grid points of the box `range` that have
  /// an `owner` (per point of the box; its `weights`, `stride` per point),
  /// marked taken.
  void keepFound(vtkDataSet* block, std::uint32_t b, const std::array<std::array<int, 2>, 3>& range,
    const std::atomic<vtkIdType>* owner, const float* weights, std::size_t stride,
    std::vector<std::uint8_t>& taken, const bp::RangeRunner& run);
  /// Appends a range's samples, shifted past the weights already held.
  void append(const Found& found);
  /// In a distributed run, keeps only the samples of points this process
  /// gives (the lowest rank holding them), and marks the points some process holds.
  void keepOwnSamples(vtkMultiProcessController* controller);
  /// The grid's vectors (3 floats a point; 0 outside) from this process's samples.
  void interpolate(const std::vector<vtkDataSet*>& blocks, bool cellVectors,
    const bp::RangeRunner& run, std::vector<float>& values) const;

  /// The resampled grid as an image: the vectors and vtkValidPointMask.
  void fillImage(const std::vector<float>& values, vtkImageData* image) const;

  bp::ResampleGrid Grid;
  bool GridKept = false;              ///< forgetGrid()
  std::array<int, 3> GridRequested{}; ///< the Resample Dimensions it was chosen for
  std::string GridNote;               ///< what the automatic choice gave up (a warning)
  std::string BeyondNote;             ///< the last mesh reached beyond the grid (a warning)
  std::uint64_t GeometryKey = 0;
  std::vector<HashedArray> Hashed; ///< the arrays of the last key
  bool Kept = false;
  std::string ArrayName;
  std::string WeightsName;    ///< setReleaseWeights()
  int WeightsAssociation = 0; ///< setReleaseWeights(): vtkDataObject's FIELD_ASSOCIATION_*
  std::vector<Sample> Samples;
  std::vector<vtkIdType> WeightPoints;
  std::vector<float> Weights;
  std::vector<std::uint8_t> Inside; ///< per grid point: some process samples it
};

} // namespace bpvtk

#endif
