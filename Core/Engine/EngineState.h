// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file EngineState.h
 * @brief A trace's whole state, as a file keeps it to resume the trace later
 * (the tracer's State output and its Initial State File).
 *
 * What an element is made of is Engine::forEachElementArray's one list: a
 * state holds every element's record (Engine::packElement's words, the
 * migration's) with that list's names, so a file's arrays are named and
 * typed from it. The random streams and the release cursors carry no state
 * of their own: every draw hashes (seed, element, generation, draw), so an
 * element's Generation is its stream's position. Around the elements the
 * state keeps what a resumed trace must take as it was (the step schedule's
 * start and step, the committed time and step count, the trail ring's times,
 * the emitter box) and what it must match to go on bit for bit (the
 * resolved parameters, the template, the field's grid), each a named value
 * so that a mismatch is said by its name. A checksum over all of it refuses
 * a file altered or saved with rounded values (ASCII).
 */
#ifndef BoundParticles_EngineState_h
#define BoundParticles_EngineState_h

#include "ElementTemplate.h"
#include "EngineParameters.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace bp
{

/// The version of the state's layout and of the engine's arithmetic a state
/// was saved by: bumped when either changes, and a state of another version
/// is refused (TestEngineState's golden bits fail on a change left unbumped).
constexpr std::uint32_t EngineStateVersion = 2;

/// One per-element array of the state, in record order.
struct StateArray
{
  enum class Type
  {
    UInt32,
    UInt8,
    Float32
  };
  std::string name;          ///< the Engine's member's name: "Ids", "Positions", ...
  Type type = Type::Float32; ///< each value takes one 32-bit word of a record
  std::size_t components = 0; ///< values per element: width times blocks (never 0)
};

/// The engine's state (Engine::saveState, Engine::loadState).
struct EngineState
{
  /// The arrays of a record (their components add up to recordWords);
  /// arrays of no component (Slips without inertia, trails off) are left out.
  std::vector<StateArray> layout;
  std::size_t recordWords = 0;
  /// Every element's record, ids increasing: elementCount() * recordWords words.
  std::vector<std::uint32_t> records;
  std::vector<double> trailTimes; ///< Engine::trailTimes()
  int trailNewest = -1;           ///< the slot recorded last, -1 before any
  std::array<float, 3> emitterMin = { 0, 0, 0 }; ///< the box releases draw from now
  std::array<float, 3> emitterMax = { 0, 0, 0 };

  std::size_t elementCount() const { return recordWords ? records.size() / recordWords : 0; }
};

/// A setting or fact by name, for the checks that say which one differs.
struct NamedValue
{
  std::string name;
  double value = 0.0;
  /// How far a saved value may lie from this one and still agree (firstDifference):
  /// 0 asks for the same bits; infinity keeps the value for the record only. Not saved.
  double tolerance = 0.0;
  /// A setting added after states were first saved: what a state saved
  /// before it (without the name) stands for, the one value every trace had
  /// then. NaN: the name is required. Not saved.
  double whenAbsent = std::numeric_limits<double>::quiet_NaN();
};

/// A trace's state: the engine's and the trace's around it.
struct TraceState
{
  std::uint32_t version = EngineStateVersion;
  EngineState engine;
  double time = 0.0;          ///< the committed step boundary, in trace time (TimeDirection.h)
  long long steps = 0;        ///< steps from the start to `time`
  double scheduleStart = 0.0; ///< the step schedule's start (StepSchedule), trace time
  double dt = 0.0;            ///< its step
  /// parameterValues() of the resolved parameters the trace ran with.
  std::vector<NamedValue> parameters;
  /// templateValues() of its element template.
  std::vector<NamedValue> shape;
  /// What the tracer knows of its field (the grid, its offset, the largest
  /// speed at the start): filled and compared by the tracer.
  std::vector<NamedValue> field;
};

/**
 * Every member of `p` by its name, in declaration order; arrays give one
 * value per component ("emitterMin[1]"), enumerations their value, and the
 * seed points their count and a 32-bit hash of their bits (two values,
 * exact in double), so that the list stays short whatever their number.
 */
std::vector<NamedValue> parameterValues(const Parameters& p);

/// The template's particle count, spring count, and 32-bit hashes of its rest
/// positions, springs and pinned flags: what a step depends on.
std::vector<NamedValue> templateValues(const ElementTemplate& shape);

/**
 * What a tracer knows of its field, as a state keeps it (fieldStateValues):
 * the whole field's, the same on any number of processes but for the
 * rounding of the bounds.
 */
/// The names of the field's values that the tracer also reads back (a
/// restart in situ: TracerResume.cxx).
namespace FieldStateNames
{
constexpr const char* TimeSteps = "time steps";
constexpr const char* TimeStepsHash = "time steps (hash)";
constexpr const char* LargestStartSpeed = "largest speed at the start";
constexpr const char* TimeDirection = "Time Direction (0 Forward, 1 Backward)";
} // namespace FieldStateNames

struct FieldStateFacts
{
  std::array<int, 3> dims = { 0, 0, 0 }; ///< the whole grid's points along x, y and z
  /// The whole domain in world coordinates: x from, x to, y from, y to, z from, z to.
  std::array<double, 6> bounds = { 0, 0, 0, 0, 0, 0 };
  std::string vectors;            ///< the Vectors array's name
  int vectorsAssociation = 0;     ///< its association (vtkDataObject's FIELD_ASSOCIATION_*)
  std::string releaseWeights;     ///< the Release Weights array's name (empty: none)
  std::vector<double> inputTimes; ///< the input's time steps (the schedule's breaks)
  double startMaxSpeed = 0.0;     ///< the field's largest speed at the start
  int timeDirection = 0;          ///< TimeDirection: 0 forward, 1 backward
  std::array<bool, 3> periodic = { false, false, false }; ///< the grid's periodic axes
  int processes = 1;              ///< the processes tracing (kept, not compared)
};

/**
 * The field's named values a resumed trace must match: the grid's points
 * and bounds, 32-bit hashes of the arrays' names and of the time steps, the
 * largest speed at the start, the time direction, the periodic axes (a
 * state saved before Periodic existed stands for none), and the process count.
 * The bounds agree within a few ulps (pieces compute their corners from
 * their own first points, so another split rounds them differently); the
 * process count is kept for the record, not compared, so a state saved on
 * one number of processes resumes on another.
 */
std::vector<NamedValue> fieldStateValues(const FieldStateFacts& facts);

/**
 * The first value of `now` that differs from `saved` (by bits, NaN equals
 * NaN; or by more than `now`'s tolerance), or that either list lacks, said
 * as "<what> <name>: the state's <value>, this trace's <value>"; empty when
 * they agree.
 */
std::string firstDifference(
  const std::vector<NamedValue>& saved, const std::vector<NamedValue>& now, const std::string& what);

/// A 64-bit checksum (FNV-1a) of everything in `state` but the checksum:
/// the engine's records, scalars and the named values, by their bits.
std::uint64_t stateChecksum(const TraceState& state);

/**
 * What keeps the engine's state `state` from loading into an engine whose
 * stateLayout() is `layout`, configured with `p`: another layout or record
 * size, records that are not whole records, more elements than
 * p.numberOfElements, element ids out of range, repeated or not increasing,
 * a trail ring other than p.trailLength slots, an emitter box that is not
 * finite. Empty when it can (Engine::loadState checks it first).
 */
std::string checkEngineState(
  const EngineState& state, const std::vector<StateArray>& layout, const Parameters& p);

/**
 * What keeps `state` from resuming on an engine configured with `shape` and
 * `p`: another EngineStateVersion, a record layout other than
 * Engine::stateLayout()'s, element ids out of range, repeated or not
 * increasing, a trail ring of another length. Empty when it can. (The named
 * values are the tracer's to compare, by firstDifference.)
 */
std::string checkTraceState(
  const TraceState& state, const ElementTemplate& shape, const Parameters& p);

} // namespace bp

#endif
