// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerOutput.h
 * @brief Builds the tracer's output polydata from the rows of bp::outputArrays().
 *
 * With the particles in this process (the CPU engine) the output has one
 * point per particle, the template's cells per element, and every array of
 * the table computed as its row says. Without them (a GPU display runs the
 * engine in its own context) it has two points spanning the field that carry
 * every array of the table with two values, the range it is expected to span,
 * so displays offer the arrays for colouring and colour maps rescale sensibly.
 */
#ifndef BoundParticles_TracerOutput_h
#define BoundParticles_TracerOutput_h

#include "TracerOutputArrays.h" // for OutputFrame

#include "vtkCellArray.h" // for vtkSmartPointer<vtkCellArray>
#include "vtkSmartPointer.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

class vtkDataArray;
class vtkPolyData;

namespace bpvtk
{

/**
 * What the output keeps from one frame to the next: its cells, while the
 * element count and shape stay, and its arrays' memory. An array nothing
 * else holds any more (a display's copy of the output lets go of it when it
 * updates) is written again in place, so a frame does not pay the kernel for
 * tens of megabytes of fresh pages. Two of each are kept: the one a display
 * still holds and the one being written. An array whose values depend only
 * on what does not change from frame to frame (ElementId, ParticleIndex;
 * Layer and Radius until an element is released again) is shown again as it
 * is, not written at all.
 */
class OutputStorage
{
public:
  /// Sets `output`'s cells for `engine`'s elements, built again only when
  /// the element count changed (or after reset()), and for `trailPoses`
  /// poses of trails whose points follow the elements' (built each time).
  void applyCells(vtkPolyData* output, const bp::Engine& engine, std::size_t trailPoses = 0);
  /// An array for `row` with `tuples` tuples, reused when free, marked modified.
  vtkSmartPointer<vtkDataArray> array(const bp::OutputArray& row, vtkIdType tuples);
  /// Points' storage of `dataType` (VTK_FLOAT or VTK_DOUBLE) for `count` points.
  vtkSmartPointer<vtkDataArray> pointData(int dataType, vtkIdType count);
  /// The array last shown for `row` with the same `key` (unchangedKey()),
  /// values and ranges as they were; null when there is none (key 0: never).
  vtkDataArray* unchanged(const bp::OutputArray& row, std::uint64_t key) const;
  /// Keeps `array`, written, as `row`'s for `key` (0: keeps none).
  void setUnchanged(const bp::OutputArray& row, std::uint64_t key, vtkDataArray* array);
  /// Forgets the cells (the shape may have changed).
  void reset() { this->Cells = nullptr; }

private:
  /// One of `kept` that nothing else holds and that fits, marked modified;
  /// else a new one, kept in place of the oldest.
  vtkSmartPointer<vtkDataArray> take(std::vector<vtkSmartPointer<vtkDataArray>>& kept, int dataType,
    int components, vtkIdType tuples);

  vtkSmartPointer<vtkCellArray> Cells;
  vtkSmartPointer<vtkCellArray> LinkCells; ///< a super set's links, as lines
  int Kind = -1; ///< 0 vertices, 1 lines, 2 triangles, 3 one triangle strip per element
  std::size_t Elements = 0;
  std::vector<std::uint8_t> Hidden; ///< per element, placed outside the release window
  /// Per array of the table (by id), then the points' storage last.
  std::array<std::vector<vtkSmartPointer<vtkDataArray>>, std::size_t(bp::OutputArrayId::Count) + 1>
    Kept;
  /// Per array of the table: the last one written with a key, and the key.
  std::array<std::pair<std::uint64_t, vtkSmartPointer<vtkDataArray>>,
    std::size_t(bp::OutputArrayId::Count)>
    Unchanged;
};

/// One point per particle with every array of the table the frame wants,
/// each filled as its row's ArraySource says.
void fillParticleOutput(vtkPolyData* output, const bp::Engine& engine, const bp::VectorField& field,
  const OutputFrame& frame, OutputStorage& storage, const bp::RangeRunner& run);

/// Two points at the corners of `worldBounds` with each array's expected range.
void fillRangeOutput(
  vtkPolyData* output, const bp::RangeFacts& facts, const std::array<double, 6>& worldBounds);

/// Adds a one-value double array to the output's field data.
void addFieldValue(vtkPolyData* output, const char* name, double value);

} // namespace bpvtk

#endif
