// SPDX-License-Identifier: BSD-3-Clause
// Progress and abort while a renderer runs a work queue's calls
// (Core/Stepping/ReplayProgress.h); where the tracer goes on after a stop is
// TestWorkQueue.cpp's.
#include "ReplayProgress.h"
#include "WorkQueue.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace
{
/// What a replay from the start records: configure, field, placement, `steps`
/// steps of 0.1, and the short step shown on a saved copy.
std::vector<bp::EngineCall> replayCalls(int steps)
{
  using K = bp::EngineCall::Kind;
  std::vector<bp::EngineCall> calls;
  for (K kind : { K::Configure, K::SetField, K::Initialize })
  {
    bp::EngineCall call;
    call.kind = kind;
    calls.push_back(call);
  }
  for (int k = 0; k < steps; ++k)
  {
    bp::EngineCall call;
    call.kind = K::Step;
    call.t = 0.1 * k;
    call.h = 0.1;
    call.steps = k; // the steps before it, as WorkQueue::step records
    calls.push_back(call);
  }
  bp::EngineCall save;
  save.kind = K::Save;
  calls.push_back(save);
  bp::EngineCall shortStep;
  shortStep.kind = K::Step;
  shortStep.t = 0.1 * steps;
  shortStep.h = 0.05;
  calls.push_back(shortStep);
  return calls;
}

/// A run whose every call takes `secondsPerCall` on a clock of its own; the
/// hooks' calls in order, and the shares reported.
struct TimedRun
{
  double clock = 0.0;
  std::string hooks;
  std::vector<double> shares;
  int stopAtReport = -1; // the report after which stop() says yes (-1: never)

  bp::ReplayProgress::Hooks make()
  {
    bp::ReplayProgress::Hooks h;
    h.settle = [this] { this->hooks += 's'; };
    h.report = [this](double share)
    {
      this->hooks += 'r';
      this->shares.push_back(share);
    };
    h.stop = [this]
    {
      this->hooks += '?';
      return int(this->shares.size()) == this->stopAtReport;
    };
    h.resume = [this] { this->hooks += 'c'; };
    h.clock = [this] { return this->clock; };
    return h;
  }

  /// Runs `calls` as the mapper does; how many ran.
  std::size_t go(
    const std::vector<bp::EngineCall>& calls, double secondsPerCall, bp::ReplayProgress& progress)
  {
    std::size_t ran = 0;
    for (std::size_t k = 0; k < calls.size() && progress.beforeCall(k); ++k)
    {
      this->clock += secondsPerCall;
      ++ran;
    }
    progress.finish();
    return ran;
  }
};
} // namespace

TEST(ReplayProgress, ReportsFromNearZeroToOneNeverGoingBack)
{
  const std::vector<bp::EngineCall> calls = replayCalls(1000);
  TimedRun run;
  bp::ReplayProgress progress(calls, run.make(), 0.05);
  EXPECT_EQ(run.go(calls, 0.001, progress), calls.size());
  EXPECT_FALSE(progress.stopped());
  // About a second of work, a report every 50 ms, then the last one.
  ASSERT_GE(run.shares.size(), 15u);
  EXPECT_LE(run.shares.size(), 22u);
  EXPECT_EQ(progress.reports(), run.shares.size());
  EXPECT_LT(run.shares.front(), 0.1);
  EXPECT_EQ(run.shares.back(), 1.0);
  for (std::size_t k = 1; k < run.shares.size(); ++k)
  {
    EXPECT_GT(run.shares[k], run.shares[k - 1]);
  }
  // Each report: the GL work finished first, the context current again after;
  // the last one asks nothing.
  std::string expected;
  for (std::size_t k = 0; k + 1 < run.shares.size(); ++k)
  {
    expected += "sr?c";
  }
  EXPECT_EQ(run.hooks, expected + "src");
}

TEST(ReplayProgress, AShortRunReportsNothing)
{
  // A Play frame: a few steps in a few milliseconds.
  const std::vector<bp::EngineCall> calls = replayCalls(5);
  TimedRun run;
  bp::ReplayProgress progress(calls, run.make(), 0.05);
  EXPECT_EQ(run.go(calls, 0.001, progress), calls.size());
  EXPECT_EQ(run.hooks, "");
  EXPECT_EQ(progress.reports(), 0u);
}

TEST(ReplayProgress, StopsBeforeAStepOnItsBoundary)
{
  const std::vector<bp::EngineCall> calls = replayCalls(1000);
  TimedRun run;
  run.stopAtReport = 3;
  bp::ReplayProgress progress(calls, run.make(), 0.05);
  const std::size_t ran = run.go(calls, 0.001, progress);
  ASSERT_TRUE(progress.stopped());
  EXPECT_EQ(ran, progress.stoppedBefore());
  const bp::EngineCall& next = calls[progress.stoppedBefore()];
  EXPECT_EQ(next.kind, bp::EngineCall::Kind::Step);
  EXPECT_EQ(progress.stoppedAt(), next.t);
  // The steps from the start to there, for the cursor and the checkpoints.
  EXPECT_EQ(progress.stoppedSteps(), (long long)(progress.stoppedBefore()) - 3);
  // About 150 ms of a second's work, and no last report of 1.
  EXPECT_GT(ran, 100u);
  EXPECT_LT(ran, 250u);
  EXPECT_EQ(run.shares.size(), 3u);
  EXPECT_LT(run.shares.back(), 1.0);
  EXPECT_EQ(run.hooks, "sr?csr?csr?c");
  // Asked again, it stays stopped.
  EXPECT_FALSE(progress.beforeCall(ran));
}

TEST(ReplayProgress, ReportsAndStopsOnlyBeforeAStep)
{
  // Reports (and stops) only before a Step: the configure, the field and the
  // placement run whatever they take.
  const std::vector<bp::EngineCall> calls = replayCalls(2);
  TimedRun run;
  run.stopAtReport = 1;
  bp::ReplayProgress progress(calls, run.make(), 0.05);
  const std::size_t ran = run.go(calls, 1.0, progress);
  ASSERT_TRUE(progress.stopped());
  EXPECT_EQ(ran, 3u); // configure, field, placement
  EXPECT_EQ(progress.stoppedAt(), 0.0);
}

TEST(ReplayProgress, ALongRunIsSaidBeforeItIsRecorded)
{
  std::shared_ptr<bp::WorkQueue> queue;
  bp::DisplayWorkQueue display = bp::newDisplayWorkQueue(1, queue);
  bp::RendererReport& report = display.writer.report();
  report.renderer = bp::RendererKind::Software;
  report.rendererName = "llvmpipe";
  // A frame's few steps: nothing to say.
  EXPECT_TRUE(bp::longReplayNote(4, 16000, 0.0, 0.1, *queue).empty());
  // 2,000 steps of 160,000 particles at llvmpipe's assumed rate: 16 s.
  const std::string slow = bp::longReplayNote(2000, 160000, 0.0, 50.0, *queue);
  EXPECT_NE(slow.find("2000 steps of 160000 particles"), std::string::npos) << slow;
  EXPECT_NE(slow.find("about 16 s on a software renderer (llvmpipe)"), std::string::npos) << slow;
  EXPECT_NE(slow.find("Number Of Elements"), std::string::npos) << slow;
  // The same on a GPU whose measured rate is 1e10: 0.03 s, nothing said.
  report.renderer = bp::RendererKind::Hardware;
  report.particleStepsPerSecond = 1.0e10;
  EXPECT_TRUE(bp::longReplayNote(2000, 160000, 0.0, 50.0, *queue).empty());
  // A measured rate is what the note quotes.
  report.particleStepsPerSecond = 1.0e7;
  const std::string measured = bp::longReplayNote(2000, 160000, 0.0, 50.0, *queue);
  EXPECT_NE(measured.find("about 32 s at the rate it last ran at"), std::string::npos) << measured;
}
