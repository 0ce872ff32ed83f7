// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracePlan.h
 * @brief Decides, once per request, how a trace reaches the requested time.
 *
 * Pipeline time drives the simulation. A request for a time at or after where
 * the stepper stands continues from there; an earlier time resumes from the
 * latest checkpoint at or before it (Checkpoints.h), or else replays from the
 * start, as a stepper made for another configuration does. An unsteady input is
 * read one time step per pipeline pass and sampled linearly between the two
 * steps that bracket each moment; the plan says which time steps the work
 * needs, which to keep (FieldCache holds at most three) and which to read
 * ahead for a display that uploads it a slab per frame. A steady input gets
 * `count` time values over [0, duration] so that an animation plays it.
 *
 * No VTK here: the tracer's pipeline passes only ask the plan.
 */
#ifndef BoundParticles_TracePlan_h
#define BoundParticles_TracePlan_h

#include "Checkpoints.h"
#include "FieldCache.h"
#include "Stepper.h"
#include "TimeDirection.h"

#include <cstdint>
#include <string>
#include <vector>

namespace bp
{

class TracePlan
{
public:
  /// The most time values a steady input may be offered at.
  static constexpr int MaxSteadyTimeSteps = 100000;
  /// The most steps one update may take (about an hour for a million
  /// particles here): beyond it an update is refused with the reason, so a
  /// wrong unit or byte order never hangs a script.
  static constexpr long long MaxStepsPerUpdate = 1000000;

  /**
   * Sets the time line: the input's time steps, finite and strictly
   * increasing, each interval between them offered as `framesPerInterval`
   * frames (fewer than two time steps: a steady input, offered `count` times
   * over [0, duration]). Empty on success, otherwise what to fix; the plan
   * then offers no times.
   */
  std::string setTimes(const std::vector<double>& inputTimes, double duration, int count,
    int framesPerInterval = 1, TimeDirection direction = TimeDirection::Forward);

  /**
   * The direction setTimes() was given (TimeDirection.h). Every time the plan
   * takes or gives is the trace's own (traceTime(): backward, the data's
   * mirrored), which always increases as the trace runs, except
   * offeredTimes(), dataTimeOf() and a request's time given to targetOf(),
   * which are the data's.
   */
  TimeDirection direction() const { return this->Direction; }
  /// The times the animation is offered, the data's, increasing (the output
  /// times in the data's time, in the data's order).
  const std::vector<double>& offeredTimes() const { return this->Offered; }
  /// The data's time of the trace's input time step `index` (the time to ask
  /// upstream for); its data index is dataIndex(direction(), index, count).
  double dataTimeOf(int index) const { return traceTime(this->Direction, this->InputTimes[index]); }

  /**
   * Sets the time line of an input that offers only its present time step
   * (StreamTimeLine): the times given since the trace started, each offered
   * as it is (no frames between: the next step has not arrived). One time is
   * the trace's start, shown as a steady field; from two on the field is
   * sampled between the last two as post hoc. `times` must increase.
   */
  void setStreamTimes(const std::vector<double>& times);
  /// Whether the time line is an in situ one (setStreamTimes).
  bool streaming() const { return this->Streaming; }

  bool unsteady() const { return this->Unsteady; }
  bool hasTimes() const { return !this->OutputTimes.empty(); }
  const std::vector<double>& inputTimes() const { return this->InputTimes; }
  const std::vector<double>& outputTimes() const { return this->OutputTimes; }
  double startTime() const { return this->OutputTimes.empty() ? 0.0 : this->OutputTimes.front(); }
  /// Times closer than this are one time.
  double epsilon() const;
  /**
   * Whether `a` and `b` are one time for a saved state's time against a
   * trace's (a restart's first step in situ): within 1e-9 of the times'
   * span, or within 8 double epsilons of the larger time (8 to 16 units in
   * its last place), whichever is larger. Relative to the times' magnitude where epsilon() is not:
   * times of 1e9 (seconds since 1970) are 1.2e-7 apart at the least, more
   * than epsilon() of a short span, and a time carried through a little
   * arithmetic (t0 + k dt against a sum of steps) differs in its last bits.
   */
  bool sameTime(double a, double b) const;
  /// The tolerance sameTime() allows between `a` and `b`.
  double timeTolerance(double a, double b) const;

  /// The requested time (the data's) as the trace's time, clamped to the
  /// offered range (+inf: the data's end); no request or NaN is the trace's
  /// start, -inf the data's start.
  double targetOf(bool requested, double time) const;

  /**
   * Input time indices of the field around time t: stepping forward from t
   * needs the interval that starts at t; showing the state at t needs only
   * an interval that contains it, and at a data time step the one that ends
   * there is the one already in hand. A steady input has one: {0}.
   */
  std::vector<int> intervalAt(double t, bool forward) const;

  /// The time steps the next piece of work needs: stepping on from `from`,
  /// or showing `target` once there.
  std::vector<int> needed(double from, double target) const;

  /// One request's decision.
  struct Update
  {
    double target = 0.0; ///< the time to show
    bool replay = true;  ///< start again from startTime()
    /// The checkpoint to resume from (its step count), -1 for none.
    long long resume = -1;
    /// Where stepping starts: startTime() for a replay, the checkpoint's time
    /// when resuming, else the cursor's.
    double from = 0.0;
  };

  /**
   * Replay, resume or continue: a stepper that holds no trace, or one made by
   * another producer or configuration, replays. Otherwise work starts from
   * the latest point at or before the target among the cursor and the
   * stepper's `checkpoints` (made for the cursor's trace): resuming from a
   * checkpoint when it is later than the cursor, or the cursor is past the
   * target; replaying when neither will do.
   */
  Update decide(double target, const TraceCursor& cursor, std::uint64_t producer,
    std::uint64_t configuration, const CheckpointIndex* checkpoints = nullptr) const;

  /// About how many steps of `dt` a trace takes from the start to the last
  /// time offered (each data time step is a step boundary too); 0 in situ,
  /// where the end is not known.
  long long stepsToEnd(double dt) const;

  /**
   * The time step to ask upstream for in an update's first pass: the first
   * one the work needs and `cache` lacks; with all in hand, the one upstream
   * already holds (`upstream`, -1 if none), so nothing upstream runs again.
   */
  int firstRequest(const Update& update, const FieldCache& cache, int upstream) const;

  /**
   * In situ (streaming()): whether `update` can go on with what `cache`
   * holds and the present time step upstream offers; every older time step
   * the work needs must be held, as the past cannot be asked for again.
   */
  bool streamCanGoOn(const Update& update, const FieldCache& cache) const;

  /// Empty when stepping from `from` to `target` by at most `dt` stays within
  /// MaxStepsPerUpdate; otherwise why the update is refused.
  std::string checkWork(double from, double target, double dt) const;

  /// The time step after the interval shown at `target`, which the next
  /// update forward will need; -1 if none (or a steady input).
  int readAheadIndex(double target) const;

private:
  /// setTimes() in the data's time.
  std::string setDataTimes(
    const std::vector<double>& inputTimes, double duration, int count, int framesPerInterval);

  bool Unsteady = false;
  bool Streaming = false;
  TimeDirection Direction = TimeDirection::Forward;
  std::vector<double> Offered;
  std::vector<double> InputTimes;
  std::vector<double> OutputTimes;
};

} // namespace bp

#endif
