// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TraceSettings.h
 * @brief What the user set on the tracer, and how automatic settings resolve
 * into the engine's Parameters.
 *
 * The tracer copies its properties into TraceSettings (world units, 0 or a
 * negative size meaning "automatic"); resolveSettings() turns them, with the
 * facts of the field at the start time, into bp::Parameters in the engine's
 * grid-local coordinates: the time step from a step in cell lengths, the
 * element size from the grid, the emitter box from the field's bounds, the
 * lifetimes from the animation's span. No VTK here, so every rule is tested
 * alone (Testing/Core/TestTraceSettings.cpp).
 */
#ifndef BoundParticles_TraceSettings_h
#define BoundParticles_TraceSettings_h

#include "Engine.h"
#include "TimeDirection.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace bp
{

/// A set LatticeSpacing whose lattice has this many times Number Of
/// Elements or more is warned of (it decides the count, and so the memory).
constexpr std::size_t LatticeOverrunWarning = 100;

/// Heavy particles that gravity alone carries this many times the field's
/// longest side over their longest lifetime are warned of: Gravity is then
/// likely not in the data's length per time squared (9.81 m/s^2 given as
/// 1.27e5 km/h^2 on carotid.vti: 560 times). With automatic lifetimes the
/// ratio is about the settling speed over the top flow speed, which rain in
/// a room's air (5 m/s against 0.65 m/s) keeps near 10.
constexpr double GravityWarningFields = 100.0;

/// The engine settings a new tracer starts with: the panel's defaults
/// (Plugin/BoundParticles.xml; PropertyDefaults.EveryPropertyOfEveryProxyHasOneVerdict
/// holds them together). Parameters keeps engine-neutral ones: a random
/// orientation, which needs no field, and massless particles.
inline Parameters propertyDefaults()
{
  Parameters p;
  p.orientation = Orientation::AlongFlow;
  p.responseTime = 0.1f;
  p.densityRatio = 1000.0f;
  return p;
}

struct TraceSettings
{
  long long numberOfElements = 1000;
  double elementSize = 0.0;                           ///< world units; 0: automatic
  std::array<double, 3> emitterCenter = { 0, 0, 0 };  ///< world coordinates
  std::array<double, 3> emitterSize = { -1, -1, -1 }; ///< negative: the field's extent on that axis
  std::array<double, 3> rotationDegrees = { 0, 0, 0 }; ///< about X, then Y, then Z
  std::array<double, 2> lifetimeRange = { 0, 0 };      ///< (0, 0): automatic
  double stepSize = 0.5;
  bool stepInCellLengths = true; ///< else stepSize is in the data's time units
  /// Releases slower than this fraction of the top speed are released again
  /// (Parameters::releaseMinSpeed).
  double minimumReleaseSpeed = 0.01;
  /// Motion trails: poses kept per element (0: none), and steps between two.
  int trailLength = 0;
  int trailSpacing = 4;
  /// Releases take a Seed Source's points: the emitter box and the minimum
  /// release speed are not used, so neither is checked.
  bool seeded = false;
  /// Release Pattern = Lattice (engine.releasePattern): the lattice's
  /// spacing in world units; 0: from numberOfElements and the emitter box.
  double latticeSpacing = 0.0;
  /// Release Weights is set (the warnings where it is not used).
  bool weighted = false;
  /// Which way the trace runs (TimeDirection.h); Backward takes massless
  /// elements only (checkTimeDirection).
  TimeDirection timeDirection = TimeDirection::Forward;
  /// The settings the engine takes as they are (integrator, restoration,
  /// shape matching, linking, reset condition, seed, random orientation);
  /// resolveSettings() fills in the rest of it. It starts at the panel's
  /// defaults (propertyDefaults()).
  Parameters engine = propertyDefaults();
};

/// What the automatic settings depend on, in grid-local coordinates.
struct FieldFacts
{
  std::array<double, 6> bounds = { 0, 1, 0, 1, 0, 1 }; ///< the whole field's
  std::array<double, 3> offset = { 0, 0, 0 };          ///< world position of the local origin
  std::array<int, 3> dims = { 2, 2, 2 };               ///< points per axis (1: a flat axis)
  double cellLength = 1.0;                             ///< mean cell length
  double maxSpeed = 1.0;                               ///< the field's largest speed at the start
  double timeSpan = 0.0;                               ///< the offered time range's length
};

/// How gravity moves heavy particles across the field in still fluid
/// (Inertia.h's settling, with Gravity in the plane of a flat field): the
/// time it takes to carry a particle from rest across the field's longest
/// side, and the speed it has then (the terminal settling speed where that
/// takes longer than the response time, free fall's sqrt(2 a length) where
/// it is far shorter). Both 0 where gravity moves nothing.
struct GravityMotion
{
  double time = 0.0;
  double speed = 0.0;
};
GravityMotion gravityMotion(const Parameters& engine, const FieldFacts& field);

/// A flow this many times slower than gravity's motion is still fluid for
/// heavy particles (float's resolution: next to the settling the flow is
/// rounding noise): their settling is what the trace is about, and no
/// warning calls Gravity out of the data's units.
constexpr double StillFlowRatio = 1.0 / 1.1920928955078125e-07;

struct Resolution
{
  Parameters parameters;
  double dt = 0.0;          ///< the largest step, in time units
  /// The top speed the automatic step and lifetimes follow: the flow's, or
  /// gravity's motion of heavy particles (GravityMotion) where it is faster;
  /// 0 where nothing moves (the step is then taken at a speed of 1).
  double speed = 0.0;
  double elementSize = 0.0; ///< world units
  std::vector<std::string> warnings;
  std::string error; ///< non-empty: what the user should fix (nothing else is set)
};

/// Resolves `settings` against `field`: the engine's parameters, or an error.
Resolution resolveSettings(const TraceSettings& settings, const FieldFacts& field);

/// Where releases land in a field whose grid changed during a trace (in
/// situ), in the engine's grid-local coordinates.
struct EmitterBox
{
  std::array<float, 3> min = { 0, 0, 0 };
  std::array<float, 3> max = { 0, 0, 0 };
  std::string warning; ///< the box misses the new field along an axis
};

/**
 * In situ, after the grid changed to `field` (its bounds in the engine's
 * frame, which stays the trace's: `field.offset` is the one the trace
 * started with): the emitter box of `settings` resolved against the new
 * field as at the start (an axis of negative size spans it, Any Particle
 * Leaves keeps an element radius of `elementSize` inside), then cut to the
 * new field's bounds, so no release lands outside the new grid (it would be
 * released again at every step). Where the box misses the new field along
 * an axis, releases span the field along it and `warning` says so. A flat
 * axis (one point) is left as resolved.
 */
EmitterBox emitterInChangedField(
  const TraceSettings& settings, const FieldFacts& field, double elementSize);

/// The field's scale as the time line needs it, probed before the first
/// update (the filter's RequestInformation); valid only with a top speed > 0.
struct TimeScale
{
  double maxSpeed = 0.0;     ///< the largest speed of the time step probed
  double typicalSpeed = 0.0; ///< VectorField::typicalSpeed of it (0: not known)
  double extent = 0.0;       ///< the field's longest side (over axes with cells)
  double cellLength = 0.0;   ///< the mean cell length, as FieldFacts::cellLength
  /// Heavy particles: gravity's motion across the field (GravityMotion::speed);
  /// the time line follows it where it is faster than the flow. 0 without.
  double gravitySpeed = 0.0;
  /// The top speed the time line follows: the flow's or gravity's.
  double speed() const { return maxSpeed > gravitySpeed ? maxSpeed : gravitySpeed; }
  bool valid() const { return speed() > 0.0 && extent > 0.0 && cellLength > 0.0; }
};

/// The time line the tracer offers the animation.
struct TimeLine
{
  double duration = 0.0;             ///< a steady input's time range [0, duration]
  int framesPerInterval = 1;         ///< an unsteady input's frames per input time step
  std::vector<std::string> warnings; ///< velocity scale and grid units that look mismatched
};

/// Automatic time line: a steady input lasts as long as the fastest flow takes
/// to cross the field AutomaticCrossings times, but (with the step in cell
/// lengths) no longer than frames of FrameSteps steps each; an unsteady input
/// gets as many frames per input time step as keep a frame within FrameSteps
/// steps, and at least MinAutomaticFrames frames in all (as many as a steady
/// input's default), so a short series still plays smoothly.
constexpr double AutomaticCrossings = 5.0;
/// An unsteady field whose typical speed carries an element across this
/// share of the field, and across UnitsWarningCells cells, between two input
/// time steps is warned of: data is written often enough to follow its flow,
/// so such a speed is a units mismatch (gfs_wind10m's m/s on a degree grid
/// with time in hours: 19%, 68 cells; in degrees per hour: 1.3%, 4.5 cells).
/// The share alone does not tell: the plugin's double gyre, whose pattern
/// changes slowly (period 10, written every 0.5), crosses 13% of its coarse
/// default grid, but only 4 cells, between two steps.
constexpr double UnitsWarningShare = 0.1;
constexpr double UnitsWarningCells = 20.0;
constexpr double FrameSteps = 10.0;
/// A steady input's Duration when the field cannot be probed (or is still).
constexpr double FallbackDuration = 10.0;
constexpr int MinAutomaticFrames = 101;
/// The most frames per input time step the automatic time line offers.
constexpr int MaxFramesPerInterval = 1000;

/**
 * The time line for `settings` (duration <= 0 and framesPerInterval <= 0 are
 * automatic) given the field's `scale` and the input's time steps (fewer than
 * two: a steady input offered `count` times).
 */
TimeLine resolveTimeLine(double duration, int framesPerInterval, int count, double stepSize,
  bool stepInCellLengths, const std::vector<double>& inputTimes, const TimeScale& scale);

} // namespace bp

#endif
