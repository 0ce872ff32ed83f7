// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file StepSchedule.h
 * @brief Where steps end (StepSchedule) and the walk along those boundaries
 * that both engines take (advance); Engine.h adds the CPU engine's walk.
 */
#ifndef BoundParticles_StepSchedule_h
#define BoundParticles_StepSchedule_h

#include <functional>
#include <vector>

namespace bp
{

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
  /// Adds a break at `time`: in situ, a data time step that has just
  /// arrived (later than the steps taken so far, so no step taken moves).
  void addBreak(double time);

  double epsilon() const { return this->Epsilon; }
  double start() const { return this->Start; }
  double dt() const { return this->Dt; }

private:
  double Start;
  double Dt;
  double Epsilon;
  std::vector<double> Breaks;
};

/// The same walk along the schedule for any engine: `step(t, h)` per step.
double advance(const StepSchedule& schedule, double t, double target,
  const std::function<void(double t, double h)>& step,
  const std::function<bool(double time)>& keepGoing = {});

} // namespace bp

#endif
