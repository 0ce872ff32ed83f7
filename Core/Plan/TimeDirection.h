// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TimeDirection.h
 * @brief A backward trace as a forward one: the trace's own time.
 *
 * Time Direction = Backward releases elements at the latest time of the
 * release window and advects them toward earlier times through the reversed
 * flow. Rather than step with negative h (every rule of the plan, the
 * schedule, checkpoints, releases, lifetimes, trails and both engines counts
 * time forward), a trace runs in its own time tau, which always increases:
 * tau = t forward, tau = -t backward. In tau, dx/dtau = -u(x, -tau): the
 * data's time steps are mirrored and reversed in order, and each slice's
 * velocity is negated (traceSlice). Everything past the filter's boundary
 * (TracePlan, StepSchedule, the engines, checkpoints, FTLE over the age)
 * then works unchanged: ages grow with |elapsed|, the interpolation between
 * the two held steps is linear in time as forward, and every integrator
 * integrates the reversed flow to its own order. Only the times the pipeline
 * sees (the offered time steps, a request's time, the release window, the
 * data's time of an input step) cross the mirror.
 */
#ifndef BoundParticles_TimeDirection_h
#define BoundParticles_TimeDirection_h

#include "BoundParticlesChoices.h"
#include "Engine.h"
#include "VectorField.h"

#include <array>
#include <string>
#include <vector>

namespace bp
{

/// The trace's time of the data's time t (and, the mirror being its own
/// inverse, the data's time of the trace's time t).
inline double traceTime(TimeDirection direction, double t)
{
  return direction == TimeDirection::Backward ? -t : t;
}

/// The trace's times of the data's increasing `times`: increasing too (a
/// backward trace takes them mirrored, last first).
std::vector<double> traceTimes(TimeDirection direction, const std::vector<double>& times);

/// The data's index of the trace's time step `index` of `count`.
inline int dataIndex(TimeDirection direction, int index, int count)
{
  return direction == TimeDirection::Backward ? count - 1 - index : index;
}

/**
 * The data's time step as the trace samples it: unchanged forward;
 * backward at the mirrored time with its velocity negated (a copy; the
 * outside cells and release weights are shared, as they do not change
 * with the direction).
 */
FieldSlice traceSlice(TimeDirection direction, const FieldSlice& slice);

/// The release window [start, stop] in the trace's time: backward its
/// mirror [-stop, -start], so the window's latest time releases first.
std::array<double, 2> traceWindow(TimeDirection direction, double start, double stop);

/// Empty when `engine` may trace in `direction`; otherwise why not (heavy
/// particles are traced forward only).
std::string checkTimeDirection(TimeDirection direction, const Parameters& engine);

} // namespace bp

#endif
