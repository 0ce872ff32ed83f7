// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Interactions.h
 * @brief What the elements did at the field's sides (engine specification
 * 2.9, "Interactions"): one event per particle that meets a wall it did
 * not lie on before the step (Stick, Slip, Bounce), one per element that
 * leaves the field (Release Again, Terminate), and one per passage of an
 * element through a surface of the Surfaces input (2.10: Gate, Outlet). The CPU engine records them
 * as it steps (Engine::interactions()); the tracer's Interactions output
 * shows them. The GPU engine drives a display only and records none.
 *
 * The record of a trace is a persistent list of steps (InteractionLog): a
 * copy of the engine (a short step's save, a checkpoint) shares what both
 * hold, so going back to a copy gives back the events of its time, and a
 * copy costs a pointer.
 */
#ifndef BoundParticles_Interactions_h
#define BoundParticles_Interactions_h

#include "VectorField.h"
#include "Walls.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace bp
{

/// What happened: an element that left the field and was released again
/// (Release Again) or ended (Terminate, or an Outlet surface); a particle
/// held on a wall (Stick), put on it to slide (Slip), or reflected
/// (Bounce); an element that passed a Gate surface (2.10).
enum class Interaction : std::int8_t
{
  Released = 0,
  Terminated,
  Stuck,
  Slid,
  Bounced,
  Passed
};
/// The names, in the enumeration's order (the output's legend).
constexpr const char* InteractionNames[] = { "Released", "Terminated", "Stuck", "Slid", "Bounced",
  "Passed" };
constexpr int InteractionCount = 6;

/// A particle's event by Boundary `b` (Stick, Slip or Bounce).
Interaction wallInteraction(Boundary b);

/// The side ids: the box's sides 0..5 = -x, +x, -y, +y, -z, +z (the bit of
/// WallHits they stand for); NoSide for none (an element that left into a
/// cell outside the flow). Ids from FirstSurfaceId up are the Surfaces
/// input's surfaces (FirstSurfaceId + its block's index).
constexpr int NoSide = -1;
constexpr int FirstSurfaceId = 6;
/// The outward normal of side `side` (0 for NoSide).
std::array<float, 3> sideNormal(int side);
/// The lowest side among `hits` (NoSide for none).
int lowestSide(WallHits hits);
/// The sides of `box` p lies on exactly (along axes that are not flat or periodic).
WallHits sidesOn(const Domain& box, const float p[3]);
/// The sides of `box` p lies beyond.
WallHits sidesBeyond(const Domain& box, const float p[3]);

/**
 * Where a particle's step from `before` to `advected` (before any wall)
 * first meets a side it did not lie on at `before`: the side, and in
 * `point` the point of the segment on it (the side's coordinate exactly,
 * the others clamped into the box), as Stick places a particle. From a
 * `before` outside the box (released across a side), `advected` clamped
 * and the lowest side it lies beyond. NoSide where the step meets none.
 */
int firstContact(const Domain& box, const float before[3], const float advected[3], float point[3]);

/// One event.
struct InteractionEvent
{
  /// Trace time: the end of the step it happened in, or for a surface's
  /// passage the time it crossed. Within a step (until Engine::keepInteractions)
  /// the share of the step at which it happened, 1 for its end.
  double time = 1.0;
  std::uint32_t element = 0;  ///< the element's global id
  std::int32_t particle = -1; ///< its particle, -1 for the whole element
  Interaction kind = Interaction::Released;
  std::int32_t side = NoSide;                  ///< sideNormal's id, or a surface's
  std::int32_t cell = -1;                      ///< the Surfaces input's cell, -1 for a side
  std::array<float, 3> position = { 0, 0, 0 }; ///< engine coordinates
  std::array<float, 3> velocity = { 0, 0, 0 }; ///< the element's mean over the step
  std::array<float, 3> normal = { 0, 0, 0 };   ///< the side's outward or the surface's normal
};

/// The output's order: (time, element, particle, kind).
bool interactionBefore(const InteractionEvent& a, const InteractionEvent& b);

/**
 * A trace's events, step by step: a persistent list whose copies share the
 * steps they have in common (append() adds a step to this copy only).
 */
class InteractionLog
{
public:
  /// The events a log keeps at most by default (about 490 MiB): a long trace
  /// of many elements whose every step leaves events (Release Again in an
  /// outflow) would otherwise take memory without end.
  static constexpr std::size_t DefaultCapacity = 8000000;

  /// Adds one step's events (nothing for none); past the capacity, only
  /// those that fit, and the log is full() from then on.
  void append(std::vector<InteractionEvent>&& step);
  /// Every event, oldest step first.
  std::vector<InteractionEvent> events() const;

  /// Where a log stood (mark()): for eventsSince. It holds that log's steps
  /// (shared with the log while it has them).
  class Mark
  {
  public:
    /// How many events the log held.
    std::size_t size() const { return this->Size; }

  private:
    friend class InteractionLog;
    std::shared_ptr<const void> Head;
    std::size_t Size = 0;
  };
  Mark mark() const;
  /// How many of `m`'s first events this log holds too (those of the last
  /// step both share, m.size() where this log is m's with steps appended,
  /// fewer for a copy gone back in time or one that went another way), and
  /// in `added` this log's events after them, oldest first. The cost is in
  /// the steps after that shared step only. A default Mark shares nothing.
  std::size_t eventsSince(const Mark& m, std::vector<InteractionEvent>& added) const;
  /// How many events.
  std::size_t size() const { return this->Head ? this->Head->total : 0; }
  /// Whether a step's events were left out for the capacity.
  bool full() const { return this->Head && this->Head->full; }
  void clear() { this->Head.reset(); }
  /// At most this many events (kept by copies; for tests, a small one).
  void setCapacity(std::size_t events) { this->Capacity = events; }
  std::size_t capacity() const { return this->Capacity; }

private:
  struct Step
  {
    std::vector<InteractionEvent> events;
    std::shared_ptr<const Step> previous;
    std::size_t total = 0; ///< events in this step and every one before
    bool full = false;     ///< events of this step or one before were left out
    Step() = default;
    Step(const Step&) = delete;
    Step& operator=(const Step&) = delete;
    /// Unlinks the steps no other copy holds one by one (no deep recursion).
    ~Step();
  };
  std::shared_ptr<const Step> Head;
  std::size_t Capacity = DefaultCapacity;
};

} // namespace bp

#endif
