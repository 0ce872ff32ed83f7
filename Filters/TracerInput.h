// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerInput.h
 * @brief What the tracer reads from its inputs: a field time step from an
 * image or rectilinear grid, and an element template from a polydata.
 *
 * Each reader returns an empty string on success, otherwise a message that
 * says what the user should fix (the tracer shows it as its error).
 */
#ifndef BoundParticles_TracerInput_h
#define BoundParticles_TracerInput_h

#include "ElementTemplate.h"
#include "VectorField.h"

#include <array>
#include <string>

class vtkDataArray;
class vtkDataObject;
class vtkPolyData;

namespace bpvtk
{

/**
 * Reads `vectors` (the selected array, or null for the first 3-component
 * point array) of `input`, a vtkImageData or vtkRectilinearGrid, into a
 * field time step: its grid (world coordinates, point 0 at `grid.origin`),
 * its velocities, and the data extent it covers. `requested` is the array
 * name the Vectors property asks for: one the input lacks is an error that
 * lists what it has (only without a name does the first vector array serve). Points where the
 * input's vtkValidPointMask is 0 or the vector is not finite are outside the flow's domain
 * (bp::maskOutsidePoints); `nonFinitePoints` counts the latter.
 */
std::string readSlice(vtkDataObject* input, vtkDataArray* vectors, int association,
  bp::GridGeometry& grid, bp::FieldSlice& slice, int extent[6], std::size_t& nonFinitePoints,
  const std::string& requested = std::string());

/// The element template of a polydata (TemplateSprings: `mode`).
std::string templateFromPolyData(vtkPolyData* mesh, bp::MeshSprings mode, bp::ElementTemplate& out);

} // namespace bpvtk

#endif
