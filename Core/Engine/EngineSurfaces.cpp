// SPDX-License-Identifier: BSD-3-Clause
// The Surfaces in a step of the CPU engine (Surfaces.h; engine specification
// 2.10): an element's centre passing gates, outlets and element-level walls,
// and each particle kept off the Walls with Stick, Slip or Bounce; called from the
// step in EngineStep.cpp.
#include "Engine.h"
#include "Surfaces.h"

#include <algorithm>
#include <cmath>

namespace bp
{

namespace
{
inline float dot3(const float* a, const float* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The crossing's normal turned to the side its step came from.
std::array<float, 3> towardStart(const SurfaceCrossing& c)
{
  const float s = c.direction > 0 ? -1.0f : 1.0f;
  return { s * c.normal[0], s * c.normal[1], s * c.normal[2] };
}

/// p put `offset` off the crossing's plane on its step's side, along m.
void putOff(const SurfaceCrossing& c, const std::array<float, 3>& m, float offset, float p[3])
{
  for (int k = 0; k < 3; ++k)
  {
    p[k] = c.point[std::size_t(k)] + offset * m[std::size_t(k)];
  }
}

/// The event of a particle that met a Wall at crossing c.
InteractionEvent wallEvent(const SurfaceSet& surfaces, const SurfaceCrossing& c, Boundary b)
{
  InteractionEvent met;
  met.kind = wallInteraction(b);
  met.side = FirstSurfaceId + c.surface;
  met.cell = surfaces.cell(c.triangle);
  met.position = c.point;
  met.normal = c.normal;
  return met;
}

/// The Wall the move start -> p crosses, where a rule left p (Slip, Bounce).
/// Where the step met the Wall at an edge it shares with another (a box's
/// edge, an inward bend), start, an offset off the first, lies on the
/// other's plane or just behind it, and the move from there meets it at
/// t = 0 or not at all: where the move from start meets none, it is tested
/// again from half an offset behind start (as the step is from before its
/// start), and a crossing found so is taken only where before, the
/// particle's position before the step, lies on the side the rule keeps p.
bool wallAgain(const SurfaceSet& surfaces, const float before[3], const float start[3],
  const float p[3], float offset, SurfaceCrossing& again)
{
  if (surfaces.wallCrossing(start, p, again))
  {
    return true;
  }
  const float d[3] = { p[0] - start[0], p[1] - start[1], p[2] - start[2] };
  const float length = std::sqrt(dot3(d, d));
  if (!(length > 0.0f))
  {
    return false;
  }
  const float back = 0.5f * offset / length;
  const float from[3] = { start[0] - back * d[0], start[1] - back * d[1], start[2] - back * d[2] };
  if (!surfaces.wallCrossing(from, p, again))
  {
    return false;
  }
  const std::array<float, 3> m = towardStart(again);
  return dot3(before, m.data()) - dot3(again.point.data(), m.data()) > 0.0f;
}

/// Last (Slip, Bounce, and a restored particle put off a Wall): p must be
/// reached from before without crossing a Wall. At an edge sharper than a
/// right angle a point c + offset m may lie behind the other Wall, where no
/// move from it meets that Wall; where the segment before -> p crosses one,
/// p goes back along it to an offset short of that crossing (before itself
/// where that is closer).
void keptOnSide(const SurfaceSet& surfaces, const float before[3], float offset, float p[3])
{
  SurfaceCrossing c;
  if (!surfaces.wallCrossing(before, p, c))
  {
    return;
  }
  const float back[3] = { before[0] - c.point[0], before[1] - c.point[1], before[2] - c.point[2] };
  const float length = std::sqrt(dot3(back, back));
  const float share = length > offset ? offset / length : 1.0f;
  for (int k = 0; k < 3; ++k)
  {
    p[k] = c.point[std::size_t(k)] + share * back[k];
  }
}
} // namespace

std::uint8_t Engine::passSurfaces(std::size_t e, const VectorField& field, const float* before,
  const float center[3], std::vector<InteractionEvent>* events) const
{
  const SurfaceSet& surfaces = *this->Params.surfaces;
  const Boundary boundary = this->Params.boundary;
  // With Release Again or Terminate a Wall acts on the element as the
  // field's sides do; with Stick, Slip or Bounce on its particles (not here).
  const bool wallsEnd = !isWall(boundary);
  float from[3];
  particleMean(before, this->Shape.particleCount(), from);
  thread_local std::vector<SurfaceCrossing> crossings;
  // A centre past a periodic side, that wrapPeriodic moves by whole periods
  // after (an anchored element is moved back instead): the step is tested
  // across the seam too (2.8, 2.10).
  float seam[3] = { 0, 0, 0 };
  const bool wraps = this->Params.anchor != Anchor::Centre && this->seamShift(field, center, seam);
  const bool ends = surfaces.passages(from, center, wallsEnd, crossings,
    wraps ? &this->domainOf(field) : nullptr, wraps ? seam : nullptr);
  std::uint8_t flag = 0;
  for (const SurfaceCrossing& c : crossings)
  {
    const SurfaceInteraction kind = surfaces.interaction(c.triangle);
    const bool released = kind == SurfaceInteraction::Wall && boundary == Boundary::ReleaseAgain;
    flag = kind == SurfaceInteraction::Gate ? flag : released ? ResetDue : Terminated;
    if (!events)
    {
      continue;
    }
    InteractionEvent passed;
    passed.time = c.t; // the share of the step; keepInteractions makes it a time
    passed.element = this->Ids[e];
    passed.particle = -1;
    passed.kind = kind == SurfaceInteraction::Gate ? Interaction::Passed
      : released                                   ? Interaction::Released
                                                   : Interaction::Terminated;
    passed.side = FirstSurfaceId + c.surface;
    passed.cell = surfaces.cell(c.triangle);
    passed.position = c.point;
    passed.normal = c.normal;
    events->push_back(passed);
  }
  return ends ? flag : std::uint8_t(0);
}

float Engine::restingOnWall(float offset) const
{
  // Within two offsets of the wall on its side: where a step or the
  // restoration before put it. A particle the springs lift farther off,
  // that the flow brings back, meets the wall again, as at the field's sides.
  return 2.0f * offset;
}

bool Engine::wallsParticlesOnSurfaces() const
{
  return this->Params.surfaces && this->Params.surfaces->hasWalls() &&
    isWall(this->Params.boundary);
}

bool Engine::heldOnSurfaceWall(const VectorField& field, const float p[3]) const
{
  // As on the field's sides, held is a property of the position: a particle
  // within two offsets of a Wall (where a step put it) stays.
  return this->Params.boundary == Boundary::Stick && this->wallsParticlesOnSurfaces() &&
    this->Params.surfaces->onWall(p, this->restingOnWall(surfaceWallOffset(this->domainOf(field))));
}

bool Engine::wallParticleOnSurfaces(const VectorField& field, const StepWeights& weights,
  const float before[3], float p[3], float* slip, InteractionEvent& met) const
{
  const SurfaceSet& surfaces = *this->Params.surfaces;
  const float offset = surfaceWallOffset(this->domainOf(field));
  // The step is tested from half an offset behind its start, so that a
  // particle that starts on a Wall's plane (a seed on it) meets it too: one
  // a rule put there lies a whole offset off it, on its side.
  const float d[3] = { p[0] - before[0], p[1] - before[1], p[2] - before[2] };
  const float length = std::sqrt(dot3(d, d));
  if (!(length > 0.0f))
  {
    return false; // not moved, or not finite (settle takes the step back)
  }
  const float back = 0.5f * offset / length;
  const float from[3] = { before[0] - back * d[0], before[1] - back * d[1],
    before[2] - back * d[2] };
  SurfaceCrossing c;
  if (!surfaces.wallCrossing(from, p, c))
  {
    return false;
  }
  const Boundary rule = this->Params.boundary;
  const std::array<float, 3> m = towardStart(c);
  this->wallRule(c, offset, p);
  if (rule != Boundary::Stick)
  {
    // Put on one plane or reflected off it, p may lie behind another Wall
    // where the walls bend inward (a corner, a pipe of flat facets, the
    // edge the step went through): the rule again on each Wall the move
    // from the wall crosses (wallAgain); after four, the particle stays
    // where that move first meets a Wall.
    float start[3];
    putOff(c, m, offset, start);
    for (int pass = 0; pass < 4; ++pass)
    {
      SurfaceCrossing again;
      if (!wallAgain(surfaces, before, start, p, offset, again))
      {
        break;
      }
      if (pass == 3)
      {
        putOff(again, towardStart(again), offset, p);
        break;
      }
      this->wallRule(again, offset, p);
      putOff(again, towardStart(again), offset, start);
    }
    keptOnSide(surfaces, before, offset, p);
  }
  if (slip)
  {
    this->wallSlip(field, weights, m, p, slip);
  }
  if (dot3(before, m.data()) - dot3(c.point.data(), m.data()) <= this->restingOnWall(offset))
  {
    return false; // it lay on the wall before the step: it slides along it
  }
  met = wallEvent(surfaces, c, rule);
  return true;
}

void Engine::wallRule(const SurfaceCrossing& c, float offset, float p[3]) const
{
  const std::array<float, 3> m = towardStart(c);
  if (this->Params.boundary == Boundary::Stick)
  {
    putOff(c, m, offset, p); // where the step met the wall (held there from then on)
    return;
  }
  // How far p lies beyond the plane (negative along m): Slip takes that
  // back (the tangential step kept), Bounce (1 + e) times it.
  const float d[3] = { p[0] - c.point[0], p[1] - c.point[1], p[2] - c.point[2] };
  const float beyond = dot3(d, m.data());
  const float e = this->Params.restitution;
  const float back = (this->Params.boundary == Boundary::Bounce ? 1.0f + e : 1.0f) * beyond;
  for (int k = 0; k < 3; ++k)
  {
    p[k] += (offset - back) * m[std::size_t(k)];
  }
}

void Engine::wallSlip(const VectorField& field, const StepWeights& weights,
  const std::array<float, 3>& m, const float p[3], float* slip) const
{
  // The rule on the heavy particle's velocity v = u + slip, u the flow where
  // the wall leaves it at the step's end: stopped (Stick), the normal
  // component into the wall removed (Slip) or reversed times e (Bounce).
  const Boundary rule = this->Params.boundary;
  float u[3];
  field.sampleWeighted(p, weights.end, u);
  const float v[3] = { u[0] + slip[0], u[1] + slip[1], u[2] + slip[2] };
  const float into = dot3(v, m.data());
  const float e = this->Params.restitution;
  const float turn = into < 0.0f ? (rule == Boundary::Bounce ? 1.0f + e : 1.0f) * into : 0.0f;
  for (int k = 0; k < 3; ++k)
  {
    slip[k] = (rule == Boundary::Stick ? 0.0f : v[k] - turn * m[std::size_t(k)]) - u[k];
  }
}

void Engine::keepOffSurfaceWalls(std::size_t e, const VectorField& field, const float* before,
  const float* advected, std::vector<InteractionEvent>& events, std::size_t first)
{
  const SurfaceSet& surfaces = *this->Params.surfaces;
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  const float offset = surfaceWallOffset(this->domainOf(field));
  const std::size_t stepEvents = events.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->heldOnSurfaceWall(field, advected + 3 * i))
    {
      std::copy_n(advected + 3 * i, 3, p + 3 * i); // held (Stick)
      continue;
    }
    SurfaceCrossing c;
    if (!surfaces.wallCrossing(advected + 3 * i, p + 3 * i, c))
    {
      continue;
    }
    const std::array<float, 3> m = towardStart(c);
    putOff(c, m, offset, p + 3 * i);
    keptOnSide(surfaces, advected + 3 * i, offset, p + 3 * i);
    const float* b = before + 3 * i;
    const float from = dot3(b, m.data()) - dot3(c.point.data(), m.data());
    const auto already = std::find_if(events.begin() + std::ptrdiff_t(first),
      events.begin() + std::ptrdiff_t(stepEvents),
      [i](const InteractionEvent& x) { return x.particle == std::int32_t(i); });
    if (from > this->restingOnWall(offset) &&
      already == events.begin() + std::ptrdiff_t(stepEvents))
    {
      InteractionEvent put = wallEvent(surfaces, c, this->Params.boundary);
      put.element = this->Ids[e];
      put.particle = std::int32_t(i);
      events.push_back(put);
    }
  }
}

} // namespace bp
