// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerTimeScale.h
 * @brief The field's scale for the automatic time line, probed before the first update.
 *
 * The time values a filter offers are set in RequestInformation, before any
 * data flows; an automatic Duration (or frames per input time step) needs the
 * field's top speed and extent. So the probe updates the input once there
 * (this process's piece, at the first input time step), reads the selected
 * vectors as an update would (a mesh resampled, masks and NaN included), and, under MPI, takes
 * the largest speed and the whole field's extent over every process (a
 * collective call, as every pipeline pass of a distributed run is).
 */
#ifndef BoundParticles_TracerTimeScale_h
#define BoundParticles_TracerTimeScale_h

#include "TraceSettings.h"

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <vector>

class vtkAlgorithmOutput;
class vtkDataArray;
class vtkInformation;

namespace bpvtk
{

/**
 * The filter's reading of the delivered data: sets `grid` to the grid it
 * traces (the data itself, or the mesh resampled, which `grid` keeps alive)
 * and returns its vectors (and their association). Called on every process,
 * as resampling is collective.
 */
using GridOf = std::function<vtkDataArray*(
  vtkDataObject* data, vtkSmartPointer<vtkDataObject>& grid, int& association)>;

/// The scale of the field `input` (the filter's input connection, `inInfo`
/// its information) delivers; invalid (bp::TimeScale::valid()) when it cannot
/// be read or does not move.
bp::TimeScale probeTimeScale(vtkAlgorithmOutput* input, vtkInformation* inInfo,
  const std::vector<double>& inputTimes, const GridOf& gridOf);

} // namespace bpvtk

#endif
