// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file EngineParameters.h
 * @brief What a system of bound particles is configured with (Parameters;
 * the choices it takes are in BoundParticlesChoices.h), its limits and the
 * reset-flag bits, and the two per-step decisions both engines take from the
 * parameters alone (recordsTrailAt, releasesAt). The engine itself is in
 * Engine.h.
 */
#ifndef BoundParticles_EngineParameters_h
#define BoundParticles_EngineParameters_h

#include "BoundParticlesChoices.h"
#include "ReleaseLattice.h"
#include "SuperSet.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace bp
{

class SurfaceSet;

/// The most particles a system may hold (about 2 GiB of state and output).
constexpr std::size_t MaxParticles = std::size_t(1) << 26;

/// The most seed points a system releases from (Parameters::seedPoints): a
/// release's index is taken modulo their count in 32-bit arithmetic on the GPU.
constexpr std::size_t MaxSeedPoints = 65536;

/// Engine::resetFlags(): bit 0, due for reset (the reposition test); bit 1,
/// placed outside the release window: hidden (not drawn, no cells in the
/// output) and due again at every step.
constexpr std::uint8_t ResetDue = 1;
constexpr std::uint8_t ReleaseHidden = 2;
/// Bit 2: placed Along Flow without a field to sample (Engine::resetDue of a
/// distributed step, whose new centre may lie in another piece); turned onto
/// the flow by the piece that holds it, before it is advected.
constexpr std::uint8_t AlignPending = 4;
/// Bit 3: left the field with Boundary::Terminate: hidden, and not due
/// until its lifetime runs out (Engine::isDue), when it is placed again.
constexpr std::uint8_t Terminated = 8;
/// The bits of an element that is not shown (no cells, no trail, no FTLE).
constexpr std::uint8_t HiddenFlags = ReleaseHidden | Terminated;

/// How many candidate centres a release draws before it takes the last one
/// (Engine::place): with 95% of the box unfit, 96% of releases still land fit.
constexpr int ReleaseTries = 64;
/// The draws of a release, by number (counterHash's fourth counter; the GPU
/// kernels get them as generated #defines): the first candidate centre's
/// coordinates are draws 0-2, a random orientation's draws 3-5
/// (OrientationDraw on), the lifetime's draw 6, the further candidates'
/// coordinates from draw 8 (candidateDraw).
constexpr std::uint32_t OrientationDraw = 3;
constexpr std::uint32_t LifetimeDraw = 6;
constexpr std::uint32_t FurtherCandidateDraw = 8;
/// The draw of a release's k-th candidate centre's first coordinate (then
/// the next two).
constexpr std::uint32_t candidateDraw(int k)
{
  return k == 0 ? 0u : std::uint32_t(FurtherCandidateDraw + 3 * (k - 1));
}

struct Parameters
{
  std::size_t numberOfElements = 1000;
  float elementSize = 1.0f; ///< bounding-sphere diameter in world units
  std::array<float, 3> emitterMin = { 0, 0, 0 };
  std::array<float, 3> emitterMax = { 1, 1, 1 };
  Orientation orientation = Orientation::Random;
  std::array<float, 9> frame = {
    1, 0, 0, 0, 1, 0, 0, 0, 1
  }; ///< row-major: the Fixed orientation, Along Flow's start (and the plane's, under planeAxis)
  /// With Random or Along Flow on a flat field (one axis of one point): that
  /// axis. Elements then turn about it only, after `frame` lays the
  /// template's x-y plane into the field's plane; -1: any rotation.
  int planeAxis = -1;
  float lifetimeMin = 1.0f;
  float lifetimeMax = 2.0f;
  Integrator integrator = Integrator::Euler;
  Restoration restoration = Restoration::AveragedJacobi;
  int iterations = 1;
  /// Plain Jacobi's step factor on the summed corrections; stable for the
  /// built-in shapes (up to 10 springs per particle) below about 0.3.
  float relaxation = 0.2f;
  /// Shape matching: how far each iteration moves particles to their goals, in [0, 1].
  float shapeStiffness = 1.0f;
  /// Shape matching's linear mode (Müller et al. 2005, §4.3): goals from
  /// beta * A + (1 - beta) * R, A the best linear (affine) fit and R its
  /// rotation, so elements may also shear and stretch, by up to beta.
  bool linearShapeMatching = false;
  float linearBlend = 0.5f; ///< beta, in [0, 1]
  /// Super sets (Core/Elements/SuperSet.h): springs between neighbouring elements.
  /// Linked elements are released together at their lattice sites, with one
  /// orientation and one lifetime, and are not reset when they leave the field
  /// (that would tear the structure): the structure lives out its lifetime.
  Linking linking = Linking::None;
  int latticeWidth = 0;       ///< W of a sheet, tube or torus; 0 for near square
  float linkStiffness = 1.0f; ///< in [0, 1], of every link
  ResetWhen resetWhen = ResetWhen::CenterLeaves;
  /// What an element that leaves the field (by resetWhen) does: released
  /// again (ResetDue), or terminated (Terminated) until its lifetime ends;
  /// or the field's boundary is a wall that keeps it in (Stick, Slip,
  /// Bounce: Walls.h).
  Boundary boundary = Boundary::ReleaseAgain;
  /// Bounce's coefficient of restitution e, in [0, 1]: a particle's step
  /// beyond the wall comes back e times as far, a heavy particle's normal
  /// velocity leaves at e times its speed. 1 (the default) is a mirror.
  float restitution = 1.0f;
  /// The Surfaces input's gates and outlets (Surfaces.h, engine
  /// specification 2.10), in engine coordinates; null for none. Shared by
  /// every copy of the parameters (it never changes once made).
  std::shared_ptr<const SurfaceSet> surfaces;
  ReleasePattern releasePattern = ReleasePattern::Random;
  /// The lattice of ReleasePattern::Lattice, over the emitter box
  /// (resolveSettings makes numberOfElements its size()).
  ReleaseLattice lattice;
  Anchor anchor = Anchor::None;
  /// Heavy particles (Core/Engine/Inertia.h): with Inertia::MaxeyRiley and a
  /// response time tau > 0 each particle keeps its slip velocity (its
  /// velocity less the flow's) and drifts from the flow by it.
  Inertia inertia = Inertia::None;
  float responseTime = 0.0f;                  ///< tau, the Stokes response time, in time units
  float densityRatio = 1.0f;                  ///< the particle's density over the fluid's, > 0
  std::array<float, 3> gravity = { 0, 0, 0 }; ///< in world units per time unit squared
  /// Release centres, 3 floats per point (at most MaxSeedPoints): release r
  /// = generation * numberOfElements + id of an element is at point r modulo
  /// their count, so releases take the points in order, cycling. Empty: the
  /// emitter box.
  std::vector<float> seedPoints;
  /// The release window: an element is released (placed and shown) only in
  /// a step that overlaps [releaseStart, releaseStop] (releasesAt). One due
  /// outside it is placed hidden (ReleaseHidden) and is due again at every
  /// step, so the window's first step releases it.
  double releaseStart = -std::numeric_limits<double>::infinity();
  double releaseStop = std::numeric_limits<double>::infinity();
  /// An element whose centre moves slower than this over its first step
  /// (in world units per time unit) was released where the flow stands
  /// still, and is released again at the next step; 0 keeps every release.
  float releaseMinSpeed = 0.0f;
  std::uint32_t seed = 0;
  /// Fit every element's pose and spin at the end of every step (Pose.h;
  /// Engine::poses(), spins()). Off, they stay as placed (spin 0): the fit
  /// costs the CPU engine about a quarter of a Strip16 step, so it runs only
  /// for an output that shows them. Nothing else depends on it.
  bool trackPoses = false;
  /// Motion trails: each element's last trailLength poses (0: none), one
  /// recorded at the start of every step that starts on trailStart + k *
  /// trailInterval (recordsTrailAt), so a trail's poses are a fixed number
  /// of steps apart and strictly older than the state shown.
  int trailLength = 0;
  double trailStart = 0.0;
  double trailInterval = 0.0;
  /// The age an element needs for an FTLE (ElementFTLE, the FTLE map; time
  /// units): bp::MinimumFtleSteps of the trace's largest step. Neither
  /// engine's step reads it.
  double ftleMinimumAge = 0.0;
};

/// The most poses a trail keeps (Parameters::trailLength).
constexpr int MaxTrailLength = 64;
/// The most steps between two trail poses: recordsTrailAt() matches a step
/// within 1e-6 of an interval, which must stay well below one step.
constexpr int MaxTrailSpacing = 1000;
/// Trail generation of a slot that holds no pose of the element
/// (Engine::trailGenerations()).
constexpr std::uint32_t NoTrailPose = 0xffffffffu;

/// A setting given in double as the engine's float: beyond float's range it
/// is +-infinity, which validate() refuses by name, where a plain float(v)
/// would be undefined behaviour (NaN stays NaN). Below float's smallest
/// (1.4e-45) a value that is not 0 keeps its sign and stays non-zero, as the
/// smallest float of that sign: -1e-300 is refused as negative where a
/// plain float(v) would give -0, and 1e-300 is a response time, not none.
inline float settingAsFloat(double v)
{
  constexpr double Largest = std::numeric_limits<float>::max();
  constexpr float Infinity = std::numeric_limits<float>::infinity();
  constexpr float Smallest = std::numeric_limits<float>::denorm_min();
  if (std::abs(v) > Largest)
  {
    return v > 0 ? Infinity : -Infinity;
  }
  const float f = float(v);
  if (f == 0.0f && v != 0.0)
  {
    return v > 0 ? Smallest : -Smallest;
  }
  return f;
}

/// Whether a step starting at `t` records a trail pose first: t is within
/// 1e-6 of an interval of trailStart + k * trailInterval, k >= 0.
inline bool recordsTrailAt(const Parameters& p, double t)
{
  if (p.trailLength <= 0 || !(p.trailInterval > 0.0) || t < p.trailStart - 1e-6 * p.trailInterval)
  {
    return false;
  }
  const double k = std::round((t - p.trailStart) / p.trailInterval);
  return std::abs(t - (p.trailStart + k * p.trailInterval)) <= 1e-6 * p.trailInterval;
}

/// Whether the step [t, t + h) releases elements: it overlaps the release
/// window (so a window of one instant releases in the one step that holds
/// it); the initialisation (h = 0) releases when t is in the window. Both
/// engines decide it so, once per step.
inline bool releasesAt(const Parameters& p, double t, double h)
{
  return h > 0.0 ? t <= p.releaseStop && t + h > p.releaseStart
                 : p.releaseStart <= t && t <= p.releaseStop;
}

} // namespace bp

#endif
