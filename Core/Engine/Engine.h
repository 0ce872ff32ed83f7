// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Engine.h
 * @brief The CPU engine: one step of a system of bound particles, as
 * docs/engine-specification.md specifies it for both engines.
 *
 * A step of size h at time t does, for every element independently:
 *  1. reset, when the element was flagged by the previous step or its lifetime
 *     ran out: a new centre (uniform in the emitter box, or the next seed
 *     point), an orientation (Orientation: the user's frame, a uniform random
 *     rotation, or along the flow), the scaled template, a lifetime uniform
 *     in [min, max]; every draw comes from counterHash(seed, element,
 *     generation, draw), draws 0-2 the centre (candidateDraw() for further
 *     candidates), 3-5 the rotation, 6 the lifetime;
 *  2. advection of every particle (Euler, RK2 midpoint or classic RK4), a
 *     heavy particle's with its slip velocity's own displacement added
 *     (Inertia.h; after restoration a restored element shares its mean slip);
 *  3. restoration, K iterations of averaged Jacobi (thesis §3.5), Jacobi with
 *     relaxation, Gauss-Seidel, or shape matching (ShapeMatching.h); the
 *     per-particle "force" is the length of the particle's total restoration
 *     displacement in this step;
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
 * parallel and gives the same bits for any number of threads (a super set's
 * links read a snapshot of every element taken between phases).
 *
 * The parameters are in EngineParameters.h; the engine's definitions are in
 * one file per role: EngineValidate.cpp (the parameter checks),
 * EngineConfigure.cpp (spring tables, sizing), EngineRelease.cpp (step 1),
 * EngineStep.cpp (steps 2, 3, 5 and 6 and the step loop), EngineWalls.cpp (the
 * walls in a step and the events at the field's sides), EngineSurfaces.cpp
 * (the Surfaces input's gates, outlets and walls), EngineLinked.cpp
 * (a super set's step), EngineVisitOrder.cpp, EngineMigration.cpp
 * (distributed runs), EngineSaveState.cpp (a state to save and resume; the
 * state's checks are in EngineState.cpp) and Engine.cpp (trails, step 4's
 * normals, and advance() along the step schedule).
 */
#ifndef BoundParticles_Engine_h
#define BoundParticles_Engine_h

#include "ElementTemplate.h"
#include "EngineParameters.h"
#include "EngineState.h"
#include "Inertia.h"
#include "Interactions.h"
#include "Parallel.h"
#include "ReleaseWeights.h"
#include "StepSchedule.h"
#include "SuperSet.h"
#include "VectorField.h"
#include "Walls.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bp
{

/**
 * The largest Jacobi relaxation factor that is stable for `shape`: Jacobi
 * moves particle i by factor * sum over its springs of share * stiffness *
 * stretch, and the iteration of the linearised springs stays bounded while
 * factor * max_i sum_i(share * stiffness) <= 1 (Gershgorin). 0.2 for ten
 * springs per particle; infinity for a template with no springs.
 */
float stableRelaxation(const ElementTemplate& shape);

/**
 * Linear shape matching's (sum q q^T)^-1 over the template's rest positions q
 * scaled by `size`, row-major; a pseudo-inverse, so that flat and line-like
 * templates (whose moment has rank 2 or 1) fit within their own span.
 */
std::array<float, 9> restMomentInverse(const ElementTemplate& shape, float size);

/// The lifetime an element drawing as `drawElement` is given when its
/// `generation` is placed (Engine::place; the GPU engine's bpLifetimeOf);
/// with Release Pattern Lattice every element's is element 0's.
float lifetimeDraw(const Parameters& p, std::uint32_t drawElement, std::uint32_t generation);

struct SurfaceCrossing;

/// The mean of n particles' positions p, summed in float, particle by
/// particle, as the reposition test (2.4) sums an element's centre.
inline void particleMean(const float* p, std::size_t n, float mean[3])
{
  float c[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[3 * i + k];
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    mean[k] = c[k] / float(n);
  }
}

class Engine
{
public:
  /// Checks the template and parameters and sizes the system; empty on success.
  std::string configure(const ElementTemplate& shape, const Parameters& parameters);

  /// The checks configure() makes, without allocating anything.
  static std::string validate(const ElementTemplate& shape, const Parameters& parameters);

  /// Places every element (generation 0) at `startTime` (the release
  /// window's test, and the flow Along Flow samples in `field`, when given).
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
   * mask, in an unfit cell) give way to the next ones in turn. `weights`
   * (on the same grid, or null) weigh the candidates (ReleaseWeights.h).
   */
  void setReleaseMask(const GridGeometry& grid,
    std::shared_ptr<const std::vector<std::uint8_t>> unfit,
    std::shared_ptr<const ReleaseWeights> weights = nullptr);

  /// The emitter box releases draw from from now on (in situ, after a change
  /// of grid: bp::emitterInChangedField), in engine coordinates.
  void setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max)
  {
    this->Params.emitterMin = min;
    this->Params.emitterMax = max;
  }

  /// One step of size h from time t (h > 0).
  void step(const VectorField& field, double t, double h, const RangeRunner& run);

  /// Computes the per-particle normals from the positions (normals());
  /// their storage is taken on the first call, as only some readers need them.
  void updateNormals(const RangeRunner& run);

  /// The elements this engine holds: all of them, or a piece's share in a
  /// distributed run (Core/Distributed/Partition.h).
  std::size_t elementCount() const { return this->Ids.size(); }
  std::size_t particlesPerElement() const { return this->Shape.particleCount(); }
  std::size_t particleCount() const { return this->elementCount() * this->particlesPerElement(); }
  const ElementTemplate& shape() const { return this->Shape; }
  const Parameters& parameters() const { return this->Params; }

  /// Element-major: particle i of element e is at 3 * (e * n + i).
  const std::vector<float>& positions() const { return this->Positions; }
  /// As of the last updateNormals(); empty until it is called, and again
  /// after configure(), exchange() or an assignment (CpuStepper::restore()):
  /// they are scratch, computed on demand, never state.
  const std::vector<float>& normals() const { return this->Scratch.normals; }
  const std::vector<float>& forces() const { return this->Forces; }
  const std::vector<float>& lifetimes() const { return this->Lifetimes; }
  /// The lifetime element e was placed with: its age is this less lifetimes()[e].
  float drawnLifetime(std::size_t e) const
  {
    return lifetimeDraw(this->Params, this->drawElement(e), this->Generations[e]);
  }
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
  /// Heavy particles (Inertia.h): each particle's slip velocity, its velocity
  /// less the flow's at its position (3 floats per particle, element-major);
  /// 0 when placed. Empty unless the parameters carry inertia.
  const std::vector<float>& slips() const { return this->Slips; }
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
  /// Whether element e's pose in `slot` lies across a periodic seam from the
  /// element now (Domain::acrossPeriodicSeam of its first particle, in the
  /// domain the steps test against): moved by a period since, it is not shown.
  bool trailAcrossSeam(std::size_t slot, std::size_t e, const VectorField& field) const;
  ///@}
  /// The super set's links (empty without Linking).
  const LinkTable& links() const { return this->Links; }
  /// The events at the field's sides since the trace started (or resumed
  /// from a saved state), Interactions.h; a copy of the engine keeps its own.
  const InteractionLog& interactions() const { return this->Log; }

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
  /// Step 1 of a step on its own: records the trail pose due at t, then
  /// resets the elements that are due.
  void resetDue(const RangeRunner& run, double t, double h);
  /// The mean of element e's particle positions.
  std::array<float, 3> centerOf(std::size_t e) const;
  /// The 32-bit words of one element's state (forEachElementArray; normals
  /// are not sent but recomputed).
  std::size_t recordWords() const;
  /// The same for a system of `shape` and `parameters`, without configuring
  /// one: what a checkpoint of an element holds (Stepper::checkpointBytes).
  static std::size_t recordWords(const ElementTemplate& shape, const Parameters& parameters);
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

  /// @name A state to save and resume (EngineState.h)
  ///@{
  /// A record's arrays (forEachElementArray's, by name and type), those of
  /// no component left out.
  std::vector<StateArray> stateLayout() const;
  /// The same for a system of `shape` and `parameters`, without configuring
  /// one (checkTraceState).
  static std::vector<StateArray> stateLayout(
    const ElementTemplate& shape, const Parameters& parameters);
  /// Every element's record, ids increasing, and the state's scalars (the
  /// trail ring's times and newest slot, the emitter box).
  EngineState saveState() const;
  /// Replaces every element held by the state's and takes its scalars, on an
  /// engine configured with the template and parameters it was saved with
  /// (checkTraceState first); empty on success, otherwise what is wrong.
  std::string loadState(const EngineState& state);
  ///@}

  /// For tests: direct access to the positions of the system.
  std::vector<float>& mutablePositions() { return this->Positions; }
  /// For tests: direct access to the slips (a particle released at rest).
  std::vector<float>& mutableSlips() { return this->Slips; }

private:
  /**
   * Calls f(name, array, width, blocks, fill) for every per-element array of
   * the state, `self` an Engine or a const one: `name` is the member's, as
   * a saved state names the array (EngineState.h); `array` holds `blocks`
   * blocks of elementCount() elements, `width` values each (element e of
   * block b at (b * E + e) * width), all `fill` when sized. The one list of what an
   * element is made of: configure() sizes by it, migration packs, unpacks
   * and counts by it (EngineMigration.cpp) and a saved state is laid out by
   * it (stateLayout), so a new array is sized, migrated and saved by its
   * line here alone (a type other than uint32, uint8 or float needs a
   * toWord() overload there and a StateArray::Type); what it holds is still
   * written where an element is placed (place()) and stepped
   * (EngineStep.cpp). Ids comes first: a record starts with the element's
   * id. A new array, or a change in what one holds, bumps EngineStateVersion.
   */
  template <class Self, class F>
  static void forEachElementArray(Self& self, F&& f)
  {
    const std::size_t n = self.Shape.particleCount();
    const std::size_t slots = std::size_t(std::max(self.Params.trailLength, 0));
    f("Ids", self.Ids, 1, 1, std::uint32_t(0));
    f("Generations", self.Generations, 1, 1, std::uint32_t(0));
    f("ResetFlags", self.ResetFlags, 1, 1, std::uint8_t(0));
    f("Lifetimes", self.Lifetimes, 1, 1, 0.0f);
    f("InitialCenters", self.InitialCenters, 3, 1, 0.0f);
    f("Orientations", self.Orientations, 4, 1, 0.0f);
    f("Poses", self.Poses, 4, 1, 0.0f);
    f("Spins", self.Spins, 4, 1, 0.0f);
    f("Positions", self.Positions, 3 * n, 1, 0.0f);
    f("Forces", self.Forces, n, 1, 0.0f);
    f("Slips", self.Slips, carriesInertia(self.Params) ? 3 * n : 0, 1, 0.0f);
    f("TrailGenerations", self.TrailGenerations, 1, slots, NoTrailPose);
    f("TrailPositions", self.TrailPositions, 3 * n, slots, 0.0f);
  }

  /// @name configure()'s parts (EngineConfigure.cpp)
  ///@{
  /// Springs (at the element size, with each end's share), Pinned and InverseDegree.
  void buildSprings();
  /// GaussSeidelSprings: the springs by colour.
  void buildGaussSeidelOrder();
  /// IncidenceStart and Incidences: each particle's springs, for Jacobi's gather.
  void buildIncidences();
  /// Every per-element array for E elements, and the trail's times.
  void sizeElements(std::size_t E);
  ///@}
  /// exchange()'s new order of (id, source) pairs, sorted by id: a source
  /// below elementCount() is an element kept, otherwise that many records on.
  /// Empty on success, otherwise what is wrong with the records.
  std::string mergeOrder(const std::vector<std::uint8_t>& leaving,
    const std::vector<std::uint32_t>& records,
    std::vector<std::pair<std::uint32_t, std::size_t>>& order) const;
  /// exchange()'s and loadState()'s merge, on records checked to be whole
  /// records of this engine's layout: the elements kept and those the
  /// records hold, in increasing id order; empty on success, otherwise what
  /// is wrong with the records (an id out of range or repeated).
  std::string merge(
    const std::vector<std::uint8_t>& leaving, const std::vector<std::uint32_t>& records);

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
  /// Whose draws element e takes (orientation, lifetime; a super set's
  /// elements all take element 0's).
  std::uint32_t drawElement(std::size_t e) const { return this->Links.empty() ? this->Ids[e] : 0u; }
  /// Places element e's next generation, hidden unless `releasing`.
  void place(std::size_t e, bool releasing, const ReleaseFlow& flow);
  /// Turns element e, placed at its initial centre, to `q`: its orientation,
  /// pose and particle positions.
  void orient(std::size_t e, const std::array<float, 4>& q);
  /// Along Flow: turns element e onto the flow at its initial centre.
  void alignToFlow(std::size_t e, const ReleaseFlow& flow);
  /// Whether element e is placed anew in the next step: flagged by the
  /// reposition test, hidden, or out of lifetime (a Terminated element waits
  /// for the end of its lifetime).
  bool isDue(std::size_t e) const
  {
    return (this->ResetFlags[e] & (ResetDue | ReleaseHidden)) || this->Lifetimes[e] <= 0.0f;
  }
  /// The release centre of element `element`'s generation (Engine::place);
  /// false for a lattice point, or a weighted release with no candidate,
  /// that does not fit (the element is hidden).
  bool releaseCenter(std::uint32_t element, std::uint32_t generation, float c[3]) const;
  /// The Random pattern's centre with Release Weights (ReleaseWeights.h);
  /// false where no candidate fits.
  bool weightedCenter(std::uint32_t element, std::uint32_t generation, float c[3]) const;
  /// What a step decides once for every element: the second slice's weight
  /// at t, t + h/2 and t + h, the release window, and who resets.
  struct StepWeights
  {
    float start, middle, end;
    bool releasing;      ///< the step overlaps the release window (releasesAt)
    bool resets;         ///< due elements are placed in this step (not done by resetDue())
    InertiaStep inertia; ///< the slip's step (with carriesInertia())
  };
  /// The step [t, t + h)'s StepWeights; takes back resetDue()'s mark.
  StepWeights beginStep(const VectorField& field, double t, double h);
  /// Steps 1 and 2 for element e: reset when due, then advect; keeps the
  /// positions before the step and after advection (3n floats each;
  /// `advected` may be null when nothing restores).
  /// `events` (or null) gets the particles' wall contacts (Interactions.h).
  void resetAndAdvect(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
    float* before, float* advected, std::vector<InteractionEvent>* events = nullptr);
  /// Element e's step; `events` gets its events (time and velocity are
  /// filled by settle() and step()).
  void stepElement(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
    std::vector<float>& scratch, std::vector<InteractionEvent>& events);
  /// `sampled`, when given, is the field at p at the step's start (k1).
  void advectParticle(const VectorField& field, const StepWeights& w, double h, float p[3],
    const float* sampled = nullptr) const;
  /// A heavy particle's step: its slip's (Inertia.h), from the field at its
  /// position at the step's start, then the tracer's advection, then the
  /// slip's displacement.
  void advectHeavyParticle(
    const VectorField& field, const StepWeights& w, double h, float p[3], float slip[3]) const;
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
  /// A wall (Boundary Stick, Slip, Bounce; Walls.h) after advection for one
  /// particle: p, advected from `before`, back into the domain's box and out
  /// of cells outside the flow (MaskWalls.h: on their faces by the rule, or
  /// back to `before` where no face is found); a heavy particle's `slip` (or
  /// null) by the same rule on its velocity. True where the step met a wall
  /// the particle did not lie on before it, with `met`'s side (NoSide for a
  /// face of the cells outside the flow), point and outward normal filled in
  /// (firstContact, firstOutsideFace).
  bool wallParticle(const VectorField& field, const StepWeights& weights, const float before[3],
    float p[3], float* slip, InteractionEvent& met) const;
  /// The wall after restoration for element e: a particle Stick holds (on a
  /// side or a face of the cells outside the flow in `advected`, its walled
  /// position) goes back there; another pushed out of the box is put on its
  /// side, one pushed into a cell outside the flow on the faces by Slip's
  /// rule from its position in `advected` (back there where no face is
  /// found). A particle put on a side or face it did not lie on in
  /// `before`, with no event yet in this step (from `first` on in
  /// `events`), gets one there.
  void wallAfterRestoration(std::size_t e, const VectorField& field, const StepWeights& weights,
    const float* before, const float* advected, std::vector<InteractionEvent>& events,
    std::size_t first);
  /// Forces (unless `advected` is null), the reposition test and the
  /// lifetime after restoration. With `events`: an element that left the
  /// field (Release Again, Terminate) gets its event, and the events from
  /// `first` on (element e's in this step) its mean velocity, or are
  /// dropped where the step is taken back (non-finite positions).
  void settle(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
    const float* before, const float* advected, std::vector<InteractionEvent>* events = nullptr,
    std::size_t first = 0);
  /// Element e left the field (its centre the reposition test read at
  /// `at`): its event, Released or `terminated`, at that centre, on the side
  /// it lies beyond (or, by any particle, the first particle's; NoSide for a
  /// cell outside the flow).
  void recordLeaving(std::size_t e, const VectorField& field, const float at[3], bool terminated,
    std::vector<InteractionEvent>& events) const;
  /// The events from `first` on get the element's mean velocity over the
  /// step: its particles' mean moved from `before` to `center`.
  /// `center` the particles' mean after the step, before any move of the
  /// whole element (anchor, periodic side).
  void fillVelocity(const float* before, const float center[3], double h,
    std::vector<InteractionEvent>& events, std::size_t first) const;
  /// settle()'s events for element e: none where the step was taken back
  /// (`moved` null: non-finite positions) or the element is not shown in it
  /// (hidden: placed and moved, but it records nothing); its leaving (recordLeaving) where
  /// `leftAt` is given; then their velocity (fillVelocity).
  void noteEvents(std::size_t e, const VectorField& field, double h, const float* before,
    const float* moved, const float* leftAt, bool terminated, std::vector<InteractionEvent>& events,
    std::size_t first) const;
  /// One step's events from t of size h, in any order, kept in the log at
  /// their times (each event's share of the step: t + share h, the end
  /// t + h as such), ordered by element and particle.
  void keepInteractions(std::vector<InteractionEvent>&& events, double t, double h);
  /// settle()'s end for element e: its reset flag from the step (`leave`:
  /// due at once; `left`: out of the field; `moved`: its particles' mean,
  /// null where the step was taken back; `at`: the centre tested), its
  /// passages of the Surfaces, and its events.
  void flagAfterStep(std::size_t e, const VectorField& field, double h, const float* before,
    const float* moved, const float at[3], bool leave, bool left,
    std::vector<InteractionEvent>* events, std::size_t first);
  /// The Surfaces (Parameters::surfaces, 2.10; EngineSurfaces.cpp):
  /// element e's centre moved from its particles' mean `before` to `center`
  /// over the step; its passages recorded in `events` (when given, with
  /// their share of the step as time). The flag a passage ends it with
  /// (Terminated at an Outlet; at a Wall, Boundary's: ResetDue for Release
  /// Again, Terminated for Terminate), 0 for none.
  /// A centre that left through a periodic side (moved by wrapPeriodic
  /// after; not anchored) passes the Surfaces just past the seam too
  /// (SurfaceSet::passages' seam).
  std::uint8_t passSurfaces(std::size_t e, const VectorField& field, const float* before,
    const float center[3], std::vector<InteractionEvent>* events) const;
  /// Whether the Surfaces have Walls that act on particles (Boundary Stick,
  /// Slip or Bounce).
  bool wallsParticlesOnSurfaces() const;
  /// Whether Stick holds a particle at p on a Wall of the Surfaces: within
  /// two offsets of one (SurfaceSet::onWall), where the rule put it.
  bool heldOnSurfaceWall(const VectorField& field, const float p[3]) const;
  /// A particle's step from `before` to `p` (after the box's walls) at the
  /// Surfaces' Walls (Stick, Slip, Bounce; 2.10): p put back on its side, a heavy
  /// particle's `slip` by the rule. Whether it met a Wall it did not lie on
  /// before the step: then `met` holds the event (but for element and particle).
  bool wallParticleOnSurfaces(const VectorField& field, const StepWeights& weights,
    const float before[3], float p[3], float* slip, InteractionEvent& met) const;
  /// Stick, Slip or Bounce on p at the Wall crossing c (p put `offset` off
  /// it on its step's side: at c, on its plane, or reflected).
  void wallRule(const SurfaceCrossing& c, float offset, float p[3]) const;
  /// The rule on a heavy particle's `slip` at a Wall whose normal toward
  /// its side is m, p where the wall left it.
  void wallSlip(const VectorField& field, const StepWeights& weights, const std::array<float, 3>& m,
    const float p[3], float* slip) const;
  /// How far off a Wall of the Surfaces (along its normal, on its side) a
  /// particle lies on it before a step, so that meeting it is no new event:
  /// two offsets (surfaceWallOffset), where the walls put it.
  float restingOnWall(float offset) const;
  /// After restoration: element e's particles held on a Wall of the
  /// Surfaces (Stick) back where they were held, those the springs pushed
  /// through one (from `advected`) put back on its side; an event
  /// for one that did not lie on it before the step, and has none yet.
  void keepOffSurfaceWalls(std::size_t e, const VectorField& field, const float* before,
    const float* advected, std::vector<InteractionEvent>& events, std::size_t first);
  /// Anchor::Centre: element e moved whole from its particles' mean `center`
  /// to its release centre; whether a particle is then outside the domain
  /// (tested only with `testParticles`).
  bool anchor(std::size_t e, const VectorField& field, const StepWeights& weights,
    const float center[3], bool testParticles);
  /// A periodic side (Periodic.h): element e, its particles' mean at
  /// `center`, moved whole by whole periods where that centre lies beyond a
  /// periodic side; then its new centre in `wrapped`. Whether it moved.
  bool wrapPeriodic(
    std::size_t e, const VectorField& field, const float center[3], float wrapped[3]);
  /// The whole periods (periodicShift, each periodic axis) that move an
  /// element whose particles' mean is `center` back into the domain; whether any is not 0.
  bool seamShift(const VectorField& field, const float center[3], float shift[3]) const;
  /// Whether a particle of element e is outside the domain (false unless
  /// `testParticles`).
  bool anyOutside(
    std::size_t e, const VectorField& field, const StepWeights& weights, bool testParticles) const;
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
  /// That pass for element e, reading StepScratch::linkSnapshot.
  void restoreLinks(std::size_t e);
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
  std::vector<float> Forces;
  std::vector<float> Slips; ///< slips()
  std::vector<float> Lifetimes;
  std::vector<std::uint32_t> Generations;
  std::vector<float> InitialCenters;
  /// resetDue() placed the due elements of the step about to be taken.
  bool ResetsDone = false;
  /// Where releases may land (setReleaseMask): the grid (a field without
  /// time steps, for locating cells only) and its unfit cells.
  std::shared_ptr<const VectorField> ReleaseGrid;
  std::shared_ptr<const std::vector<std::uint8_t>> ReleaseUnfit;
  std::shared_ptr<const ReleaseWeights> Weights; ///< Release Weights, or null
  std::vector<float> Orientations;
  std::vector<float> Poses; ///< poses(): 4 floats per element
  std::vector<float> Spins; ///< spins(): 4 floats per element
  std::array<float, 4> FrameQuaternion = { 0, 0, 0, 1 };
  /// The template's long axis (longAxis()), which Along Flow turns onto the flow.
  std::array<float, 3> LongAxis = { 1, 0, 0 };
  std::vector<std::uint8_t> ResetFlags;
  std::array<float, 9> RestMomentInverse = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };

  std::vector<float> TrailPositions;
  std::vector<std::uint32_t> TrailGenerations;
  std::vector<double> TrailTimes;
  int TrailNewest = -1; ///< the slot written last, -1 before any

  LinkTable Links;
  InteractionLog Log; ///< interactions()

  /**
   * What the engine derives from its state, or writes before it reads it
   * again, so that a copy of the engine (CpuStepper::save) leaves it out: a
   * copy starts with none of it, and an assignment keeps the target's
   * buffers but empties the normals and the visiting order (they belong to
   * other positions). Each buffer is sized where it is used.
   */
  struct StepScratch
  {
    /// updateNormals()'s, 3 floats per particle.
    std::vector<float> normals;
    /// A super set's step runs in phases over all elements: its before,
    /// advected and per-iteration positions are kept for the whole system.
    std::vector<float> linkBefore, linkAdvected, linkSnapshot;
    /// visitOrder()'s, and the steps since it was sorted.
    std::vector<std::uint32_t> visitOrder;
    int stepsSinceOrdered = 0;

    StepScratch() = default;
    StepScratch(const StepScratch&) {}
    StepScratch(StepScratch&&) = default;
    StepScratch& operator=(const StepScratch&)
    {
      this->normals.clear();
      this->visitOrder.clear();
      return *this;
    }
    StepScratch& operator=(StepScratch&&) = default;
  };
  StepScratch Scratch;
};

/**
 * Steps `engine` from its committed time t along the schedule's boundaries
 * while the next boundary is not past `target`; returns the new committed time.
 * `keepGoing` is asked before every step (progress, abort) and may stop early.
 */
double advance(Engine& engine, const VectorField& field, const StepSchedule& schedule, double t,
  double target, const RangeRunner& run, const std::function<bool(double time)>& keepGoing = {});

} // namespace bp

#endif
