// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerFieldProbe.h
 * @brief The field's facts before the first update: its scale for the
 * automatic time line, and its geometry for the FTLE map's extent.
 *
 * The time values a filter offers, and the extent of an image output, are set
 * in RequestInformation, before any data flows. An automatic Duration (or
 * frames per input time step) needs the field's top speed and extent; the
 * FTLE map's extent is the release lattice's, which needs the field's bounds
 * (an emitter box spanning the field) and its flat axes. So the probe
 * updates the input once there (this process's piece, at the first input
 * time step: DeliveredInput), reads the selected vectors as an update would
 * (a mesh resampled, masks and NaN included: probeDelivered), and, under
 * MPI, takes the largest speed and the whole field's bounds over every
 * process (a collective call, as every pipeline pass of a distributed run
 * is). The input's output is shared with its other consumers: where it held
 * another time step for them, it is updated at that time again after the
 * probe, so that none finds it at a time it did not ask for.
 */
#ifndef BoundParticles_TracerFieldProbe_h
#define BoundParticles_TracerFieldProbe_h

#include "TraceSettings.h"

#include "vtkDataObject.h"
#include "vtkInformation.h" // for vtkSmartPointer<vtkInformation>
#include "vtkSmartPointer.h"

#include <functional>
#include <vector>

class vtkAlgorithmOutput;
class vtkDataArray;

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

/// What the probe found.
struct FieldProbe
{
  bool read = false; ///< the field could be read (facts and scale are set)
  /// Its scale; invalid (bp::TimeScale::valid()) where it does not move.
  bp::TimeScale scale;
  /// Its facts as a replay resolves settings against them (the whole field's
  /// bounds, grid-local; its first point; points per axis; the mean cell
  /// length; the top speed of the time step probed).
  bp::FieldFacts facts;
};

/**
 * The input (`connection`, `inInfo` its information: the producer's output
 * information, shared by its consumers) updated whole for this process's
 * piece, no ghosts, at its first time step, while this lives. On
 * destruction the consumers' last request is put back, and where the input
 * held data of another time step for them (a downstream filter or a display
 * at the view's time) that it still offers, the input is updated at that
 * time again: its output
 * is updated in place, and a consumer that reads it without asking again (a
 * downstream filter's output, a Fetch) would otherwise get the probe's time
 * step. Collective under MPI, as every pipeline pass of a distributed run.
 */
class DeliveredInput
{
public:
  DeliveredInput(
    vtkAlgorithmOutput* connection, vtkInformation* inInfo, const std::vector<double>& inputTimes);
  ~DeliveredInput();
  DeliveredInput(const DeliveredInput&) = delete;
  DeliveredInput& operator=(const DeliveredInput&) = delete;
  /// The data delivered (null without a producer); valid while this lives.
  vtkDataObject* data() const { return this->Data; }

private:
  vtkAlgorithmOutput* Connection = nullptr;
  vtkInformation* Info = nullptr;
  vtkDataObject* Data = nullptr;
  /// The consumers' request before the probe's (its UPDATE_ keys).
  vtkSmartPointer<vtkInformation> Request;
  /// Whether the input held data for its consumers at a time it still
  /// offers (`HeldTime` within its time steps' range): the only data worth
  /// updating again. A source that moved on (in situ, a producer holding
  /// this step alone) cannot give the earlier time back.
  bool HeldOffered = false;
  double HeldTime = 0.0;
};

/// Probes the field the input delivered (`data`, DeliveredInput's; `inInfo`
/// its information): no update. Collective under MPI.
FieldProbe probeDelivered(vtkDataObject* data, vtkInformation* inInfo,
  const std::vector<double>& inputTimes, const GridOf& gridOf);

} // namespace bpvtk

#endif
