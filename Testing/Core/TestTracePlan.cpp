// SPDX-License-Identifier: BSD-3-Clause
// The trace plan (Core/Plan/TracePlan.h) and its field cache (Core/Field/FieldCache.h):
// replay or continue, which time steps a request needs, keeps and reads ahead.
#include "FieldCache.h"
#include "TracePlan.h"

#include <cstdint>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

namespace
{
bp::TracePlan unsteadyPlan()
{
  bp::TracePlan plan;
  EXPECT_EQ(plan.setTimes({ 0.0, 1.0, 2.0, 3.0 }, 10.0, 101), "");
  return plan;
}

bp::TraceCursor cursorAt(double committed, std::uint64_t producer = 7, std::uint64_t config = 3)
{
  bp::TraceCursor c;
  c.valid = true;
  c.committed = committed;
  c.producer = producer;
  c.configuration = config;
  return c;
}

bp::FieldSlice slice(double time)
{
  bp::FieldSlice s;
  s.time = time;
  s.velocity = std::make_shared<std::vector<float>>(24, 0.0f);
  return s;
}
} // namespace

TEST(TracePlan, SteadyInputIsOfferedDurationInEvenSteps)
{
  bp::TracePlan plan;
  EXPECT_EQ(plan.setTimes({ 5.0 }, 2.0, 5), "");
  EXPECT_FALSE(plan.unsteady());
  ASSERT_EQ(plan.outputTimes().size(), 5u);
  EXPECT_DOUBLE_EQ(plan.outputTimes()[1], 0.5);
  EXPECT_DOUBLE_EQ(plan.outputTimes().back(), 2.0);
  EXPECT_EQ(plan.intervalAt(1.3, true), std::vector<int>{ 0 });
  EXPECT_EQ(plan.readAheadIndex(1.0), -1);
}

TEST(TracePlan, SteadyTimeLineIsCheckedWithAMessage)
{
  bp::TracePlan plan;
  EXPECT_NE(plan.setTimes({}, 0.0, 10).find("Duration must be positive"), std::string::npos);
  EXPECT_FALSE(plan.hasTimes());
  EXPECT_NE(plan.setTimes({}, 1.0, 1).find("NumberOfTimeSteps"), std::string::npos);
  EXPECT_NE(plan.setTimes({}, std::numeric_limits<double>::infinity(), 10), "");
}

TEST(TracePlan, InputTimesMustBeFiniteAndIncreasing)
{
  bp::TracePlan plan;
  EXPECT_NE(plan.setTimes({ 0, 2, 1, 3 }, 1.0, 10).find("out of order"), std::string::npos);
  EXPECT_FALSE(plan.hasTimes());
  EXPECT_NE(plan.setTimes({ 0, 1, 1 }, 1.0, 10).find("duplicate"), std::string::npos);
  EXPECT_NE(plan.setTimes({ 0, std::nan("") }, 1.0, 10).find("finite"), std::string::npos);
  EXPECT_NE(plan.setTimes({ 0, HUGE_VAL }, 1.0, 10).find("finite"), std::string::npos);
}

TEST(TracePlan, WorkBeyondTheStepBoundIsRefused)
{
  const bp::TracePlan plan = unsteadyPlan();
  EXPECT_EQ(plan.checkWork(0.0, 3.0, 1e-3), "");
  EXPECT_NE(plan.checkWork(0.0, 3.0, 1e-9).find("steps"), std::string::npos);
  EXPECT_NE(plan.checkWork(0.0, 3.0, 0.0).find("steps"), std::string::npos);
}

TEST(TracePlan, RequestsAreClampedToTheOfferedRange)
{
  const bp::TracePlan plan = unsteadyPlan();
  EXPECT_DOUBLE_EQ(plan.targetOf(true, -4.0), 0.0);
  EXPECT_DOUBLE_EQ(plan.targetOf(true, 9.0), 3.0);
  EXPECT_DOUBLE_EQ(plan.targetOf(true, 1.5), 1.5);
  EXPECT_DOUBLE_EQ(plan.targetOf(false, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(plan.targetOf(true, std::nan("")), 0.0);
  EXPECT_DOUBLE_EQ(plan.targetOf(true, HUGE_VAL), 3.0);
  EXPECT_DOUBLE_EQ(plan.targetOf(true, -HUGE_VAL), 0.0);
}

TEST(TracePlan, IntervalsForSteppingAndForShowing)
{
  const bp::TracePlan plan = unsteadyPlan();
  // Stepping on from a data time step needs the interval that starts there;
  // showing the state there needs only the one that ends there.
  EXPECT_EQ(plan.intervalAt(1.0, true), (std::vector<int>{ 1, 2 }));
  EXPECT_EQ(plan.intervalAt(1.0, false), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(plan.intervalAt(0.0, false), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(plan.intervalAt(3.0, true), (std::vector<int>{ 2, 3 }));
  EXPECT_EQ(plan.needed(0.5, 2.5), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(plan.needed(2.5, 2.5), (std::vector<int>{ 2, 3 }));
}

TEST(TracePlan, ContinuesForwardAndReplaysBackwardOrOnChange)
{
  const bp::TracePlan plan = unsteadyPlan();
  const bp::TraceCursor at1 = cursorAt(1.0);
  const auto forward = plan.decide(2.0, at1, 7, 3);
  EXPECT_FALSE(forward.replay);
  EXPECT_DOUBLE_EQ(forward.from, 1.0);
  EXPECT_FALSE(plan.decide(1.0, at1, 7, 3).replay);
  const auto back = plan.decide(0.5, at1, 7, 3);
  EXPECT_TRUE(back.replay);
  EXPECT_DOUBLE_EQ(back.from, 0.0);
  EXPECT_TRUE(plan.decide(2.0, at1, 8, 3).replay) << "another tracer's trace";
  EXPECT_TRUE(plan.decide(2.0, at1, 7, 4).replay) << "made for another configuration";
  bp::TraceCursor empty = at1;
  empty.valid = false;
  EXPECT_TRUE(plan.decide(2.0, empty, 7, 3).replay);
}

TEST(TracePlan, FirstRequestIsWhatIsMissingElseWhatUpstreamHolds)
{
  const bp::TracePlan plan = unsteadyPlan();
  bp::FieldCache cache;
  bp::TracePlan::Update u = plan.decide(2.5, cursorAt(0.0), 7, 3);
  EXPECT_EQ(plan.firstRequest(u, cache, -1), 0);
  cache.insert(0, slice(0.0), {});
  EXPECT_EQ(plan.firstRequest(u, cache, 0), 1);
  cache.insert(1, slice(1.0), {});
  // All in hand: ask for what upstream holds, so nothing upstream runs again.
  EXPECT_EQ(plan.firstRequest(u, cache, 3), 3);
  EXPECT_EQ(plan.firstRequest(u, cache, -1), 1);
}

TEST(TracePlan, ReadsAheadTheStepAfterTheShownInterval)
{
  const bp::TracePlan plan = unsteadyPlan();
  EXPECT_EQ(plan.readAheadIndex(0.5), 2);
  EXPECT_EQ(plan.readAheadIndex(1.0), 2);
  EXPECT_EQ(plan.readAheadIndex(2.5), -1);
}

TEST(FieldCache, HoldsAtMostThreeKeepingWhatTheWorkNeeds)
{
  bp::FieldCache cache;
  cache.insert(0, slice(0), {});
  cache.insert(1, slice(1), {});
  cache.insert(2, slice(2), {});
  EXPECT_EQ(cache.size(), 3u);
  cache.insert(3, slice(3), { 1, 2 });
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_FALSE(cache.has(0));
  EXPECT_TRUE(cache.has(1) && cache.has(2) && cache.has(3));
  EXPECT_EQ(cache.firstMissing({ 2, 4 }), 4);
  EXPECT_EQ(cache.firstMissing({ 2, 3 }), -1);
  cache.dropBefore(3);
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_DOUBLE_EQ(cache.at(3).time, 3.0);
}

TEST(FieldCache, FieldBetweenTwoHeldSteps)
{
  bp::GridGeometry g;
  g.dims = { 2, 2, 2 };
  bp::FieldCache cache;
  cache.insert(4, slice(4.0), {});
  cache.insert(5, slice(6.0), {});
  const bp::VectorField steady = cache.field(g, { 4 });
  EXPECT_TRUE(steady.isSteady());
  const bp::VectorField between = cache.field(g, { 4, 5 });
  EXPECT_FALSE(between.isSteady());
  EXPECT_FLOAT_EQ(between.timeWeight(5.0), 0.5f);
}

TEST(TracePlan, FramesBetweenTheInputsTimeSteps)
{
  bp::TracePlan plan;
  EXPECT_EQ(plan.setTimes({ 0.0, 6.0, 9.0 }, 0.0, 101, 3), "");
  const std::vector<double> expected = { 0, 2, 4, 6, 7, 8, 9 };
  ASSERT_EQ(plan.outputTimes().size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(plan.outputTimes()[k], expected[k], 1e-12);
  EXPECT_EQ(plan.outputTimes()[3], 6.0); // the input's own times exactly
  // Between two input steps, the field is the interval's.
  EXPECT_EQ(plan.intervalAt(4.0, true), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(plan.intervalAt(7.0, true), (std::vector<int>{ 1, 2 }));
}

namespace
{
bp::TracePlan steadyTimeLine()
{
  bp::TracePlan plan;
  EXPECT_EQ(plan.setTimes({}, 10.0, 101), "");
  return plan;
}
} // namespace

TEST(TracePlan, GoingBackResumesFromTheLatestCheckpointAtOrBeforeTheTarget)
{
  const bp::TracePlan plan = steadyTimeLine();
  bp::CheckpointIndex index;
  index.add(200, 2.0);
  index.add(400, 4.0);
  // Back from 8.0 to 5.0: from the checkpoint at 4.0, not the start.
  bp::TracePlan::Update u = plan.decide(5.0, cursorAt(8.0), 7, 3, &index);
  EXPECT_FALSE(u.replay);
  EXPECT_EQ(u.resume, 400);
  EXPECT_DOUBLE_EQ(u.from, 4.0);
  // Exactly on a checkpoint.
  u = plan.decide(2.0, cursorAt(8.0), 7, 3, &index);
  EXPECT_EQ(u.resume, 200);
  // Before every checkpoint: a replay from the start, as without any.
  u = plan.decide(1.0, cursorAt(8.0), 7, 3, &index);
  EXPECT_TRUE(u.replay);
  EXPECT_EQ(u.resume, -1);
  EXPECT_DOUBLE_EQ(u.from, 0.0);
  // Forward from a cursor later than every checkpoint: go on from the cursor.
  u = plan.decide(9.0, cursorAt(8.0), 7, 3, &index);
  EXPECT_FALSE(u.replay);
  EXPECT_EQ(u.resume, -1);
  EXPECT_DOUBLE_EQ(u.from, 8.0);
  // Forward past a checkpoint later than the cursor (back at 1.0 after a
  // trace to 8.0, then on to 4.5): from that checkpoint.
  u = plan.decide(4.5, cursorAt(1.0), 7, 3, &index);
  EXPECT_FALSE(u.replay);
  EXPECT_EQ(u.resume, 400);
  // Another configuration or producer, or no trace: the checkpoints are not
  // its own; a replay.
  for (const bp::TraceCursor& other : { cursorAt(8.0, 7, 4), cursorAt(8.0, 8, 3), bp::TraceCursor() })
  {
    u = plan.decide(5.0, other, 7, 3, &index);
    EXPECT_TRUE(u.replay);
    EXPECT_EQ(u.resume, -1);
  }
}

TEST(TracePlan, StepsToTheEndCountTheDataTimeSteps)
{
  EXPECT_EQ(steadyTimeLine().stepsToEnd(0.1), 100 + 0); // a steady input has no time steps
  bp::TracePlan unsteady;
  ASSERT_EQ(unsteady.setTimes({ 0.0, 1.0, 2.0 }, 10.0, 101), "");
  EXPECT_EQ(unsteady.stepsToEnd(0.25), 8 + 3);
  EXPECT_EQ(unsteady.stepsToEnd(0.0), 0);
  bp::TracePlan stream;
  stream.setStreamTimes({ 0.0, 1.0 });
  EXPECT_EQ(stream.stepsToEnd(0.25), 0); // in situ the end is not known
}

TEST(TracePlan, OneTimeIsRelativeToTheTimesMagnitude)
{
  // A restart in situ compares a saved state's time with the first step
  // handed: one time within the times' rounding, however large they are.
  const double epoch = 1.7e9; // seconds since 1970
  bp::TracePlan stream;
  stream.setStreamTimes({ epoch });
  const double ulp = std::nextafter(epoch, 2.0 * epoch) - epoch;
  EXPECT_GT(ulp, stream.epsilon()); // the absolute epsilon cannot tell such times apart
  EXPECT_TRUE(stream.sameTime(epoch, epoch));
  EXPECT_TRUE(stream.sameTime(epoch, epoch + ulp));
  EXPECT_TRUE(stream.sameTime(epoch + 4.0 * ulp, epoch - 3.0 * ulp));
  // 0.1 s apart is another time step, not rounding.
  EXPECT_FALSE(stream.sameTime(epoch, epoch + 0.1));
  EXPECT_FALSE(stream.sameTime(epoch, epoch + 64.0 * ulp));
  // t0 + k dt against a sum of k steps: the last bits differ, one time.
  double sum = 1.0e6;
  for (int k = 0; k < 10; ++k)
  {
    sum += 0.1;
  }
  bp::TracePlan million;
  million.setStreamTimes({ 1.0e6 + 10 * 0.1 });
  EXPECT_TRUE(million.sameTime(sum, 1.0e6 + 10 * 0.1));
  EXPECT_FALSE(million.sameTime(sum, 1.0e6 + 11 * 0.1));
  // Small times are not one time merely for being within an absolute 1e-9:
  // microseconds of a simulation stepping by nanoseconds stay apart.
  bp::TracePlan micro;
  micro.setStreamTimes({ 2.0e-6 });
  EXPECT_FALSE(micro.sameTime(2.0e-6, 2.0e-6 + 1.0e-9));
  EXPECT_TRUE(micro.sameTime(2.0e-6, 2.0e-6 * (1.0 + 1e-15)));
  // Post hoc the times' span sets the floor, as epsilon() does.
  bp::TracePlan span;
  ASSERT_EQ(span.setTimes({ 0.0, 10.0 }, 10.0, 11), "");
  EXPECT_TRUE(span.sameTime(5.0, 5.0 + 5e-9));
  EXPECT_FALSE(span.sameTime(5.0, 5.0 + 1e-7));
  EXPECT_DOUBLE_EQ(span.timeTolerance(5.0, 5.0), 1e-8);
}
