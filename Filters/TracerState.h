// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerState.h
 * @brief A trace's saved state (bp::TraceState) as a vtkPolyData: what the
 * tracer's State output holds and its Initial State File reads back.
 *
 * The polydata opens in ParaView as the elements it holds: its points are
 * every particle (world coordinates) and each element is one poly-vertex
 * cell. What the engine resumes from is in its cell data, one array per
 * array of the engine's record (bp::EngineState::layout, named "bp" and the
 * engine's name: bpPositions, bpGenerations, ...), holding the engine's own
 * 32-bit values, and in its field data: bpStateFormat, bpStateVersion, the
 * trace's scalars (bpTime, bpSteps, bpScheduleStart, bpDt, bpTrailTimes,
 * bpTrailNewest, bpEmitterMin, bpEmitterMax), the named values
 * (bpParameterNames / bpParameterValues, bpShape..., bpField...) and
 * bpChecksum (bp::stateChecksum, in hexadecimal). Saved as binary XML
 * (.vtp, or .pvtp from a parallel writer) every bit comes back; an ASCII
 * file may round a value, and its checksum then refuses it.
 */
#ifndef BoundParticles_TracerState_h
#define BoundParticles_TracerState_h

#include "EngineState.h"

#include "vtkSmartPointer.h"

#include <array>
#include <cstdint>
#include <string>

class vtkMultiProcessController;
class vtkPolyData;

namespace bpvtk
{

/// `state` into `out` (emptied first); `offset` places the points in the world.
void writeStatePolyData(
  const bp::TraceState& state, const std::array<double, 3>& offset, vtkPolyData* out);

/// In place of a state, why there is none (readStatePolyData says it).
void writeStateNote(const std::string& why, vtkPolyData* out);

/// The state `data` holds (as writeStatePolyData wrote it); empty on success,
/// otherwise what is missing or wrong, its checksum included.
std::string readStatePolyData(vtkPolyData* data, bp::TraceState& state);

/// The state in the file `path` (.vtp or .pvtp, whole, on every process
/// alike); empty on success, otherwise why not, naming the file.
std::string readStateFile(const std::string& path, bp::TraceState& state);

/**
 * In a distributed trace, every process's elements gathered into process
 * 0's `state` (collective), ids increasing; the other processes' states are
 * emptied of elements. Empty on success.
 */
std::string gatherStateElements(vtkMultiProcessController* controller, bp::EngineState& state);

/// A file's identity, to read it again only when it changed.
struct StateFileStamp
{
  std::string path;
  long long size = -1;
  long long modified = -1; ///< nanoseconds since the epoch

  static StateFileStamp of(const std::string& path);
  bool operator==(const StateFileStamp& o) const
  {
    return path == o.path && size == o.size && modified == o.modified;
  }
};

/// The Initial State File as last read: the state, or why it cannot be read.
struct InitialState
{
  StateFileStamp stamp;
  bp::TraceState state;
  std::string error;

  /// The file at `path`, read again when it changed since the last call.
  void take(const std::string& path);
};

} // namespace bpvtk

#endif
