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

#include "Engine.h"
#include "OutputArrays.h"
#include "Parallel.h"
#include "VectorField.h"

#include "vtkSmartPointer.h"

#include <array>
#include <cstddef>

class vtkCellArray;
class vtkPolyData;

namespace bpvtk
{

/// Where the particles are shown: what turns engine state into output.
struct OutputFrame
{
  double time = 0.0;                                   ///< the simulation time shown
  std::array<double, 3> offset = { 0, 0, 0 };          ///< world position of the grid-local origin
  std::array<double, 6> domain = { 0, 1, 0, 1, 0, 1 }; ///< the whole field, grid-local
  double reach = 0.0;      ///< the largest world |coordinate| in the field
  double cellLength = 1.0; ///< of the local grid (for the points' precision)
  int coloringAxis = 2;    ///< for Layer and Radius
  bool computeVorticity = true;

  /// Whether the output carries `row`: every row but the optional ones not asked for.
  bool wants(const bp::OutputArray& row) const;
};

/// The output's cells, kept while the element count and shape stay.
class ParticleCells
{
public:
  /// Sets `output`'s cells for `engine`'s elements, built again only when
  /// the element count changed (or after reset()).
  void apply(vtkPolyData* output, const bp::Engine& engine);
  /// Forgets the cells (the shape may have changed).
  void reset() { this->Cells = nullptr; }

private:
  vtkSmartPointer<vtkCellArray> Cells;
  vtkSmartPointer<vtkCellArray> LinkCells; ///< a super set's links, as lines
  int Kind = -1;                           ///< 0 vertices, 1 lines, 2 triangles
  std::size_t Elements = 0;
};

/// One point per particle with every array of the table the frame wants,
/// each filled as its row's ArraySource says.
void fillParticleOutput(vtkPolyData* output, const bp::Engine& engine, const bp::VectorField& field,
  const OutputFrame& frame, ParticleCells& cells, const bp::RangeRunner& run);

/// Two points at the corners of `worldBounds` with each array's expected range.
void fillRangeOutput(
  vtkPolyData* output, const bp::RangeFacts& facts, const std::array<double, 6>& worldBounds);

/// Adds a one-value double array to the output's field data.
void addFieldValue(vtkPolyData* output, const char* name, double value);

} // namespace bpvtk

#endif
