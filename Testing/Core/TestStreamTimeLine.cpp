// SPDX-License-Identifier: BSD-3-Clause
// The in situ time line (Core/Plan/StreamTimeLine.h) and the trace plan it sets
// (TracePlan::setStreamTimes): one step at a time, never asking for the past.
#include "FieldCache.h"
#include "StepSchedule.h"
#include "StreamTimeLine.h"
#include "TracePlan.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

TEST(StreamTimeLine, FirstStartsLaterAdvancesRepeatsAndEarlierAreRefused)
{
  using Arrival = bp::StreamTimeLine::Arrival;
  bp::StreamTimeLine line;
  EXPECT_EQ(line.offer(0.5), Arrival::Start);
  EXPECT_EQ(line.offer(0.75), Arrival::Advance);
  EXPECT_EQ(line.offer(0.75), Arrival::Repeat);
  EXPECT_EQ(line.offer(0.6), Arrival::Back);
  EXPECT_EQ(line.offer(std::numeric_limits<double>::quiet_NaN()), Arrival::Back);
  // Refused times leave the line as it was.
  EXPECT_EQ(line.times(), (std::vector<double>{ 0.5, 0.75 }));
  EXPECT_EQ(line.offer(1.0), Arrival::Advance);
  EXPECT_DOUBLE_EQ(line.present(), 1.0);
}

TEST(StreamTimeLine, RefusalsSayWhatCameAndWhereTheTraceStays)
{
  using Arrival = bp::StreamTimeLine::Arrival;
  bp::StreamTimeLine line;
  line.offer(1.0);
  line.offer(2.0);
  EXPECT_EQ(line.refusal(Arrival::Advance, 3.0), "");
  const std::string repeat = line.refusal(Arrival::Repeat, 2.0);
  EXPECT_NE(repeat.find("repeats the last one"), std::string::npos) << repeat;
  EXPECT_NE(repeat.find("stays at t = 2"), std::string::npos) << repeat;
  const std::string back = line.refusal(Arrival::Back, 1.5);
  EXPECT_NE(back.find("comes before the last one (t = 2)"), std::string::npos) << back;
}

TEST(StreamTimeLine, RestartKeepsOnlyThePresent)
{
  bp::StreamTimeLine line;
  line.offer(1.0);
  line.offer(2.0);
  line.offer(3.0);
  line.restartAtPresent();
  EXPECT_EQ(line.times(), (std::vector<double>{ 3.0 }));
  EXPECT_EQ(line.offer(4.0), bp::StreamTimeLine::Arrival::Advance);
}

TEST(StreamTimeLine, ADroppedPresentLetsTheNextTimeAdvanceFromTheOneBefore)
{
  bp::StreamTimeLine line;
  line.offer(1.0);
  line.offer(2.0);
  line.dropPresent(); // t = 2's data was unusable
  EXPECT_EQ(line.times(), (std::vector<double>{ 1.0 }));
  EXPECT_EQ(line.offer(3.0), bp::StreamTimeLine::Arrival::Advance);
  EXPECT_EQ(line.times(), (std::vector<double>{ 1.0, 3.0 }));
}

namespace
{
/// A grid of n points an axis from `lo` with spacing h, and v = (x, 2y, 3z)
/// on it: linear, so trilinear sampling gives it exactly.
bp::GridGeometry cube(int n, double lo, double h)
{
  bp::GridGeometry g;
  g.dims = { n, n, n };
  g.origin = { lo, lo, lo };
  g.spacing = { h, h, h };
  return g;
}

bp::FieldSlice linearOn(const bp::GridGeometry& g, double time)
{
  auto v = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
      {
        v->push_back(float(g.coordinate(0, i)));
        v->push_back(float(2 * g.coordinate(1, j)));
        v->push_back(float(3 * g.coordinate(2, k)));
      }
  bp::FieldSlice s;
  s.time = time;
  s.velocity = v;
  return s;
}
} // namespace

TEST(FieldCache, RegridSamplesTheHeldStepsOnTheNewGridAndTakesThePresentBeyondTheOld)
{
  // The old grid spans [0, 1]; the new one [0.5, 1.5] in finer cells.
  const bp::GridGeometry from = cube(5, 0.0, 0.25);
  const bp::GridGeometry to = cube(6, 0.5, 0.2);
  bp::FieldCache cache;
  cache.insert(3, linearOn(from, 1.5), { 3 });
  bp::FieldSlice present;
  present.time = 2.0;
  present.velocity = std::make_shared<std::vector<float>>(3 * to.pointCount(), 7.0f);
  present.outsideCells = std::make_shared<std::vector<std::uint8_t>>(to.pointCount(), 0);
  // Points with every coordinate at most 1 lie in the old grid: 0.5, 0.7, 0.9 an axis.
  EXPECT_EQ(cache.regrid(from, to, present), to.pointCount() - 27);
  const bp::FieldSlice& held = cache.at(3);
  EXPECT_EQ(held.time, 1.5);
  EXPECT_EQ(held.outsideCells, present.outsideCells);
  ASSERT_EQ(held.velocity->size(), 3 * to.pointCount());
  std::size_t n = 0;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i, n += 3)
      {
        const double x = to.coordinate(0, i), y = to.coordinate(1, j), z = to.coordinate(2, k);
        const bool inOld = x <= 1.0 + 1e-9 && y <= 1.0 + 1e-9 && z <= 1.0 + 1e-9;
        const float* v = held.velocity->data() + n;
        EXPECT_NEAR(v[0], inOld ? x : 7.0, 1e-5);
        EXPECT_NEAR(v[1], inOld ? 2 * y : 7.0, 1e-5);
        EXPECT_NEAR(v[2], inOld ? 3 * z : 7.0, 1e-5);
      }
}

TEST(TracePlan, StreamTimesStartSteadyThenStepBetweenTheLastTwo)
{
  bp::TracePlan plan;
  plan.setStreamTimes({ 0.5 });
  EXPECT_TRUE(plan.streaming());
  EXPECT_FALSE(plan.unsteady());
  EXPECT_EQ(plan.outputTimes(), (std::vector<double>{ 0.5 }));
  EXPECT_DOUBLE_EQ(plan.startTime(), 0.5);
  EXPECT_DOUBLE_EQ(plan.targetOf(true, 0.5), 0.5);

  plan.setStreamTimes({ 0.5, 0.75, 1.0 });
  EXPECT_TRUE(plan.unsteady());
  // Continuing from the last step to the present needs those two only: the
  // last is held, the present is what upstream offers; nothing older.
  bp::TraceCursor cursor;
  cursor.valid = true;
  cursor.committed = 0.75;
  const bp::TracePlan::Update u = plan.decide(1.0, cursor, 0, 0);
  EXPECT_FALSE(u.replay);
  EXPECT_EQ(plan.needed(u.from, u.target), (std::vector<int>{ 1, 2 }));
  bp::FieldCache cache;
  bp::FieldSlice held;
  held.time = 0.75;
  cache.insert(1, held, { 1 });
  EXPECT_EQ(plan.firstRequest(u, cache, 1), 2);
  // A later setTimes is a post hoc line again.
  EXPECT_EQ(plan.setTimes({ 0.0, 1.0 }, 1.0, 2), "");
  EXPECT_FALSE(plan.streaming());
}

TEST(TracePlan, StreamGoesOnOnlyWithEveryPastStepItNeedsHeld)
{
  bp::TracePlan plan;
  plan.setStreamTimes({ 1.0 });
  bp::TracePlan::Update start;
  start.replay = true;
  EXPECT_TRUE(plan.streamCanGoOn(start, bp::FieldCache()));

  plan.setStreamTimes({ 1.0, 2.0, 3.0 });
  bp::TracePlan::Update on;
  on.replay = false;
  on.from = 1.9; // the trace stands short of the last step (a short step was shown)
  on.target = 3.0;
  bp::FieldCache cache;
  bp::FieldSlice held;
  cache.insert(1, held, { 1 });
  EXPECT_FALSE(plan.streamCanGoOn(on, cache)) << "time step 0 is needed and gone";
  cache.insert(0, held, { 0, 1 });
  EXPECT_TRUE(plan.streamCanGoOn(on, cache));
  // A replay cannot reach the past steps again.
  on.replay = true;
  EXPECT_FALSE(plan.streamCanGoOn(on, cache));
}

TEST(StepSchedule, ABreakAddedAsItsStepArrivesEndsAStepThere)
{
  // In situ each data time step becomes a break when it arrives, so steps end
  // where a post hoc trace, which knew every break from the start, ends them.
  bp::StepSchedule schedule(0.0, 0.3, { 0.0 });
  EXPECT_DOUBLE_EQ(schedule.next(0.9), 1.2);
  schedule.addBreak(1.0);
  schedule.addBreak(1.0);
  EXPECT_DOUBLE_EQ(schedule.next(0.9), 1.0);
  EXPECT_DOUBLE_EQ(schedule.next(1.0), 1.2);
}
