// SPDX-License-Identifier: BSD-3-Clause
#include "ReplayProgress.h"

#include "WorkQueue.h"

#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

namespace bp
{

ReplayProgress::ReplayProgress(const std::vector<EngineCall>& calls, Hooks hooks, double interval)
  : Calls(calls)
  , H(std::move(hooks))
  , Interval(interval)
{
  this->LastReport = this->now();
}

double ReplayProgress::now() const
{
  if (this->H.clock)
  {
    return this->H.clock();
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool ReplayProgress::reportShare(double share, bool askToStop)
{
  if (this->H.settle)
  {
    this->H.settle();
  }
  ++this->Reports;
  if (this->H.report)
  {
    this->H.report(share);
  }
  const bool stop = askToStop && this->H.stop && this->H.stop();
  if (this->H.resume)
  {
    this->H.resume();
  }
  // From the end of the report: a slow listener (one that redraws the
  // application) does not make every following step report.
  this->LastReport = this->now();
  return stop;
}

bool ReplayProgress::beforeCall(std::size_t k)
{
  if (this->Stopped)
  {
    return false;
  }
  const EngineCall& call = this->Calls[k];
  if (call.kind != EngineCall::Kind::Step || this->now() - this->LastReport < this->Interval)
  {
    return true;
  }
  if (this->reportShare(double(k) / double(this->Calls.size()), true))
  {
    this->Stopped = true;
    this->StoppedAt = call.t;
    this->StoppedBefore = k;
    this->StoppedSteps = call.steps;
    return false;
  }
  return true;
}

void ReplayProgress::finish()
{
  if (this->Reports > 0 && !this->Stopped)
  {
    this->reportShare(1.0, false);
  }
}

std::string longReplayNote(
  double steps, double particles, double from, double to, const WorkQueue& queue)
{
  const RendererReport& report = queue.report();
  const bool measured = report.particleStepsPerSecond > 0.0;
  const double rate = measured
    ? report.particleStepsPerSecond
    : (report.renderer == RendererKind::Software ? AssumedSoftwareRate : AssumedHardwareRate);
  const double seconds = steps * particles / rate;
  if (!(seconds > LongReplaySeconds))
  {
    return std::string();
  }
  std::ostringstream say;
  say.precision(3);
  say << "The GPU engine runs " << std::llround(steps) << " steps of " << std::llround(particles)
      << " particles (t = " << from << " to " << to << ") before this frame is drawn: about "
      << std::llround(seconds) << " s "
      << (measured ? "at the rate it last ran at"
                   : (report.renderer == RendererKind::Software
                         ? "on a software renderer"
                         : "at a modest GPU's rate (not yet measured here)"))
      << (report.rendererName.empty() ? std::string() : " (" + report.rendererName + ")")
      << ", while the view waits. A trace is replayed from its start when it is new, changed, "
         "or its engine switched: to wait less, set Engine before going to a late time, lower "
         "Number Of Elements, or keep Engine = CPU on a software renderer.";
  return say.str();
}

} // namespace bp
