// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file PassTimer.h
 * @brief Where the GPU engine's time goes, for tests and benchmarks: a
 * GL_TIME_ELAPSED query around every pass (and copy) while timing is on,
 * summed per pass. The engine calls it as its PassObserver
 * (GpuEngine::setPassObserver).
 *
 * On a software renderer (llvmpipe) the queries mislead: a compute dispatch
 * runs when a later command needs it, inside the next pass's query, so each
 * pass was charged with the one before it. There the timer reads the CPU
 * clock instead, around each pass with glFinish on both sides (timing on,
 * the passes wait for each other; the step's total stays the same).
 *
 * Nothing waits while the passes run: a query's result is read only by
 * collect(), or when very many are pending (then the oldest, long finished).
 * Off, it records nothing. Needs the GL context current; enable(false)
 * deletes the queries (GlObjects.h: a destructor calls no GL).
 */
#ifndef BoundParticles_PassTimer_h
#define BoundParticles_PassTimer_h

#include "GlObjects.h"
#include "PassObserver.h"
#include "PassTime.h"

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace bp
{

/// Usage: timer.enable(true); engine.setPassObserver(&timer); steps;
/// timer.collect(); engine.setPassObserver(nullptr); timer.enable(false).
class PassTimer : public PassObserver
{
public:
  /// Starts or stops timing; stopping drops what was not collected and
  /// deletes the queries. Starting reads GL_RENDERER: a software renderer's
  /// passes are timed by the CPU clock.
  void enable(bool on);
  bool enabled() const { return this->On; }
  /// Whether the CPU clock times the passes (a software renderer).
  bool cpuClock() const { return this->CpuClock; }

  /// Opens the query of a run of `pass`; one at a time (GL_TIME_ELAPSED
  /// queries do not nest).
  void begin(const std::string& pass) override;
  void end() override;

  /// Every pass's time since the last collect(), in the order each first
  /// ran; waits for the GPU to finish what was timed.
  std::vector<PassTime> collect();

private:
  /// Adds the results of the pending queries but the newest `keep`.
  void settle(std::size_t keep);

  struct Pending
  {
    std::size_t query; ///< in Queries
    std::size_t pass;  ///< in Times
  };
  bool On = false;
  bool CpuClock = false;
  double Started = 0.0;          ///< the CPU clock's begin(), in seconds
  std::size_t Running = 0;       ///< the pass begin() opened, in Times (CPU clock)
  GlQueryList Queries;           ///< every query made; reused
  std::vector<std::size_t> Free; ///< queries not pending
  std::deque<Pending> Open;      ///< begun, results not read yet, oldest first
  std::vector<PassTime> Times;
};

} // namespace bp

#endif
