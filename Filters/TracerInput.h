// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerInput.h
 * @brief What the tracer reads from its inputs: a field time step from an
 * image or rectilinear grid (any other input is resampled onto an image
 * first, TracerResample.h), and an element template from a polydata.
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
#include <vector>

class vtkDataArray;
class vtkDataObject;
class vtkInformation;
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
 * (bp::maskOutsidePoints); `nonFinitePoints` counts the latter. A vtkValidPointMask that
 * cannot be used (cell data, several components, another length, not numbers) is ignored and
 * `maskProblem` says why; a NaN in it counts as 0.
 */
std::string readSlice(vtkDataObject* input, vtkDataArray* vectors, int association,
  bp::GridGeometry& grid, bp::FieldSlice& slice, int extent[6], std::size_t& nonFinitePoints,
  const std::string& requested = std::string(), std::string* maskProblem = nullptr);

/**
 * What the tracer traces of `input`, for Output Messages, when it offers
 * more than one 3-component array (point or cell; a composite's first block
 * that has some): the array `name` (of `association`) and why (the input's
 * active vectors, named like a velocity, or chosen in Vectors), with the
 * others. `why`, where given, says why in place of those (the Vectors
 * default that preferred an array whose units fit, bp::fittingUnitsReason).
 * Empty where there was no choice to make.
 */
std::string describeVectorsChoice(vtkDataObject* input, const std::string& name, int association,
  const std::string& why = std::string());

/**
 * Where the tracer's input (`inInfo`, its input port's information) comes
 * through ParaView's post filter and the data given to that filter has no
 * point array `name` but a cell array of that name: the post filter then
 * made the point array the tracer reads by interpolating the cell array
 * (vtkPVPostFilter, as Cell Data to Point Data), silently. What to tell the
 * user; empty otherwise.
 */
std::string cellVectorsMadePoints(vtkInformation* inInfo, const std::string& name);

/// Every value of `array` (all components, tuple by tuple) as floats, each
/// times `scale` in double first where it is not 1.
void copyToFloats(vtkDataArray* array, std::vector<float>& out, double scale = 1.0);

/// The largest absolute finite value of `array` (any component), in double;
/// 0 where there is none.
double largestFinite(vtkDataArray* array);

/// The element template of a polydata (TemplateSprings: `mode`).
std::string templateFromPolyData(vtkPolyData* mesh, bp::MeshSprings mode, bp::ElementTemplate& out);

/**
 * The Element Template input's data as a polydata: `data` itself, or null
 * with `error` set when it is another kind of data (a multiblock, an image)
 * that says how to make a polydata of it. Null with no error when there is no
 * data at all (a process given nothing).
 */
vtkPolyData* templateMesh(vtkDataObject* data, std::string& error);

/**
 * Appends the points of `data` (world coordinates, 3 doubles each) to `xyz`:
 * a dataset's, or every dataset's of a composite in traversal order. Nothing
 * for no data. Returns an error for data that has no points to give (a table).
 */
std::string appendSeedPoints(vtkDataObject* data, std::vector<double>& xyz);

} // namespace bpvtk

#endif
