// SPDX-License-Identifier: BSD-3-Clause
// The walls in a step of the CPU engine (Walls.h; engine specification 2.8,
// "Walls") and the events at the field's sides it records (Interactions.h,
// 2.9): called from the step in EngineStep.cpp.
#include "Engine.h"

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

int Engine::wallParticle(const VectorField& field, const StepWeights& weights,
  const float before[3], float p[3], float* slip, float contact[3]) const
{
  if (!finite3(p))
  {
    return NoSide; // settle() takes the element back to its positions before the step
  }
  const Parameters& P = this->Params;
  const Domain& box = this->domainOf(field);
  int side = firstContact(box, before, p, contact);
  const WallHits hits = wallAfterAdvection(P.boundary, P.restitution, box, before, p);
  // A cell outside the flow has no normal: the particle goes back to where
  // it was before the step, and a heavy one stops there.
  const bool masked = field.outsideCellAt(p, weights.end);
  if (masked)
  {
    std::copy_n(before, 3, p);
    side = NoSide;
  }
  if (slip && (hits || masked))
  {
    // The rule acts on the particle's velocity v = u + slip, u the flow
    // where the wall leaves it at the step's end.
    float u[3];
    field.sampleWeighted(p, weights.end, u);
    float v[3] = { u[0] + slip[0], u[1] + slip[1], u[2] + slip[2] };
    wallVelocity(masked ? Boundary::Stick : P.boundary, P.restitution, masked ? 1u : hits, v);
    for (int k = 0; k < 3; ++k)
    {
      slip[k] = v[k] - u[k];
    }
  }
  return side;
}

void Engine::wallAfterRestoration(std::size_t e, const VectorField& field,
  const StepWeights& weights, const float* before, const float* advected,
  std::vector<InteractionEvent>& events, std::size_t first)
{
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  const Domain& box = this->domainOf(field);
  const bool stick = this->Params.boundary == Boundary::Stick;
  const std::size_t advectionEvents = events.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    float* q = p + 3 * i;
    const float* a = advected + 3 * i;
    if (stick && onWall(box, a))
    {
      std::copy_n(a, 3, q); // held
      continue;
    }
    const WallHits hits = clampToBox(box, q);
    if (finite3(q) && field.outsideCellAt(q, weights.end))
    {
      std::copy_n(a, 3, q);
      continue;
    }
    const WallHits met = hits & ~sidesOn(box, before + 3 * i);
    if (!met)
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
      put.side = lowestSide(met);
      put.normal = sideNormal(put.side);
      std::copy_n(q, 3, put.position.data());
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
