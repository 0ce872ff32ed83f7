// SPDX-License-Identifier: BSD-3-Clause
// The hand-off between a display and the tracer through a work queue
// (Core/Stepping/WorkQueue.h): the display alone writes the report, through
// the writer it got with the queue; the renderer records where a run stopped
// or that the state was lost, and the tracer settles its own cursor from that
// at its next decision.
#include "WorkQueue.h"

#include <gtest/gtest.h>

#include <memory>
#include <type_traits>
#include <vector>

namespace
{
// The display holds the queue read-only and one writer, which it cannot copy
// and nobody else can make.
static_assert(
  std::is_same_v<decltype(bp::DisplayWorkQueue::queue), std::shared_ptr<const bp::WorkQueue>>);
static_assert(!std::is_copy_constructible_v<bp::RendererReportWriter>);
static_assert(!std::is_copy_assignable_v<bp::RendererReportWriter>);
static_assert(!std::is_constructible_v<bp::RendererReportWriter, std::shared_ptr<bp::WorkQueue>>);
// The tracer reads the report const only.
static_assert(
  std::is_same_v<decltype(std::declval<bp::WorkQueue&>().report()), const bp::RendererReport&>);

/// A tracer's queue whose cursor stands at t = 10 showing a short step, with
/// the calls of that update taken by the display's renderer.
struct Handoff
{
  std::shared_ptr<bp::WorkQueue> tracer;
  bp::DisplayWorkQueue display = bp::newDisplayWorkQueue(7, tracer);

  Handoff()
  {
    tracer->cursor.valid = true;
    tracer->cursor.committed = 10.0;
    tracer->cursor.showsPartialStep = true;
    for (int k = 0; k < 100; ++k)
    {
      tracer->step(0.1 * k, 0.1);
    }
    taken = display.writer.take();
  }
  std::vector<bp::EngineCall> taken;
};

TEST(WorkQueue, TheDisplaysQueueIsTheOneTheTracerRecordsInto)
{
  Handoff h;
  EXPECT_EQ(h.display.queue.get(), h.tracer.get());
  EXPECT_EQ(h.display.queue->id(), 7);
  EXPECT_EQ(h.taken.size(), 100u);
  EXPECT_FALSE(h.tracer->hasPending());
  // What the display writes is what the tracer reads.
  bp::RendererReport& report = h.display.writer.report();
  report.maxTextureSize = 4096;
  report.renderer = bp::RendererKind::Software;
  report.streamTimeSteps = false;
  EXPECT_EQ(h.tracer->report().maxTextureSize, 4096);
  EXPECT_EQ(h.tracer->report().renderer, bp::RendererKind::Software);
  EXPECT_FALSE(h.tracer->readsAhead());
  // What the tracer sets is what the display reads.
  bp::DrawSettings draw;
  draw.time = 2.0;
  draw.serial = 3;
  h.tracer->setDraw(draw);
  h.tracer->setAutomaticOnCpu(true);
  EXPECT_EQ(h.display.queue->draw().time, 2.0);
  EXPECT_EQ(h.display.queue->draw().serial, 3u);
  EXPECT_TRUE(h.display.queue->automaticOnCpu());
}

TEST(WorkQueue, TheTracerGoesOnFromWhereTheDisplayStopped)
{
  Handoff h;
  // The run stopped before the step from t = 2.5 (ReplayProgress): the
  // display records it; the tracer's cursor is the tracer's until it looks.
  h.display.writer.stoppedAt(2.5);
  EXPECT_EQ(h.tracer->cursor.committed, 10.0);
  EXPECT_TRUE(h.tracer->cursor.showsPartialStep);
  EXPECT_EQ(h.tracer->report().engineState.stops(), 1u);
  EXPECT_EQ(h.tracer->report().engineState.stoppedAt(), 2.5);

  // Its next decision starts on that step boundary, showing no short step.
  h.tracer->settleCursor();
  EXPECT_TRUE(h.tracer->cursor.valid);
  EXPECT_EQ(h.tracer->cursor.committed, 2.5);
  EXPECT_FALSE(h.tracer->cursor.showsPartialStep);

  // A stop is taken in once: the tracer's own progress after it stays.
  h.tracer->cursor.committed = 4.0;
  h.tracer->cursor.showsPartialStep = true;
  h.tracer->settleCursor();
  EXPECT_EQ(h.tracer->cursor.committed, 4.0);
  EXPECT_TRUE(h.tracer->cursor.showsPartialStep);
}

TEST(WorkQueue, AStopWhileCallsArePendingDropsThemAndTheTracerReplays)
{
  Handoff h;
  // An update inside the run recorded calls that continue from where every
  // taken call would have led, t = 10.
  h.tracer->step(10.0, 0.1);
  ASSERT_TRUE(h.tracer->hasPending());
  h.display.writer.stoppedAt(2.5);
  // Dropped at once, so no render runs them before the tracer decides again.
  EXPECT_FALSE(h.tracer->hasPending());
  EXPECT_TRUE(h.display.writer.take().empty());
  EXPECT_TRUE(h.tracer->cursor.valid);
  // The next decision replays.
  h.tracer->settleCursor();
  EXPECT_FALSE(h.tracer->cursor.valid);
  EXPECT_EQ(h.tracer->cursor.committed, 10.0);
}

TEST(WorkQueue, ALostStateDropsWhatIsQueuedAndTheTracerReplays)
{
  Handoff h;
  h.tracer->step(10.0, 0.1);
  // The display released its GL resources: the engine state is gone.
  h.display.writer.stateLost();
  EXPECT_FALSE(h.tracer->hasPending());
  EXPECT_TRUE(h.tracer->cursor.valid);
  h.tracer->settleCursor();
  EXPECT_FALSE(h.tracer->cursor.valid);

  // The replay makes a new trace, which a later settle leaves alone.
  h.tracer->cursor.valid = true;
  h.tracer->settleCursor();
  EXPECT_TRUE(h.tracer->cursor.valid);
}

TEST(WorkQueue, StopsAndLossesBetweenTwoDecisionsComeToWhatTheyDidInTurn)
{
  // A loss and then a stop: no trace (replay), standing at the stop.
  {
    Handoff h;
    h.display.writer.stateLost();
    h.display.writer.stoppedAt(2.5);
    h.tracer->settleCursor();
    EXPECT_FALSE(h.tracer->cursor.valid);
    EXPECT_EQ(h.tracer->cursor.committed, 2.5);
    EXPECT_FALSE(h.tracer->cursor.showsPartialStep);
  }
  // A stop and then a loss: the same.
  {
    Handoff h;
    h.display.writer.stoppedAt(2.5);
    h.display.writer.stateLost();
    h.tracer->settleCursor();
    EXPECT_FALSE(h.tracer->cursor.valid);
    EXPECT_EQ(h.tracer->cursor.committed, 2.5);
    EXPECT_FALSE(h.tracer->cursor.showsPartialStep);
  }
  // Two stops: the later one.
  {
    Handoff h;
    h.display.writer.stoppedAt(2.5);
    h.display.writer.stoppedAt(1.5);
    h.tracer->settleCursor();
    EXPECT_TRUE(h.tracer->cursor.valid);
    EXPECT_EQ(h.tracer->cursor.committed, 1.5);
  }
}
} // namespace
