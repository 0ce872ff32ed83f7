// SPDX-License-Identifier: BSD-3-Clause
#include "Interactions.h"

#include <algorithm>
#include <tuple>

namespace bp
{

Interaction wallInteraction(Boundary b)
{
  return b == Boundary::Stick ? Interaction::Stuck
    : b == Boundary::Slip     ? Interaction::Slid
                              : Interaction::Bounced;
}

std::array<float, 3> sideNormal(int side)
{
  std::array<float, 3> n = { 0, 0, 0 };
  if (side >= 0 && side < 6)
  {
    n[std::size_t(side / 2)] = side % 2 ? 1.0f : -1.0f;
  }
  return n;
}

int lowestSide(WallHits hits)
{
  for (int s = 0; s < 6; ++s)
  {
    if (hits & (1u << s))
    {
      return s;
    }
  }
  return NoSide;
}

WallHits sidesOn(const Domain& box, const float p[3])
{
  WallHits on = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (box.bounded(a))
    {
      on |= p[a] == box.lower[a] ? 1u << (2 * a) : 0u;
      on |= p[a] == box.upper[a] ? 1u << (2 * a + 1) : 0u;
    }
  }
  return on;
}

WallHits sidesBeyond(const Domain& box, const float p[3])
{
  WallHits beyond = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (box.bounded(a))
    {
      beyond |= p[a] < box.lower[a] ? 1u << (2 * a) : 0u;
      beyond |= p[a] > box.upper[a] ? 1u << (2 * a + 1) : 0u;
    }
  }
  return beyond;
}

int firstContact(const Domain& box, const float before[3], const float advected[3], float point[3])
{
  const WallHits beyond = sidesBeyond(box, advected) & ~sidesOn(box, before);
  if (!beyond)
  {
    return NoSide;
  }
  if (!box.contains(before))
  {
    std::copy_n(advected, 3, point);
    clampToBox(box, point);
    return lowestSide(beyond);
  }
  // The fraction of the step at which each side crossed is met; the
  // smallest wins (the lowest side on a tie). There advected != before.
  int side = NoSide;
  float first = 0.0f;
  for (int s = 0; s < 6; ++s)
  {
    if (!(beyond & (1u << s)))
    {
      continue;
    }
    const int a = s / 2;
    const float w = s % 2 ? box.upper[a] : box.lower[a];
    const float t = (w - before[a]) / (advected[a] - before[a]);
    if (side == NoSide || t < first)
    {
      side = s;
      first = t;
    }
  }
  const int axis = side / 2;
  for (int a = 0; a < 3; ++a)
  {
    point[a] = before[a] + first * (advected[a] - before[a]);
  }
  point[axis] = side % 2 ? box.upper[axis] : box.lower[axis];
  clampToBox(box, point);
  return side;
}

bool interactionBefore(const InteractionEvent& a, const InteractionEvent& b)
{
  return std::make_tuple(a.time, a.element, a.particle, std::int8_t(a.kind)) <
    std::make_tuple(b.time, b.element, b.particle, std::int8_t(b.kind));
}

InteractionLog::Step::~Step()
{
  // Each step holds the one before: a long trace's list would otherwise be
  // freed by a recursion as deep as its steps.
  std::shared_ptr<const Step> next = std::move(const_cast<Step*>(this)->previous);
  while (next && next.use_count() == 1)
  {
    std::shared_ptr<const Step> after = std::move(const_cast<Step&>(*next).previous);
    next = std::move(after);
  }
}

void InteractionLog::append(std::vector<InteractionEvent>&& step)
{
  const std::size_t room = this->Capacity - std::min(this->Capacity, this->size());
  const bool leavesOut = step.size() > room;
  if (step.empty() || (this->full() && leavesOut))
  {
    return; // nothing new: no events, or a full log that stays full
  }
  if (leavesOut)
  {
    step.resize(room); // the first of the step's events, in its order
  }
  auto added = std::make_shared<Step>();
  added->total = this->size() + step.size();
  added->full = this->full() || leavesOut;
  added->events = std::move(step);
  added->previous = this->Head;
  this->Head = std::move(added);
}

std::vector<InteractionEvent> InteractionLog::events() const
{
  std::vector<const Step*> steps;
  for (const Step* s = this->Head.get(); s; s = s->previous.get())
  {
    steps.push_back(s);
  }
  std::vector<InteractionEvent> all;
  all.reserve(this->size());
  for (auto s = steps.rbegin(); s != steps.rend(); ++s)
  {
    all.insert(all.end(), (*s)->events.begin(), (*s)->events.end());
  }
  return all;
}

InteractionLog::Mark InteractionLog::mark() const
{
  Mark m;
  m.Head = this->Head;
  m.Size = this->size();
  return m;
}

std::size_t InteractionLog::eventsSince(const Mark& m, std::vector<InteractionEvent>& added) const
{
  added.clear();
  // Back from both heads to the last step both hold: the totals grow along
  // each list (no step is empty), so the one with more events steps back.
  const Step* mine = this->Head.get();
  const Step* theirs = static_cast<const Step*>(m.Head.get());
  std::vector<const Step*> steps;
  while (mine != theirs)
  {
    const std::size_t a = mine ? mine->total : 0;
    const std::size_t b = theirs ? theirs->total : 0;
    if (a >= b)
    {
      steps.push_back(mine);
      mine = mine->previous.get();
    }
    if (b >= a)
    {
      theirs = theirs->previous.get();
    }
  }
  const std::size_t shared = mine ? mine->total : 0;
  added.reserve(this->size() - shared);
  for (auto t = steps.rbegin(); t != steps.rend(); ++t)
  {
    added.insert(added.end(), (*t)->events.begin(), (*t)->events.end());
  }
  return shared;
}

} // namespace bp
