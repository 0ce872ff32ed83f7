// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Checkpoints.h
 * @brief How often a trace keeps a copy of its whole state (CheckpointSpacing)
 * and which copies it holds (CheckpointIndex), so that a request for an
 * earlier time resumes from the nearest copy at or before it instead of
 * replaying from the start.
 *
 * A checkpoint is taken on a step boundary, counted in steps from the start
 * (TraceCursor::steps). The boundaries do not depend on where a run stops
 * (StepSchedule), so resuming from a copy and stepping on passes through the
 * same states as a replay from the start: the result is the same, bit for bit.
 * Every process of a distributed run takes the same steps and decides alike,
 * so they all keep copies at the same steps.
 *
 * No VTK here: the stepper holds the copies and this index of them; the
 * trace plan (TracePlan.h) decides from it.
 */
#ifndef BoundParticles_Checkpoints_h
#define BoundParticles_Checkpoints_h

#include <cstddef>
#include <map>

namespace bp
{

/// Every how many steps a trace keeps a copy of its state.
struct CheckpointSpacing
{
  long long every = 0; ///< steps between copies; 0: none kept
  int most = 0;        ///< copies the budget holds

  bool on() const { return this->every > 0; }
  /// Whether the boundary after `steps` steps gets a copy (the start never
  /// does: a replay starts there anyway).
  bool due(long long steps) const { return this->every > 0 && steps > 0 && steps % this->every == 0; }
};

/**
 * The spacing that keeps the copies of a trace of `stepsToEnd` steps within
 * `budgetBytes`, each copy `stateBytes` (the whole system's, so every process
 * of a distributed run finds the same spacing): as many copies as fit, spread
 * evenly over the trace. No budget, or one smaller than a copy: none.
 */
CheckpointSpacing checkpointSpacing(double budgetBytes, double stateBytes, long long stepsToEnd);

/// The copies a stepper holds: the step count of each and its time.
class CheckpointIndex
{
public:
  void add(long long steps, double time) { this->Times[steps] = time; }
  bool has(long long steps) const { return this->Times.count(steps) != 0; }
  /// The time of the copy kept after `steps` steps (has(steps)).
  double timeOf(long long steps) const { return this->Times.at(steps); }
  void clear() { this->Times.clear(); }
  std::size_t size() const { return this->Times.size(); }

  struct Entry
  {
    long long steps = -1; ///< -1: none
    double time = 0.0;
  };
  /// The latest copy at or before `time` (within `epsilon`); steps -1 if none.
  Entry latestAtOrBefore(double time, double epsilon) const;

private:
  std::map<long long, double> Times;
};

} // namespace bp

#endif
