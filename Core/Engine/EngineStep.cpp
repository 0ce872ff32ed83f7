// SPDX-License-Identifier: BSD-3-Clause
// One step of the system (Engine.h, steps 2-6): per element, advection,
// restoration, the reposition test and the pose; and step(), which runs them
// over the elements in visiting order, fetching ahead. The per-particle and
// per-element functions stay in this one file with step() so that the
// compiler inlines them into its loop; the walls' (Boundary Stick, Slip,
// Bounce) and the events' (Interactions.h) are in EngineWalls.cpp.
#include "CounterHash.h"
#include "Engine.h"
#include "MaskWalls.h"
#include "Pose.h"
#include "ShapeMatching.h"
#include "SpringForce.h"
#include "Surfaces.h"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace bp
{

namespace
{
inline bool finite3(const float* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
} // namespace

void Engine::advectParticle(
  const VectorField& field, const StepWeights& w, double h, float p[3], const float* sampled) const
{
  const float hf = float(h);
  float k1[3];
  if (sampled)
  {
    std::copy_n(sampled, 3, k1);
  }
  else
  {
    field.sampleWeighted(p, w.start, k1);
  }
  switch (this->Params.integrator)
  {
    case Integrator::Euler:
      for (int k = 0; k < 3; ++k)
      {
        p[k] += hf * k1[k];
      }
      return;
    case Integrator::RK2:
    {
      float q[3], k2[3];
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + 0.5f * hf * k1[k];
      }
      field.sampleWeighted(q, w.middle, k2);
      for (int k = 0; k < 3; ++k)
      {
        p[k] += hf * k2[k];
      }
      return;
    }
    case Integrator::RK4:
    {
      float q[3], k2[3], k3[3], k4[3];
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + 0.5f * hf * k1[k];
      }
      field.sampleWeighted(q, w.middle, k2);
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + 0.5f * hf * k2[k];
      }
      field.sampleWeighted(q, w.middle, k3);
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + hf * k3[k];
      }
      field.sampleWeighted(q, w.end, k4);
      for (int k = 0; k < 3; ++k)
      {
        p[k] += hf / 6.0f * (k1[k] + 2.0f * k2[k] + 2.0f * k3[k] + k4[k]);
      }
      return;
    }
  }
}

void Engine::advectHeavyParticle(
  const VectorField& field, const StepWeights& w, double h, float p[3], float slip[3]) const
{
  float u[3], move[3];
  SlipStepper stepper(w.inertia, slip, move);
  field.sampleAlong(p, w.start, stepper, u);
  this->advectParticle(field, w, h, p, u); // u is the integrator's first sample
  for (int k = 0; k < 3; ++k)
  {
    p[k] += move[k];
  }
}

inline bool Engine::springCorrection(const float* p, const SpringWork& s, float c[3])
{
  // The whole correction moves end a away from end b; the ends share it.
  return springForce(p + 3 * s.a, p + 3 * s.b, s.rest, s.stiffness, c);
}

void Engine::matchShape(float* p, float* orientation) const
{
  // Goals: the rest shape turned by the best-fit rotation about the current
  // centre (Müller et al. 2005, equal masses); particles move towards them.
  const std::size_t n = this->Shape.particleCount();
  const float size = this->Params.elementSize;
  float c[3], A[9];
  momentOf(p, n, this->Shape.rest, size, c, A);
  fitRotation(A, orientation, MatchIterations);
  float R[9];
  quaternionToMatrix(orientation, R);
  if (this->Params.linearShapeMatching)
  {
    // Goals from M = beta * A Aqq^-1 + (1 - beta) * R (Müller et al. 2005, §4.3).
    const float beta = this->Params.linearBlend;
    const float* Q = this->RestMomentInverse.data();
    for (int row = 0; row < 3; ++row)
    {
      for (int col = 0; col < 3; ++col)
      {
        const float linear =
          A[3 * row] * Q[col] + A[3 * row + 1] * Q[3 + col] + A[3 * row + 2] * Q[6 + col];
        R[3 * row + col] = beta * linear + (1.0f - beta) * R[3 * row + col];
      }
    }
  }
  const float k = this->Params.shapeStiffness;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->Pinned[i])
    {
      continue;
    }
    const auto& r = this->Shape.rest[i];
    const float q[3] = { size * r[0], size * r[1], size * r[2] };
    for (int row = 0; row < 3; ++row)
    {
      const float goal =
        c[row] + (R[3 * row] * q[0] + R[3 * row + 1] * q[1] + R[3 * row + 2] * q[2]);
      p[3 * i + row] += k * (goal - p[3 * i + row]);
    }
  }
}

void Engine::restore(float* p, float* scratch, float* orientation) const
{
  for (int it = 0; it < this->Params.iterations; ++it)
  {
    this->restoreOnce(p, scratch, orientation);
  }
}

std::size_t Engine::restorationScratchFloats() const
{
  // Jacobi's per-spring corrections.
  return 3 * this->Springs.size();
}

bool Engine::restoresElements() const
{
  return !this->Springs.empty() || this->Params.restoration == Restoration::ShapeMatching;
}

void Engine::restoreOnce(float* p, float* scratch, float* orientation) const
{
  const std::size_t n = this->Shape.particleCount();
  const Restoration method = this->Params.restoration;
  if (method == Restoration::ShapeMatching)
  {
    this->matchShape(p, orientation);
    return;
  }
  if (method == Restoration::GaussSeidel)
  {
    // Each spring moves its ends at once, so later springs see the update.
    for (const SpringWork& s : this->GaussSeidelSprings)
    {
      float c[3];
      if (springCorrection(p, s, c))
      {
        for (int k = 0; k < 3; ++k)
        {
          p[3 * s.a + k] += s.shareA * c[k];
          p[3 * s.b + k] -= s.shareB * c[k];
        }
      }
    }
    return;
  }
  // Jacobi: every spring sees the positions of the previous iteration. Each
  // particle's corrections are summed in spring order, as a per-particle
  // gather over a spring list sorted by index sums them. The corrections are
  // computed first, all independent, so their square roots and divisions
  // overlap; coincident ends give no direction to restore along, and none.
  const std::size_t springs = this->Springs.size();
  float* corrections = scratch;
  for (std::size_t k = 0; k < springs; ++k)
  {
    float* c = corrections + 3 * k;
    if (!springCorrection(p, this->Springs[k], c))
    {
      std::fill_n(c, 3, 0.0f);
    }
  }
  // Each particle gathers its springs' corrections in spring order, with the
  // signed share of its end, in registers.
  const bool averaged = method == Restoration::AveragedJacobi;
  const float w = this->Params.relaxation;
  for (std::size_t i = 0; i < n; ++i)
  {
    float sum[3] = { 0, 0, 0 };
    for (std::uint32_t j = this->IncidenceStart[i]; j < this->IncidenceStart[i + 1]; ++j)
    {
      const Incidence& in = this->Incidences[j];
      const float* c = corrections + 3 * in.spring;
      for (int k = 0; k < 3; ++k)
      {
        sum[k] += in.share * c[k];
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      p[3 * i + k] += averaged ? sum[k] * this->InverseDegree[i] : w * sum[k];
    }
  }
}

Engine::StepWeights Engine::beginStep(const VectorField& field, double t, double h)
{
  // After resetDue() (a distributed step) nothing is left to place; a hidden
  // element, due at every step, would otherwise be placed twice.
  const bool resets = !this->ResetsDone;
  this->ResetsDone = false;
  return { field.timeWeight(t), field.timeWeight(t + 0.5 * h), field.timeWeight(t + h),
    this->releasesAt(t, h), resets, inertiaStepOf(this->Params, h) };
}

void Engine::resetAndAdvect(std::size_t e, const VectorField& field, const StepWeights& weights,
  double h, float* before, float* advected, std::vector<InteractionEvent>* events)
{
  const std::size_t n = this->Shape.particleCount();
  if (weights.resets && (this->isDue(e)))
  {
    ++this->Generations[e];
    this->place(e, weights.releasing, { &field, weights.start });
  }
  else if (this->ResetFlags[e] & AlignPending)
  {
    this->alignToFlow(e, { &field, weights.start });
  }
  float* p = this->Positions.data() + 3 * e * n;
  std::copy_n(p, 3 * n, before);
  float* slips = this->Slips.empty() ? nullptr : this->Slips.data() + 3 * e * n;
  const bool walls = isWall(this->Params.boundary);
  const bool surfaceWalls = this->wallsParticlesOnSurfaces();
  // Stick holds a particle that lies on a side of the box: not advected.
  const bool stick = this->Params.boundary == Boundary::Stick;
  const Domain& box = this->domainOf(field);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->Pinned[i] ||
      (stick &&
        (onWall(box, p + 3 * i) ||
          onOutsideFace(field, weights.end, surfaceWallOffset(box), p + 3 * i))) ||
      (surfaceWalls && this->heldOnSurfaceWall(field, p + 3 * i)))
    {
      continue;
    }
    float* slip = slips ? slips + 3 * i : nullptr;
    if (slip)
    {
      this->advectHeavyParticle(field, weights, h, p + 3 * i, slip);
    }
    else
    {
      this->advectParticle(field, weights, h, p + 3 * i);
    }
    if (walls)
    {
      InteractionEvent met;
      if (this->wallParticle(field, weights, before + 3 * i, p + 3 * i, slip, met) && events)
      {
        met.element = this->Ids[e];
        met.particle = std::int32_t(i);
        met.kind = wallInteraction(this->Params.boundary);
        events->push_back(met);
      }
    }
    InteractionEvent hit; // at a Wall of the Surfaces (2.10), one event a step at most
    if (surfaceWalls &&
      this->wallParticleOnSurfaces(field, weights, before + 3 * i, p + 3 * i, slip, hit) &&
      events &&
      (events->empty() || events->back().particle != std::int32_t(i) ||
        events->back().element != this->Ids[e]))
    {
      hit.element = this->Ids[e];
      hit.particle = std::int32_t(i);
      events->push_back(hit);
    }
  }
  if (advected)
  {
    std::copy_n(p, 3 * n, advected);
  }
}

void Engine::stepElement(std::size_t e, const VectorField& field, const StepWeights& weights,
  double h, std::vector<float>& scratch, std::vector<InteractionEvent>& events)
{
  const std::size_t n = this->Shape.particleCount();
  float* before = scratch.data(); // positions before the step
  // Positions before restoration, for the forces; without restoration every
  // force stays 0 and nothing is kept.
  const bool restores = this->restoresElements();
  float* advected = restores ? scratch.data() + 3 * n : nullptr;
  const std::size_t first = events.size();
  this->resetAndAdvect(e, field, weights, h, before, advected, &events);
  if (restores)
  {
    this->restore(this->Positions.data() + 3 * e * n, scratch.data() + 6 * n,
      this->Orientations.data() + 4 * e);
    if (isWall(this->Params.boundary))
    {
      this->wallAfterRestoration(e, field, weights, before, advected, events, first);
    }
    if (this->wallsParticlesOnSurfaces())
    {
      this->keepOffSurfaceWalls(e, field, before, advected, events, first);
    }
  }
  this->settle(e, field, weights, h, before, advected, &events, first);
}

void Engine::settle(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
  const float* before, const float* advected, std::vector<InteractionEvent>* events,
  std::size_t first)
{
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  bool finite = true;
  float* force = this->Forces.data() + e * n;
  // Summed in float, particle by particle, as the GPU engine sums it.
  float c[3] = { 0, 0, 0 };
  bool anyOutside = false;
  const bool byParticle = this->Params.resetWhen == ResetWhen::AnyParticleLeaves;
  // An anchored element's particles are tested where anchoring puts them.
  const bool anchored = this->Params.anchor == Anchor::Centre;
  const bool testParticles = byParticle && !anchored;
  for (std::size_t i = 0; i < n; ++i)
  {
    const float* q = p + 3 * i;
    if (advected)
    {
      const float* a = advected + 3 * i;
      const float d[3] = { q[0] - a[0], q[1] - a[1], q[2] - a[2] };
      force[i] = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    finite = finite && finite3(q);
    for (int k = 0; k < 3; ++k)
    {
      c[k] += q[k];
    }
    anyOutside = anyOutside || (testParticles && !this->inDomain(field, q, weights.end));
  }
  float* slips = this->Slips.empty() ? nullptr : this->Slips.data() + 3 * e * n;
  if (slips && advected)
  {
    shareSlip(slips, n); // restored: the element moves as one body
  }
  bool leave = false, left = false; // due at once; out of the field (by resetWhen)
  float at[3] = { 0, 0, 0 }, moved[3] = { 0, 0, 0 }; // the centre tested; the particles' mean
  if (!finite)
  {
    // Keep the last good positions on view until the reset at the next step.
    std::copy_n(before, 3 * n, p);
    std::fill_n(force, n, 0.0f);
    if (slips)
    {
      std::fill_n(slips, 3 * n, 0.0f);
    }
    leave = true;
  }
  else
  {
    const float count = float(n);
    const float center[3] = { c[0] / count, c[1] / count, c[2] / count };
    std::copy_n(center, 3, at);
    std::copy_n(center, 3, moved);
    float wrapped[3];
    if (anchored)
    {
      std::copy_n(this->InitialCenters.data() + 3 * e, 3, at);
      anyOutside = this->anchor(e, field, weights, center, byParticle);
    }
    else if (this->wrapPeriodic(e, field, center, wrapped))
    {
      std::copy_n(wrapped, 3, at);
      anyOutside = this->anyOutside(e, field, weights, testParticles);
    }
    left = byParticle ? anyOutside : !this->inDomain(field, at, weights.end);
    // The release-speed test reads the centre the flow carried the element
    // to, before anchoring took it back (else every anchored release would
    // look stagnant) or a periodic side moved it by a period.
    leave = this->releasedStagnant(e, center, h);
  }
  if (this->Params.trackPoses)
  {
    this->updatePose(e, field, weights, h, finite);
  }
  this->flagAfterStep(
    e, field, h, before, finite ? moved : nullptr, at, leave, left, events, first);
  this->Lifetimes[e] -= float(h);
}

void Engine::flagAfterStep(std::size_t e, const VectorField& field, double h, const float* before,
  const float* moved, const float at[3], bool leave, bool left,
  std::vector<InteractionEvent>* events, std::size_t first)
{
  // A super set's element stays (and keeps its last good positions when they
  // turn non-finite): resetting it alone would tear the structure.
  // A hidden element stays hidden, and due (even in a super set, which is
  // released whole when the window opens).
  // Boundary::Terminate: one that left the field is hidden (Terminated)
  // until its lifetime runs out, and stays so whatever happens to it meanwhile.
  const std::uint8_t hidden = this->ResetFlags[e] & (ReleaseHidden | Terminated);
  // The Surfaces (2.10): the centre's step through gates and outlets; an
  // element that is not shown passes none.
  const std::uint8_t ended =
    this->Params.surfaces && moved && !leave && !hidden && this->Links.empty()
    ? this->passSurfaces(e, field, before, moved, events)
    : std::uint8_t(0);
  std::uint8_t flag = 0;
  if (this->Links.empty() && !(hidden & Terminated))
  {
    // A wall keeps the element in: it is never released again for leaving.
    // A surface that ends it (an Outlet, a Wall with Release Again or
    // Terminate) does so wherever it went on after.
    const bool walled = isWall(this->Params.boundary);
    const bool terminates = !leave &&
      (ended == Terminated || (!ended && left && this->Params.boundary == Boundary::Terminate));
    flag = terminates                                               ? Terminated
      : (leave || ended == ResetDue || (!ended && left && !walled)) ? ResetDue
                                                                    : 0;
  }
  if (events)
  {
    const bool leaving = left && flag && !isWall(this->Params.boundary) && !ended;
    this->noteEvents(e, field, h, before, hidden ? nullptr : moved, // hidden: none
      leaving ? at : nullptr, flag == Terminated, *events, first);
  }
  this->ResetFlags[e] = std::uint8_t(flag | hidden);
}

bool Engine::wrapPeriodic(
  std::size_t e, const VectorField& field, const float center[3], float wrapped[3])
{
  // An element whose centre left through a periodic side moves whole by
  // whole periods to the other side (Periodic.h): its shape is untouched.
  float shift[3];
  if (!this->seamShift(field, center, shift))
  {
    return false;
  }
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    p[i] += shift[i % 3];
  }
  for (int k = 0; k < 3; ++k)
  {
    wrapped[k] = center[k] + shift[k];
  }
  return true;
}

bool Engine::seamShift(const VectorField& field, const float center[3], float shift[3]) const
{
  const Domain& box = this->domainOf(field);
  bool moves = false;
  for (int a = 0; a < 3; ++a)
  {
    shift[a] = box.periodic[a] && !box.degenerate[a]
      ? periodicShift(center[a], box.lower[a], box.upper[a])
      : 0.0f;
    moves = moves || shift[a] != 0.0f;
  }
  return moves;
}

bool Engine::anyOutside(
  std::size_t e, const VectorField& field, const StepWeights& weights, bool testParticles) const
{
  if (!testParticles)
  {
    return false;
  }
  const std::size_t n = this->Shape.particleCount();
  const float* p = this->Positions.data() + 3 * e * n;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!this->inDomain(field, p + 3 * i, weights.end))
    {
      return true;
    }
  }
  return false;
}

bool Engine::anchor(std::size_t e, const VectorField& field, const StepWeights& weights,
  const float center[3], bool testParticles)
{
  // The whole element moved so that its particles' mean is back at its
  // release centre: it keeps the turn and the deformation of the step.
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  const float* a = this->InitialCenters.data() + 3 * e;
  const float shift[3] = { a[0] - center[0], a[1] - center[1], a[2] - center[2] };
  bool anyOutside = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    float* q = p + 3 * i;
    for (int k = 0; k < 3; ++k)
    {
      q[k] += shift[k];
    }
    anyOutside = anyOutside || (testParticles && !this->inDomain(field, q, weights.end));
  }
  return anyOutside;
}

void Engine::updatePose(
  std::size_t e, const VectorField& field, const StepWeights& weights, double h, bool finite)
{
  const std::size_t n = this->Shape.particleCount();
  float* spin = this->Spins.data() + 4 * e;
  if (!finite || n < 2)
  {
    // Back at the positions before the step (or no orientation): no turn.
    std::fill_n(spin, 4, 0.0f);
    return;
  }
  float* pose = this->Poses.data() + 4 * e;
  const float before[4] = { pose[0], pose[1], pose[2], pose[3] };
  float center[3];
  fitPose(this->Positions.data() + 3 * e * n, n, this->Shape.rest, this->Params.elementSize, pose,
    center);
  spinBetween(before, pose, float(h), spin);
  float velocity[3], curl[3];
  field.sampleWithCurl(center, weights.end, velocity, curl);
  spin[3] = spinVorticityRatio(spin, curl, float(h));
}

bool Engine::releasedStagnant(std::size_t e, const float c[3], double h) const
{
  const Parameters& P = this->Params;
  if (!(P.releaseMinSpeed > 0.0f) || !this->Links.empty())
  {
    return false;
  }
  // Slower than the minimum since its release (the cheap test first) ...
  const float* start = this->InitialCenters.data() + 3 * e;
  const float d[3] = { c[0] - start[0], c[1] - start[1], c[2] - start[2] };
  const float reach = P.releaseMinSpeed * float(h);
  if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < reach * reach))
  {
    return false;
  }
  // ... and in its first step: its lifetime is still the one drawn at its
  // placement (compared with half a step's slack, so that both engines'
  // roundings agree). A lattice's generation draws element 0's (lifetimeDraw).
  const float drawn = lifetimeDraw(P, this->Ids[e], this->Generations[e]);
  return drawn - this->Lifetimes[e] < 0.5f * float(h);
}

void Engine::step(const VectorField& field, double t, double h, const RangeRunner& run)
{
  if (!this->ResetsDone && recordsTrailAt(this->Params, t))
  {
    this->recordTrail(t); // resetDue() recorded it in a distributed step
  }
  if (!this->Links.empty())
  {
    this->stepLinked(field, t, h, run);
    return;
  }
  const std::size_t n = this->Shape.particleCount();
  const StepWeights weights = this->beginStep(field, t, h);
  const std::vector<std::uint32_t>& order = this->visitOrder(field);
  std::vector<InteractionEvent> stepEvents;
  std::mutex eventsLock;
  run(this->elementCount(),
    [&](std::size_t begin, std::size_t end)
    {
      // before + advected + restoration's scratch, per worker.
      std::vector<float> scratch(6 * n + this->restorationScratchFloats());
      std::vector<InteractionEvent> events; // this range's (Interactions.h)
      for (std::size_t k = begin; k < end; ++k)
      {
        if (!order.empty())
        {
          // In visiting order the elements' own state is scattered in memory:
          // fetch it ahead, while earlier elements sample the field.
          // Its positions, once there, say which grid cells it will sample:
          // fetch those a few elements later.
          constexpr std::size_t StateAhead = 16, FieldAhead = 6;
          if (k + StateAhead < end)
          {
            this->prefetchElement(order[k + StateAhead]);
          }
          if (k + FieldAhead < end)
          {
            const std::size_t next = order[k + FieldAhead];
            const float* q = this->Positions.data() + 3 * next * n;
            for (std::size_t i = 0; i < n; ++i)
            {
              field.prefetch(q + 3 * i);
            }
          }
          this->stepElement(order[k], field, weights, h, scratch, events);
        }
        else
        {
          this->stepElement(k, field, weights, h, scratch, events);
        }
      }
      if (!events.empty())
      {
        const std::lock_guard<std::mutex> hold(eventsLock);
        stepEvents.insert(stepEvents.end(), events.begin(), events.end());
      }
    });
  this->keepInteractions(std::move(stepEvents), t, h);
}

void Engine::prefetchElement(std::size_t e) const
{
#if defined(__GNUC__)
  const std::size_t n = this->Shape.particleCount();
  constexpr std::size_t Line = 64;
  __builtin_prefetch(this->ResetFlags.data() + e);
  __builtin_prefetch(this->Lifetimes.data() + e, 1);
  const char* positions = reinterpret_cast<const char*>(this->Positions.data() + 3 * e * n);
  for (std::size_t b = 0; b < 12 * n; b += Line)
  {
    __builtin_prefetch(positions + b, 1);
  }
  if (!this->Slips.empty())
  {
    // Heavy particles: the slips are read and written with the positions.
    const char* slips = reinterpret_cast<const char*>(this->Slips.data() + 3 * e * n);
    for (std::size_t b = 0; b < 12 * n; b += Line)
    {
      __builtin_prefetch(slips + b, 1);
    }
  }
  if (this->restoresElements())
  {
    const char* forces = reinterpret_cast<const char*>(this->Forces.data() + e * n);
    for (std::size_t b = 0; b < 4 * n; b += Line)
    {
      __builtin_prefetch(forces + b, 1);
    }
  }
#else
  (void)e;
#endif
}

} // namespace bp
