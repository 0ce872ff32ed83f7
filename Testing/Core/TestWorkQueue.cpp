// SPDX-License-Identifier: BSD-3-Clause
// The hand-off between a display and the tracer through a work queue
// (Core/Stepping/WorkQueue.h): the display alone writes the report, through
// the writer it got with the queue; the renderer records where a run stopped
// or that the state was lost, and the tracer settles its own cursor from that
// at its next decision.
#include "WorkQueue.h"

#include "ElementTemplate.h"
#include "ParticleLayout.h"

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
      ++tracer->cursor.steps; // as the tracer counts them
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
  h.display.writer.stoppedAt(2.5, 25, bp::CheckpointIndex());
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
  h.display.writer.stoppedAt(2.5, 25, bp::CheckpointIndex());
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
  // A loss and a stop, in either order: no trace (replay), standing at the stop.
  for (const bool lossFirst : { true, false })
  {
    SCOPED_TRACE(lossFirst ? "a loss, then a stop" : "a stop, then a loss");
    Handoff h;
    if (lossFirst)
    {
      h.display.writer.stateLost();
    }
    h.display.writer.stoppedAt(2.5, 25, bp::CheckpointIndex());
    if (!lossFirst)
    {
      h.display.writer.stateLost();
    }
    h.tracer->settleCursor();
    EXPECT_FALSE(h.tracer->cursor.valid);
    EXPECT_EQ(h.tracer->cursor.committed, 2.5);
    EXPECT_FALSE(h.tracer->cursor.showsPartialStep);
  }
  // Two stops: the later one.
  {
    Handoff h;
    h.display.writer.stoppedAt(2.5, 25, bp::CheckpointIndex());
    h.display.writer.stoppedAt(1.5, 15, bp::CheckpointIndex());
    h.tracer->settleCursor();
    EXPECT_TRUE(h.tracer->cursor.valid);
    EXPECT_EQ(h.tracer->cursor.committed, 1.5);
  }
}

TEST(WorkQueue, RecordsCheckpointCallsAndHoldsWhatTheGpuWillHold)
{
  std::shared_ptr<bp::WorkQueue> tracer;
  bp::DisplayWorkQueue display = bp::newDisplayWorkQueue(3, tracer);
  EXPECT_TRUE(tracer->keepsCheckpoints());
  bp::Parameters p;
  p.numberOfElements = 10;
  p.trailLength = 3;
  p.trailInterval = 0.1;
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  ASSERT_EQ(tracer->configure(cross, p), "");
  for (int k = 0; k < 6; ++k)
  {
    if (k == 2 || k == 4)
    {
      tracer->keepCheckpoint(k, 0.1 * k);
    }
    tracer->step(0.1 * k, 0.1);
    ++tracer->cursor.steps;
  }
  // What the GPU will hold once the calls run, before they do.
  EXPECT_EQ(tracer->checkpoints().size(), 2u);
  EXPECT_TRUE(tracer->checkpoints().has(2));
  EXPECT_DOUBLE_EQ(tracer->checkpoints().timeOf(4), 0.4);
  // Back to step 2: the cursor stands where the engine will, showing no short step.
  tracer->cursor.showsPartialStep = true;
  tracer->resumeCheckpoint(2);
  EXPECT_EQ(tracer->cursor.steps, 2);
  EXPECT_DOUBLE_EQ(tracer->cursor.committed, 0.2);
  EXPECT_FALSE(tracer->cursor.showsPartialStep);
  tracer->step(0.2, 0.1);
  // A copy it was not told of records nothing.
  tracer->resumeCheckpoint(3);
  EXPECT_EQ(tracer->cursor.steps, 2);

  using K = bp::EngineCall::Kind;
  const std::vector<bp::EngineCall> calls = display.writer.take();
  ASSERT_EQ(calls.size(), 1u + 6u + 2u + 1u + 1u);
  EXPECT_EQ(calls[0].kind, K::Configure);
  EXPECT_EQ(calls[3].kind, K::KeepCheckpoint);
  EXPECT_EQ(calls[3].steps, 2);
  EXPECT_DOUBLE_EQ(calls[3].t, 0.2);
  EXPECT_EQ(calls[4].kind, K::Step);
  EXPECT_EQ(calls[4].steps, 2); // each step knows how many came before it
  EXPECT_EQ(calls[6].kind, K::KeepCheckpoint);
  EXPECT_EQ(calls[6].steps, 4);
  EXPECT_EQ(calls[9].kind, K::ResumeCheckpoint);
  EXPECT_EQ(calls[9].steps, 2);
  EXPECT_EQ(calls[10].kind, K::Step);
  EXPECT_EQ(calls[10].steps, 2);

  // Dropped: recorded, and none held.
  tracer->dropCheckpoints();
  EXPECT_EQ(tracer->checkpoints().size(), 0u);
  const std::vector<bp::EngineCall> drop = display.writer.take();
  ASSERT_EQ(drop.size(), 1u);
  EXPECT_EQ(drop[0].kind, K::DropCheckpoints);

  // A configure starts a new engine, which holds none.
  tracer->keepCheckpoint(8, 0.8);
  ASSERT_EQ(tracer->configure(cross, p), "");
  EXPECT_EQ(tracer->checkpoints().size(), 0u);
}

TEST(WorkQueue, ACheckpointTakesTheLargerOfTheGpuTexturesAndTheCpuState)
{
  std::shared_ptr<bp::WorkQueue> tracer;
  bp::DisplayWorkQueue display = bp::newDisplayWorkQueue(3, tracer);
  EXPECT_EQ(tracer->checkpointBytes(), 0.0);
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  for (const bool heavy : { false, true })
  {
    bp::Parameters p;
    p.numberOfElements = 1000;
    p.trailLength = heavy ? 0 : 4;
    p.trailInterval = 0.1;
    if (heavy)
    {
      p.inertia = bp::Inertia::MaxeyRiley;
      p.responseTime = 0.01f;
    }
    ASSERT_EQ(bp::carriesInertia(p), heavy);
    ASSERT_EQ(tracer->configure(cross, p), "");
    p.trackPoses = true; // as the GPU engine runs it
    bp::Engine cpu;
    ASSERT_EQ(cpu.configure(cross, p), "");
    const double cpuBytes = 4.0 * double(cpu.recordWords()) * 1000.0;
    const double gpuBytes =
      bp::gpuCheckpointBytes(1000, cross.particleCount(), p.trailLength, heavy);
    // RGBA32F texels, padded to the texture's rows: larger than the CPU's record.
    EXPECT_GT(gpuBytes, cpuBytes);
    EXPECT_EQ(tracer->checkpointBytes(), std::max(cpuBytes, gpuBytes));
    // The GPU engine's per element: 16 bytes a particle and a texel a row,
    // as many again for the slips with inertia and per trail slot.
    const std::size_t n = cross.particleCount();
    const bp::ParticleLayout layout = bp::ParticleLayout::of(1000, n);
    EXPECT_GE(gpuBytes,
      16.0 * 1000.0 * double((heavy ? 2 : 1) * n + 5 + std::size_t(p.trailLength) * (n + 1)));
    EXPECT_EQ(gpuBytes,
      16.0 *
        double(layout.width * layout.height * ((heavy ? 2 : 1) + p.trailLength) + (heavy ? 0 : 1) +
          layout.elementGrid[0] * layout.elementGrid[1] * (5 + p.trailLength)));
  }
}

TEST(WorkQueue, AStopTellsTheStepsAndTheCheckpointsThatRan)
{
  Handoff h;
  // The renderer's engine kept the checkpoint at step 20 and stopped before
  // the step from t = 2.5, the 26th: the one at step 40 was never kept.
  h.tracer->keepCheckpoint(20, 2.0);
  h.tracer->keepCheckpoint(40, 4.0);
  h.tracer->cursor.steps = 100;
  bp::CheckpointIndex held;
  held.add(20, 2.0);
  h.display.writer.take();
  h.display.writer.stoppedAt(2.5, 25, held);
  EXPECT_EQ(h.tracer->report().engineState.stoppedSteps(), 25);
  EXPECT_EQ(h.tracer->checkpoints().size(), 2u); // the tracer's until it looks
  h.tracer->settleCursor();
  EXPECT_TRUE(h.tracer->cursor.valid);
  EXPECT_EQ(h.tracer->cursor.committed, 2.5);
  EXPECT_EQ(h.tracer->cursor.steps, 25);
  EXPECT_EQ(h.tracer->checkpoints().size(), 1u);
  EXPECT_TRUE(h.tracer->checkpoints().has(20));
  EXPECT_FALSE(h.tracer->checkpoints().has(40));
}

TEST(WorkQueue, ALostStateTakesTheCheckpointsWithIt)
{
  Handoff h;
  h.tracer->keepCheckpoint(20, 2.0);
  h.display.writer.take();
  h.display.writer.stateLost();
  h.tracer->settleCursor();
  EXPECT_FALSE(h.tracer->cursor.valid);
  EXPECT_EQ(h.tracer->checkpoints().size(), 0u);
}

TEST(WorkQueue, TheEnginesRecordWordsNeedNoConfiguredEngine)
{
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  for (int variant = 0; variant < 3; ++variant)
  {
    bp::Parameters p;
    p.numberOfElements = 5;
    p.trailLength = variant == 1 ? 3 : 0;
    p.trailInterval = 0.1;
    if (variant == 2)
    {
      p.inertia = bp::Inertia::MaxeyRiley;
      p.responseTime = 0.01f;
    }
    bp::Engine engine;
    ASSERT_EQ(engine.configure(cross, p), "");
    EXPECT_EQ(bp::Engine::recordWords(cross, p), engine.recordWords());
    engine.initialize(bp::serialRunner());
    std::vector<std::uint32_t> record;
    engine.packElement(0, record);
    EXPECT_EQ(record.size(), engine.recordWords());
  }
}

TEST(WorkQueue, RecordsAStateToLoadAfterTheGpuEnginesChecks)
{
  // The tracer hears a refusal at once: the display's upload cannot answer it.
  std::shared_ptr<bp::WorkQueue> tracer;
  bp::DisplayWorkQueue display = bp::newDisplayWorkQueue(4, tracer);
  bp::Parameters p;
  p.numberOfElements = 6;
  p.trailLength = 2;
  p.trailInterval = 0.1;
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(cross, p), "");
  engine.initialize(bp::serialRunner());
  const bp::EngineState saved = engine.saveState();
  EXPECT_EQ(tracer->loadState(saved),
    "the GPU engine cannot resume a state before its system is configured");
  ASSERT_EQ(tracer->configure(cross, p), "");
  tracer->take();
  // Generations past a float's exact integers, a pending Along Flow turn.
  bp::EngineState old = saved;
  old.records[2 * old.recordWords + 1] = bp::GpuMaxGeneration + 1;
  EXPECT_NE(tracer->loadState(old).find("generation 16777217"), std::string::npos);
  bp::EngineState pending = saved;
  pending.records[5 * pending.recordWords + 2] |= bp::AlignPending;
  EXPECT_NE(tracer->loadState(pending).find("Along Flow"), std::string::npos);
  bp::EngineState part = saved;
  part.records.resize(part.records.size() - part.recordWords);
  EXPECT_NE(tracer->loadState(part), "");
  EXPECT_FALSE(tracer->hasPending());
  // A state it can hold is recorded, shared, not copied again.
  ASSERT_EQ(tracer->loadState(saved), "");
  std::vector<bp::EngineCall> calls = display.writer.take();
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0].kind, bp::EngineCall::Kind::LoadState);
  ASSERT_TRUE(calls[0].state);
  EXPECT_EQ(calls[0].state->records, saved.records);
  // Its state lives in the renderer: the queue saves none.
  bp::EngineState none;
  EXPECT_FALSE(tracer->committedState(none));
  // Applied to a CPU stepper (as a GPU one in the display), it loads.
  bp::CpuStepper cpu;
  ASSERT_EQ(cpu.configure(cross, p), "");
  cpu.initialize(0.0);
  EXPECT_EQ(calls[0].applyTo(cpu), "");
}
} // namespace
