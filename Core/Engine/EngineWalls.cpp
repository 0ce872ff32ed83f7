// SPDX-License-Identifier: BSD-3-Clause
// The walls in a step of the CPU engine (Walls.h; engine specification 2.8,
// "Walls") and the events at the field's sides it records (Interactions.h,
// 2.9): called from the step in EngineStep.cpp.
#include "Engine.h"
#include "MaskWalls.h"
#include "Surfaces.h"

#include <algorithm>
#include <cmath>

namespace bp
{

namespace
{
inline bool finite3(const float* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

} // namespace

bool Engine::wallParticle(const VectorField& field, const StepWeights& weights,
  const float before[3], float p[3], float* slip, InteractionEvent& met) const
{
  if (!finite3(p))
  {
    return false; // settle() takes the element back to its positions before the step
  }
  const Parameters& P = this->Params;
  const Domain& box = this->domainOf(field);
  met.side = firstContact(box, before, p, met.position.data());
  bool event = met.side != NoSide;
  if (event)
  {
    met.normal = sideNormal(met.side);
  }
  WallHits hits = wallAfterAdvection(P.boundary, P.restitution, box, before, p);
  if (field.hasOutsideCells())
  {
    // The faces of the cells outside the flow (MaskWalls.h); where none is
    // found, back to before the step, and a heavy particle stops there.
    const float offset = surfaceWallOffset(box);
    MaskFace face;
    const WallHits faces =
      wallOnOutsideCells(P.boundary, P.restitution, offset, field, weights.end, before, p, face);
    if (faces & WallMaskedCell)
    {
      event = false;
    }
    else if (faces && !event && !onOutsideFace(field, weights.end, offset, before))
    {
      event = true; // reaching the face: its outward normal, no side
      met.side = NoSide;
      std::copy_n(face.point, 3, met.position.data());
      met.normal = { 0.0f, 0.0f, 0.0f };
      met.normal[std::size_t(face.axis)] = -face.toward;
    }
    hits |= faces;
  }
  if (slip && hits)
  {
    // The rule acts on the particle's velocity v = u + slip, u the flow
    // where the wall leaves it at the step's end.
    const bool masked = hits & WallMaskedCell;
    float u[3];
    field.sampleWeighted(p, weights.end, u);
    float v[3] = { u[0] + slip[0], u[1] + slip[1], u[2] + slip[2] };
    wallVelocity(masked ? Boundary::Stick : P.boundary, P.restitution, hits, v);
    for (int k = 0; k < 3; ++k)
    {
      slip[k] = v[k] - u[k];
    }
  }
  return event;
}

void Engine::wallAfterRestoration(std::size_t e, const VectorField& field,
  const StepWeights& weights, const float* before, const float* advected,
  std::vector<InteractionEvent>& events, std::size_t first)
{
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  const Domain& box = this->domainOf(field);
  const bool stick = this->Params.boundary == Boundary::Stick;
  const float offset = surfaceWallOffset(box);
  const std::size_t advectionEvents = events.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    float* q = p + 3 * i;
    const float* a = advected + 3 * i;
    if (stick && (onWall(box, a) || onOutsideFace(field, weights.end, offset, a)))
    {
      std::copy_n(a, 3, q); // held
      continue;
    }
    const WallHits hits = clampToBox(box, q);
    // Pushed into a cell outside the flow: Slip's rule on the faces from
    // the advected position (back there where none is found).
    MaskFace face;
    const WallHits faces = finite3(q) && field.hasOutsideCells()
      ? wallOnOutsideCells(Boundary::Slip, 0.0f, offset, field, weights.end, a, q, face)
      : 0;
    const WallHits met = faces & WallMaskedCell ? 0 : hits & ~sidesOn(box, before + 3 * i);
    const bool metFace = !(faces & WallMaskedCell) && faces && !met &&
      !onOutsideFace(field, weights.end, offset, before + 3 * i);
    if (!met && !metFace)
    {
      continue;
    }
    const auto already = std::find_if(events.begin() + std::ptrdiff_t(first),
      events.begin() + std::ptrdiff_t(advectionEvents),
      [i](const InteractionEvent& x) { return x.particle == std::int32_t(i); });
    if (already == events.begin() + std::ptrdiff_t(advectionEvents))
    {
      InteractionEvent put;
      put.element = this->Ids[e];
      put.particle = std::int32_t(i);
      put.kind = wallInteraction(this->Params.boundary);
      put.side = met ? lowestSide(met) : NoSide;
      put.normal = met ? sideNormal(put.side) : std::array<float, 3>{ 0.0f, 0.0f, 0.0f };
      if (!met)
      {
        put.normal[std::size_t(face.axis)] = -face.toward;
      }
      std::copy_n(met ? q : face.point, 3, put.position.data());
      events.push_back(put);
    }
  }
}

void Engine::recordLeaving(std::size_t e, const VectorField& field, const float at[3],
  bool terminated, std::vector<InteractionEvent>& events) const
{
  const Domain& box = this->domainOf(field);
  WallHits beyond = sidesBeyond(box, at);
  const std::size_t n = this->Shape.particleCount();
  const float* p = this->Positions.data() + 3 * e * n;
  for (std::size_t i = 0; i < n && !beyond; ++i)
  {
    beyond = sidesBeyond(box, p + 3 * i);
  }
  InteractionEvent left;
  left.element = this->Ids[e];
  left.particle = -1;
  left.kind = terminated ? Interaction::Terminated : Interaction::Released;
  left.side = lowestSide(beyond);
  left.normal = sideNormal(left.side);
  std::copy_n(at, 3, left.position.data());
  events.push_back(left);
}

void Engine::fillVelocity(const float* before, const float center[3], double h,
  std::vector<InteractionEvent>& events, std::size_t first) const
{
  float c[3];
  particleMean(before, this->Shape.particleCount(), c);
  std::array<float, 3> velocity;
  for (int k = 0; k < 3; ++k)
  {
    velocity[std::size_t(k)] = float((double(center[k]) - double(c[k])) / h);
  }
  for (std::size_t k = first; k < events.size(); ++k)
  {
    events[k].velocity = velocity;
  }
}

void Engine::noteEvents(std::size_t e, const VectorField& field, double h, const float* before,
  const float* moved, const float* leftAt, bool terminated, std::vector<InteractionEvent>& events,
  std::size_t first) const
{
  if (!moved)
  {
    events.resize(first); // the step is taken back: nothing happened
    return;
  }
  if (leftAt)
  {
    this->recordLeaving(e, field, leftAt, terminated, events);
  }
  if (events.size() > first)
  {
    this->fillVelocity(before, moved, h, events, first);
  }
}

void Engine::keepInteractions(std::vector<InteractionEvent>&& events, double t, double h)
{
  for (InteractionEvent& event : events)
  {
    // The share of the step it happened at (1: its end, t + h as such).
    event.time = event.time == 1.0 ? t + h : t + event.time * h;
  }
  std::sort(events.begin(), events.end(), interactionBefore);
  this->Log.append(std::move(events));
}

} // namespace bp
