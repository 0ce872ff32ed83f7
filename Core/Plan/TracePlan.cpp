// SPDX-License-Identifier: BSD-3-Clause
#include "TracePlan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace bp
{

namespace
{
/// Empty when the input's time steps are finite and strictly increasing;
/// otherwise what is wrong with them.
std::string checkInputTimes(const std::vector<double>& times)
{
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    std::ostringstream err;
    if (!std::isfinite(times[k]))
    {
      err << "The input's time step " << k << " is " << times[k]
          << "; every time value must be finite.";
      return err.str();
    }
    if (k > 0 && !(times[k] > times[k - 1]))
    {
      err << "The input's time values must increase, but value " << k << " (" << times[k]
          << ") follows " << times[k - 1]
          << (times[k] == times[k - 1] ? " (a duplicate)" : " (out of order)")
          << ". Fix the time values of the data (e.g. the reader's time array).";
      return err.str();
    }
  }
  return std::string();
}
} // namespace

std::string TracePlan::setTimes(const std::vector<double>& inputTimes, double duration, int count,
  int framesPerInterval, TimeDirection direction)
{
  this->Direction = TimeDirection::Forward;
  this->Offered.clear();
  const std::string error = this->setDataTimes(inputTimes, duration, count, framesPerInterval);
  if (!error.empty())
  {
    return error;
  }
  // The data's times stay what the animation is offered; the trace runs on
  // their mirror backward (TimeDirection.h).
  this->Offered = this->OutputTimes;
  this->Direction = direction;
  this->InputTimes = traceTimes(direction, this->InputTimes);
  this->OutputTimes = traceTimes(direction, this->OutputTimes);
  return std::string();
}

std::string TracePlan::setDataTimes(
  const std::vector<double>& inputTimes, double duration, int count, int framesPerInterval)
{
  this->InputTimes.clear();
  this->OutputTimes.clear();
  this->Unsteady = false;
  this->Streaming = false;
  const std::string timesError = checkInputTimes(inputTimes);
  if (!timesError.empty())
  {
    return timesError;
  }
  this->InputTimes = inputTimes;
  // One time step is no flow in time: treat it as steady.
  this->Unsteady = inputTimes.size() >= 2;
  this->OutputTimes.clear();
  if (this->Unsteady)
  {
    const int parts = std::max(framesPerInterval, 1);
    for (std::size_t k = 0; k + 1 < inputTimes.size(); ++k)
    {
      for (int f = 0; f < parts; ++f)
      {
        // Input time steps exactly, and evenly between them.
        const double w = double(f) / parts;
        this->OutputTimes.push_back(
          f == 0 ? inputTimes[k] : inputTimes[k] + w * (inputTimes[k + 1] - inputTimes[k]));
      }
    }
    this->OutputTimes.push_back(inputTimes.back());
    return std::string();
  }
  if (count < 2 || count > MaxSteadyTimeSteps)
  {
    std::ostringstream err;
    err << "For a steady input, NumberOfTimeSteps must be between 2 and " << MaxSteadyTimeSteps
        << " (it is " << count << ").";
    return err.str();
  }
  if (!(duration > 0.0) || !std::isfinite(duration))
  {
    std::ostringstream err;
    err << "For a steady input, Duration must be positive and finite (it is " << duration << ").";
    return err.str();
  }
  for (int k = 0; k < count; ++k)
  {
    this->OutputTimes.push_back(duration * k / (count - 1));
  }
  return std::string();
}

void TracePlan::setStreamTimes(const std::vector<double>& times)
{
  this->Streaming = true;
  this->Direction = TimeDirection::Forward; // in situ traces forward only
  this->InputTimes = times;
  this->OutputTimes = times;
  this->Offered = times;
  this->Unsteady = times.size() >= 2;
}

double TracePlan::epsilon() const
{
  const double span =
    this->InputTimes.empty() ? 1.0 : this->InputTimes.back() - this->InputTimes.front();
  return 1e-9 * std::max(1.0, std::abs(span));
}

double TracePlan::timeTolerance(double a, double b) const
{
  const double span =
    this->InputTimes.size() < 2 ? 0.0 : this->InputTimes.back() - this->InputTimes.front();
  const double scale = std::max(std::abs(a), std::abs(b));
  return std::max(1e-9 * std::abs(span), 8.0 * std::numeric_limits<double>::epsilon() * scale);
}

bool TracePlan::sameTime(double a, double b) const
{
  return std::abs(a - b) <= this->timeTolerance(a, b);
}

double TracePlan::targetOf(bool requested, double time) const
{
  const double start = this->startTime();
  const double end = this->OutputTimes.empty() ? start : this->OutputTimes.back();
  // +inf is past the end (the end); -inf and NaN ask for nothing in range (the start).
  const double target =
    requested && !std::isnan(time) ? bp::traceTime(this->Direction, time) : start;
  return std::min(std::max(target, start), end);
}

std::vector<int> TracePlan::intervalAt(double t, bool forward) const
{
  if (!this->Unsteady)
  {
    return { 0 };
  }
  const double eps = this->epsilon();
  const auto begin = this->InputTimes.begin(), end = this->InputTimes.end();
  int k = forward ? int(std::upper_bound(begin, end, t + eps) - begin) - 1
                  : int(std::lower_bound(begin, end, t - eps) - begin) - 1;
  k = std::max(0, std::min(k, int(this->InputTimes.size()) - 2));
  return { k, k + 1 };
}

std::vector<int> TracePlan::needed(double from, double target) const
{
  const bool forward = from < target - this->epsilon();
  return this->intervalAt(forward ? from : target, forward);
}

TracePlan::Update TracePlan::decide(double target, const TraceCursor& cursor,
  std::uint64_t producer, std::uint64_t configuration, const CheckpointIndex* checkpoints) const
{
  Update u;
  u.target = target;
  const double eps = this->epsilon();
  const bool sameTrace =
    cursor.valid && cursor.producer == producer && cursor.configuration == configuration;
  u.replay = !sameTrace || target < cursor.committed - eps;
  u.from = u.replay ? this->startTime() : cursor.committed;
  if (sameTrace && checkpoints)
  {
    const CheckpointIndex::Entry c = checkpoints->latestAtOrBefore(target, eps);
    if (c.steps >= 0 && c.time > u.from + eps)
    {
      u.replay = false;
      u.resume = c.steps;
      u.from = c.time;
    }
  }
  return u;
}

long long TracePlan::stepsToEnd(double dt) const
{
  if (this->Streaming || this->OutputTimes.empty() || !(dt > 0.0))
  {
    return 0;
  }
  const double steps = (this->OutputTimes.back() - this->startTime()) / dt;
  if (!(steps < double(MaxStepsPerUpdate)))
  {
    return MaxStepsPerUpdate;
  }
  return (long long)(std::ceil(steps)) + (long long)(this->InputTimes.size());
}

int TracePlan::firstRequest(const Update& update, const FieldCache& cache, int upstream) const
{
  const std::vector<int> ids = this->needed(update.from, update.target);
  const int missing = cache.firstMissing(ids);
  return missing >= 0 ? missing : upstream >= 0 ? upstream : ids.back();
}

bool TracePlan::streamCanGoOn(const Update& update, const FieldCache& cache) const
{
  if (update.replay || this->InputTimes.empty())
  {
    return this->InputTimes.size() == 1;
  }
  const int present = int(this->InputTimes.size()) - 1;
  for (int k = this->needed(update.from, update.target).front(); k < present; ++k)
  {
    if (!cache.has(k))
    {
      return false;
    }
  }
  return true;
}

std::string TracePlan::checkWork(double from, double target, double dt) const
{
  const double steps = (target - from) / dt;
  if (!(steps <= double(MaxStepsPerUpdate)))
  {
    std::ostringstream err;
    // In the data's times, which the user sees (a backward trace's are mirrored).
    err << "Reaching t = " << traceTime(this->direction(), target)
        << " from t = " << traceTime(this->direction(), from) << " takes about " << steps
        << " steps of " << dt << ", more than the " << MaxStepsPerUpdate
        << " one update may take. The step comes from Step Size and the field's top speed: "
           "check the velocity's units (and byte order), or raise Step Size, or shorten "
           "Duration.";
    return err.str();
  }
  return std::string();
}

int TracePlan::readAheadIndex(double target) const
{
  if (!this->Unsteady)
  {
    return -1;
  }
  const int next = this->intervalAt(target, false).back() + 1;
  return next < int(this->InputTimes.size()) ? next : -1;
}

} // namespace bp
