// SPDX-License-Identifier: BSD-3-Clause
// Step boundaries and the walk along them (StepSchedule.h).
#include "StepSchedule.h"

#include <algorithm>
#include <cmath>

namespace bp
{

StepSchedule::StepSchedule(double start, double dt, std::vector<double> breaks)
  : Start(start)
  , Dt(dt)
  , Epsilon(dt * 1e-6)
  , Breaks(std::move(breaks))
{
  std::sort(this->Breaks.begin(), this->Breaks.end());
}

void StepSchedule::addBreak(double time)
{
  const auto at = std::lower_bound(this->Breaks.begin(), this->Breaks.end(), time);
  if (at == this->Breaks.end() || *at != time)
  {
    this->Breaks.insert(at, time);
  }
}

double StepSchedule::next(double t) const
{
  const double limit = t + this->Epsilon;
  // Grid points are computed from their index, never accumulated, so every run
  // meets the same ones.
  double k = std::floor((t - this->Start) / this->Dt);
  double grid = this->Start + k * this->Dt;
  while (grid <= limit)
  {
    k += 1.0;
    grid = this->Start + k * this->Dt;
  }
  // A break before the grid point, or within epsilon after it, wins: steps
  // land exactly on breaks and no sliver step is left on either side.
  const auto it = std::upper_bound(this->Breaks.begin(), this->Breaks.end(), limit);
  if (it != this->Breaks.end() && *it <= grid + this->Epsilon)
  {
    return *it;
  }
  return grid;
}

double advance(const StepSchedule& schedule, double t, double target,
  const std::function<void(double t, double h)>& step,
  const std::function<bool(double time)>& keepGoing)
{
  for (double next = schedule.next(t); next <= target + schedule.epsilon(); next = schedule.next(t))
  {
    if (keepGoing && !keepGoing(t))
    {
      break;
    }
    step(t, next - t);
    t = next;
  }
  return t;
}

} // namespace bp
