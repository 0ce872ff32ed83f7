// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Engine.h
 * @brief The CPU engine: one step of a system of bound particles, as
 * docs/engine-specification.md specifies it for both engines.
 *
 * A step of size h at time t does, for every element independently:
 *  1. reset, when the element was flagged by the previous step or its lifetime
 *     ran out: a new centre uniform in the emitter box, a uniform random
 *     rotation (or the user's frame), the scaled template, a lifetime uniform
 *     in [min, max]; every draw comes from counterHash(seed, element,
 *     generation, draw), draws 0-2 the centre, 3-5 the rotation, 6 the lifetime;
 *  2. advection of every particle (Euler, RK2 midpoint or classic RK4);
 *  3. restoration, K iterations of averaged Jacobi (thesis §3.5), Jacobi with
 *     relaxation, or Gauss-Seidel; the per-particle "force" is the length of
 *     the particle's total restoration displacement in this step;
 *  4. normals (computed on demand by updateNormals(): they do not feed back
 *     into the simulation, so computing them only for output is the same);
 *  5. the reposition test: flag the element when its centre (or, as an option,
 *     any particle) left the field or entered a cell outside the flow's
 *     domain (DomainMask.h), when in its first step its centre moved slower
 *     than releaseMinSpeed (released where the flow stands still), or when a
 *     position became non-finite (then the element keeps its positions from
 *     before the step, so no NaN is ever visible); decrease the lifetime by h;
 *  6. with Parameters::trackPoses, the pose: the best rigid fit of the
 *     particles, warm-started from the pose before, and the spin, the turn
 *     from one to the other over h (Pose.h).
 *
 * Elements touch disjoint memory, so a step runs over element ranges in
 * parallel and gives the same bits for any number of threads.
 */
#ifndef BoundParticles_Engine_h
#define BoundParticles_Engine_h

#include "ElementNormals.h"
#include "ElementTemplate.h"
#include "Parallel.h"
#include "SuperSet.h"
#include "VectorField.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace bp
{

enum class Integrator
{
  Euler = 0,
  RK2,
  RK4
};

enum class Restoration
{
  AveragedJacobi = 0,
  Jacobi,
  GaussSeidel,
  ShapeMatching ///< best rigid fit (Core/ShapeMatching.h), goals blended by shapeStiffness
};

/// How an element is turned when it is placed (Engine::place).
enum class Orientation
{
  Fixed = 0, ///< by Parameters::frame (Element Rotation)
  Random,    ///< a uniform random rotation (about the plane's axis on a flat field)
  AlongFlow  ///< the frame's x axis turned onto the flow at the release centre
};

enum class ResetWhen
{
  CenterLeaves = 0,
  AnyParticleLeaves
};

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

/// How many candidate centres a release draws before it takes the last one
/// (Engine::place): with 95% of the box unfit, 96% of releases still land fit.
constexpr int ReleaseTries = 64;
/// The draw of a release's k-th candidate centre's first coordinate (then
/// the next two): 0 for the first, after the orientation and lifetime draws
/// (3-6) for the others.
constexpr std::uint32_t candidateDraw(int k)
{
  return k == 0 ? 0u : std::uint32_t(8 + 3 * (k - 1));
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
  /// Super sets (Core/SuperSet.h): springs between neighbouring elements.
  /// Linked elements are released together at their lattice sites, with one
  /// orientation and one lifetime, and are not reset when they leave the field
  /// (that would tear the structure): the structure lives out its lifetime.
  Linking linking = Linking::None;
  int latticeWidth = 0;       ///< W of a sheet, tube or torus; 0 for near square
  float linkStiffness = 1.0f; ///< in [0, 1], of every link
  ResetWhen resetWhen = ResetWhen::CenterLeaves;
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
};

/// The most poses a trail keeps (Parameters::trailLength).
constexpr int MaxTrailLength = 64;
/// The most steps between two trail poses: recordsTrailAt() matches a step
/// within 1e-6 of an interval, which must stay well below one step.
constexpr int MaxTrailSpacing = 1000;
/// Trail generation of a slot that holds no pose of the element
/// (Engine::trailGenerations()).
constexpr std::uint32_t NoTrailPose = 0xffffffffu;

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

/**
 * The largest Jacobi relaxation factor that is stable for `shape`: Jacobi
 * moves particle i by factor * sum over its springs of share * stiffness *
 * stretch, and the iteration of the linearised springs stays bounded while
 * factor * max_i sum_i(share * stiffness) <= 1 (Gershgorin). 0.2 for ten
 * springs per particle; infinity for a template with no springs.
 */
float stableRelaxation(const ElementTemplate& shape);

/// Row-major rotation R = Rz * Ry * Rx from angles in degrees about X, then Y, then Z.
std::array<float, 9> rotationFromDegrees(double x, double y, double z);

/// Shoemake's uniform random rotation from three uniforms in [0, 1), as the
/// unit quaternion (x, y, z, w) and as a row-major matrix.
std::array<float, 4> quaternionFromUniforms(float u1, float u2, float u3);
std::array<float, 9> rotationFromUniforms(float u1, float u2, float u3);

/// The unit quaternion (x, y, z, w) of a row-major rotation matrix.
std::array<float, 4> quaternionFromRotation(const std::array<float, 9>& R);

/// The rotation by 2 pi u about axis `axis` (0-2) after the rotation `first`,
/// as a unit quaternion: an in-plane orientation (Parameters::planeAxis).
std::array<float, 4> inPlaneQuaternion(int axis, float u, const std::array<float, 4>& first);

/// The product r * q of unit quaternions (x, y, z, w): q, then r.
std::array<float, 4> multiplyQuaternions(const float r[4], const std::array<float, 4>& q);

/**
 * Along Flow's orientation for a flow `v` at the release centre: the shortest
 * turn of the frame's x axis (the template's long axis) onto v, after the
 * frame (row-major `frame`, as the quaternion `first`). On a flat field
 * (`planeAxis` >= 0) v's component along that axis is dropped, so the turn is
 * about it. Opposite directions turn by a half turn about the frame's z axis;
 * a zero or non-finite v keeps `first`.
 */
std::array<float, 4> alongFlowQuaternion(const float v[3], int planeAxis,
  const std::array<float, 9>& frame, const std::array<float, 4>& first);

/**
 * Linear shape matching's (sum q q^T)^-1 over the template's rest positions q
 * scaled by `size`, row-major; a pseudo-inverse, so that flat and line-like
 * templates (whose moment has rank 2 or 1) fit within their own span.
 */
std::array<float, 9> restMomentInverse(const ElementTemplate& shape, float size);

class Engine
{
public:
  /// Checks the template and parameters and sizes the system; empty on success.
  std::string configure(const ElementTemplate& shape, const Parameters& parameters);

  /// The checks configure() makes, without allocating anything.
  static std::string validate(const ElementTemplate& shape, const Parameters& parameters);

  /// Places every element (generation 0) and computes its normals; at
  /// `startTime` (the release window's test, and the flow Along Flow
  /// samples in `field`, when given).
  void initialize(
    const RangeRunner& run, double startTime = 0.0, const VectorField* field = nullptr);

  /// Whether the step [t, t + h) releases elements (bp::releasesAt).
  bool releasesAt(double t, double h) const { return bp::releasesAt(this->Params, t, h); }

  /**
   * Where releases may land: `unfit` (releaseUnfitCells(), DomainMask.h) per
   * cell of `grid`, the whole field's grid in engine coordinates. A release
   * draws up to ReleaseTries candidate centres and takes the first inside the
   * grid's bounds in a fit cell (or else the last); null `unfit`: the first
   * candidate. Seed points that do not fit (outside the bounds or, with a
   * mask, in an unfit cell) give way to the next ones in turn.
   */
  void setReleaseMask(
    const GridGeometry& grid, std::shared_ptr<const std::vector<std::uint8_t>> unfit);

  /// One step of size h from time t (h > 0).
  void step(const VectorField& field, double t, double h, const RangeRunner& run);

  /// Recomputes the per-particle normals from the positions.
  void updateNormals(const RangeRunner& run);

  /// The elements this engine holds: all of them, or a piece's share in a
  /// distributed run (Core/Partition.h).
  std::size_t elementCount() const { return this->Ids.size(); }
  std::size_t particlesPerElement() const { return this->Shape.particleCount(); }
  std::size_t particleCount() const { return this->elementCount() * this->particlesPerElement(); }
  const ElementTemplate& shape() const { return this->Shape; }
  const Parameters& parameters() const { return this->Params; }

  /// Element-major: particle i of element e is at 3 * (e * n + i).
  const std::vector<float>& positions() const { return this->Positions; }
  const std::vector<float>& normals() const { return this->Normals; }
  const std::vector<float>& forces() const { return this->Forces; }
  const std::vector<float>& lifetimes() const { return this->Lifetimes; }
  const std::vector<std::uint32_t>& generations() const { return this->Generations; }
  /// The centre each element was last placed at: 3 floats per element.
  const std::vector<float>& initialCenters() const { return this->InitialCenters; }
  /// Each element's orientation (x, y, z, w) as placed, kept up to date by
  /// shape matching (the warm start of its fit).
  const std::vector<float>& orientations() const { return this->Orientations; }
  /// Each element's pose (x, y, z, w): its rotation from the template by the
  /// best rigid fit of its particles at the end of the last step (Pose.h),
  /// for every restoration method; the identity for one-particle elements.
  const std::vector<float>& poses() const { return this->Poses; }
  /// Each element's spin over the last step, 4 floats: the angular velocity
  /// (radians per time unit, world axes) and the SpinVorticityRatio reading
  /// against the field at its centre at the step's end (Pose.h); 0 when
  /// placed, for one particle, and for a step whose positions turned non-finite.
  const std::vector<float>& spins() const { return this->Spins; }
  /// Elements flagged for reset at the next step.
  const std::vector<std::uint8_t>& resetFlags() const { return this->ResetFlags; }
  /// @name Motion trails (Parameters::trailLength slots, a ring)
  /// Slot s holds every element's positions (element-major, as positions())
  /// at trailTimes()[s], and each element's generation then (NoTrailPose:
  /// none); a slot's pose belongs to an element's trail while its generation
  /// is the element's own. Slots from newest to oldest: trailSlot(0), ...
  ///@{
  const std::vector<float>& trailPositions() const { return this->TrailPositions; }
  const std::vector<std::uint32_t>& trailGenerations() const { return this->TrailGenerations; }
  const std::vector<double>& trailTimes() const { return this->TrailTimes; }
  /// The slot of the k-th newest pose (k < trailLength).
  int trailSlot(int k) const;
  /// Records the current poses at time t (a time recorded last is replaced:
  /// a step taken back and taken again records once).
  void recordTrail(double t);
  ///@}
  /// The super set's links (empty without Linking).
  const LinkTable& links() const { return this->Links; }

  /// The global id of each element held, increasing: what its draws hash.
  const std::vector<std::uint32_t>& elementIds() const { return this->Ids; }

  /// @name Distributed runs
  /// A piece of a distributed run holds the elements whose centres lie in its
  /// part of the field and samples a ghosted piece of it, so the reposition
  /// test takes the whole field's domain. A step there is resetDue(), the
  /// exchange of elements whose centres lie in another piece (Partition.h),
  /// then step(): the same arithmetic as step() alone, which resets first.
  ///@{
  /// The bounds of the reposition test (by default the sampled field's).
  void setDomain(const Domain& domain);
  /// Step 1 of a step on its own: resets the elements that are due.
  void resetDue(const RangeRunner& run, double t, double h);
  /// The mean of element e's particle positions.
  std::array<float, 3> centerOf(std::size_t e) const;
  /// The 32-bit words of one element's state (normals are recomputed).
  std::size_t recordWords() const;
  /// Appends element e's state to `out`.
  void packElement(std::size_t e, std::vector<std::uint32_t>& out) const;
  /**
   * Drops the elements flagged in `leaving` (one flag per element held) and
   * takes in those `records` hold (recordWords() each, from packElement() of
   * an engine configured alike); the elements stay in increasing id order.
   * Empty on success, otherwise what is wrong with the records.
   */
  std::string exchange(
    const std::vector<std::uint8_t>& leaving, const std::vector<std::uint32_t>& records);
  ///@}

  /// For tests: direct access to the positions of the system.
  std::vector<float>& mutablePositions() { return this->Positions; }

private:
  struct SpringWork
  {
    std::uint32_t a, b;
    float rest, stiffness;
    float shareA, shareB; ///< part of the correction each end takes (pinned ends take none)
  };

  /// The flow Along Flow samples where an element is placed: the field at
  /// the second slice's weight; without a field the turn is left pending.
  struct ReleaseFlow
  {
    const VectorField* field;
    float weight;
  };
  /// Places element e's next generation, hidden unless `releasing`.
  void place(std::size_t e, bool releasing, const ReleaseFlow& flow);
  /// Turns element e, placed at its initial centre, to `q`: its orientation,
  /// pose and particle positions.
  void orient(std::size_t e, const std::array<float, 4>& q);
  /// Along Flow: turns element e onto the flow at its initial centre.
  void alignToFlow(std::size_t e, const ReleaseFlow& flow);
  /// Whether element e is placed anew in the next step: flagged by the
  /// reposition test, hidden, or out of lifetime.
  bool isDue(std::size_t e) const
  {
    return (this->ResetFlags[e] & (ResetDue | ReleaseHidden)) || this->Lifetimes[e] <= 0.0f;
  }
  /// The release centre of element `element`'s generation (Engine::place).
  void releaseCenter(std::uint32_t element, std::uint32_t generation, float c[3]) const;
  /// What a step decides once for every element: the second slice's weight
  /// at t, t + h/2 and t + h, the release window, and who resets.
  struct StepWeights
  {
    float start, middle, end;
    bool releasing; ///< the step overlaps the release window (releasesAt)
    bool resets;    ///< due elements are placed in this step (not done by resetDue())
  };
  /// The step [t, t + h)'s StepWeights; takes back resetDue()'s mark.
  StepWeights beginStep(const VectorField& field, double t, double h);
  /// Steps 1 and 2 for element e: reset when due, then advect; keeps the
  /// positions before the step and after advection (3n floats each;
  /// `advected` may be null when nothing restores).
  void resetAndAdvect(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
    float* before, float* advected);
  void stepElement(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
    std::vector<float>& scratch);
  void advectParticle(const VectorField& field, const StepWeights& w, double h, float p[3]) const;
  /// The correction of spring s at positions p; false when its ends coincide.
  static bool springCorrection(const float* p, const SpringWork& s, float c[3]);
  /// K iterations on one element's positions; `scratch` holds
  /// restorationScratchFloats() floats of scratch, `orientation` the
  /// element's quaternion (shape matching).
  void restore(float* p, float* scratch, float* orientation) const;
  /// One of those iterations.
  void restoreOnce(float* p, float* scratch, float* orientation) const;
  void matchShape(float* p, float* orientation) const;
  bool restoresElements() const;
  std::size_t restorationScratchFloats() const;
  /// Forces (unless `advected` is null), the reposition test and the
  /// lifetime after restoration.
  void settle(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
    const float* before, const float* advected);
  /// Whether p is in the domain after a step: in the bounds, in a cell
  /// inside the flow's domain (DomainMask.h).
  bool inDomain(const VectorField& field, const float p[3], float weight) const
  {
    return this->domainOf(field).contains(p) && !field.outsideCellAt(p, weight);
  }
  /// The pose fit and spin at the end of a step (Pose.h); `finite`: the
  /// positions after the step were finite (otherwise they are the ones before).
  void updatePose(
    std::size_t e, const VectorField& field, const StepWeights& weights, double h, bool finite);
  /// Whether element e, in its first step since it was placed, moved its
  /// centre `c` slower than releaseMinSpeed.
  bool releasedStagnant(std::size_t e, const float c[3], double h) const;
  const Domain& domainOf(const VectorField& field) const
  {
    return this->HasDomain ? this->DomainBox : field.domain();
  }
  /// A step of a super set: each restoration iteration is followed by one
  /// averaged Jacobi pass over the links, so elements wait for each other.
  void stepLinked(const VectorField& field, double t, double h, const RangeRunner& run);
  /// That pass for element e, reading LinkSnapshot.
  void restoreLinks(std::size_t e);
  void normalsOf(std::size_t e);
  /**
   * The order step() visits elements in, or empty for storage order: by a
   * coarse grid over the field (about one bin per element) in the field's
   * own memory order, so consecutive elements sample neighbouring memory and
   * a worker's range is a slab of space. Elements are independent, so the
   * order changes the speed, never the bits. Re-sorted every few steps.
   */
  const std::vector<std::uint32_t>& visitOrder(const VectorField& field);
  /// Asks the cache for element e's state ahead of its step.
  void prefetchElement(std::size_t e) const;

  ElementTemplate Shape;
  Parameters Params;
  std::vector<std::uint32_t> Ids;
  bool HasDomain = false;
  Domain DomainBox;
  std::vector<SpringWork> Springs;
  std::vector<SpringWork> GaussSeidelSprings; ///< the springs in colour order
  /// A spring at one of its ends: the share of its correction that end
  /// takes, negative at end b.
  struct Incidence
  {
    std::uint32_t spring;
    float share;
  };
  std::vector<std::uint32_t> IncidenceStart; ///< particle i's are [start[i], start[i + 1])
  std::vector<Incidence> Incidences;
  std::vector<float> InverseDegree;
  std::vector<std::uint8_t> Pinned;

  std::vector<float> Positions;
  std::vector<float> Normals;
  std::vector<float> Forces;
  std::vector<float> Lifetimes;
  std::vector<std::uint32_t> Generations;
  std::vector<float> InitialCenters;
  /// Where releases may land (setReleaseMask): the grid (a field without
  /// time steps, for locating cells only) and its unfit cells.
  /// resetDue() placed the due elements of the step about to be taken.
  bool ResetsDone = false;
  std::shared_ptr<const VectorField> ReleaseGrid;
  std::shared_ptr<const std::vector<std::uint8_t>> ReleaseUnfit;
  std::vector<float> Orientations;
  std::vector<float> Poses; ///< poses(): 4 floats per element
  std::vector<float> Spins; ///< spins(): 4 floats per element
  std::array<float, 4> FrameQuaternion = { 0, 0, 0, 1 };
  std::vector<std::uint8_t> ResetFlags;
  std::array<float, 9> RestMomentInverse = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };

  std::vector<std::uint32_t> VisitOrder;
  int StepsSinceOrdered = 0;

  std::vector<float> TrailPositions;
  std::vector<std::uint32_t> TrailGenerations;
  std::vector<double> TrailTimes;
  int TrailNewest = -1; ///< the slot written last, -1 before any

  LinkTable Links;
  // A super set's step runs in phases over all elements: its before, advected
  // and per-iteration positions are kept for the whole system.
  std::vector<float> LinkBefore, LinkAdvected, LinkSnapshot;
};

/**
 * Where steps end: on the grid start + k * dt and on every time in `breaks`
 * (the data's time steps, so no step straddles two data intervals). Because
 * the boundaries do not depend on where a run stops, stepping to T1 and then
 * to T2 passes through exactly the states a fresh run to T2 does.
 */
class StepSchedule
{
public:
  StepSchedule(double start, double dt, std::vector<double> breaks);
  /// The first boundary after t. Boundaries closer than epsilon() to t are
  /// skipped, and a grid point within epsilon() of a break yields the break.
  double next(double t) const;
  double epsilon() const { return this->Epsilon; }
  double start() const { return this->Start; }
  double dt() const { return this->Dt; }

private:
  double Start;
  double Dt;
  double Epsilon;
  std::vector<double> Breaks;
};

/**
 * Steps `engine` from its committed time t along the schedule's boundaries
 * while the next boundary is not past `target`; returns the new committed time.
 * `keepGoing` is asked before every step (progress, abort) and may stop early.
 */
double advance(Engine& engine, const VectorField& field, const StepSchedule& schedule, double t,
  double target, const RangeRunner& run, const std::function<bool(double time)>& keepGoing = {});

/// The same walk along the schedule for any engine: `step(t, h)` per step.
double advance(const StepSchedule& schedule, double t, double target,
  const std::function<void(double t, double h)>& step,
  const std::function<bool(double time)>& keepGoing = {});

/**
 * The GPU engine's texture layout (thesis §3.5.1, generalised): elements in a
 * near-square W x H grid, one such block per template particle index, blocks
 * bx per row, so the particle texture is near square. Here, not in Gpu/, so
 * the filter can check a system against a GPU's texture limit before it asks
 * for one.
 */
struct ParticleLayout
{
  long long elementGrid[2] = { 0, 0 }; ///< W, H
  long long blocksPerRow = 0;          ///< bx
  long long width = 0, height = 0;     ///< the particle texture
  static ParticleLayout of(std::size_t elements, std::size_t particlesPerElement);
};

/**
 * Empty when every texture of the GPU engine for `elements` elements of
 * `shape` fits a GPU whose textures are at most `maxSize` texels wide and
 * high: the particle state (ParticleLayout), and the template's tables (rest
 * positions and particle info n wide, the Gauss-Seidel spring table 2n wide,
 * the spring and triangle lists 4096 wide). Otherwise which one does not.
 */
std::string gpuTextureError(const ElementTemplate& shape, std::size_t elements, long long maxSize);

/// Velocity and |curl v| sampled at `count` positions (3 floats each);
/// `vorticity` may be null.
void sampleAtPositions(const VectorField& field, double t, const float* positions,
  std::size_t count, float* velocity, float* vorticity, const RangeRunner& run);

} // namespace bp

#endif
