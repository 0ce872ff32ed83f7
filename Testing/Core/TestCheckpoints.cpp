// SPDX-License-Identifier: BSD-3-Clause
// Checkpoints (Core/Stepping/Checkpoints.h): how they are spaced within a
// budget, and that a trace resumed from one steps to the same bits as a run
// that never stopped. Which one a request resumes from: TestTracePlan.cpp.
#include "Checkpoints.h"
#include "Stepper.h"
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <cstring>

TEST(Checkpoints, AsManyAsTheBudgetHoldsSpreadEvenlyOverTheTrace)
{
  // Ten copies' worth over 1000 steps: ten copies, the last before the end.
  const bp::CheckpointSpacing ten = bp::checkpointSpacing(10.5e6, 1e6, 1000);
  ASSERT_TRUE(ten.on());
  EXPECT_EQ(ten.most, 10);
  EXPECT_LE(ten.most * 1e6, 10.5e6); // within the budget
  EXPECT_LE((1000 - 1) / ten.every, 10);
  EXPECT_GE(ten.every * (ten.most + 1), 1000); // spread over the whole trace
  EXPECT_FALSE(ten.due(0));                   // the start is a replay's anyway
  EXPECT_TRUE(ten.due(ten.every));
  EXPECT_FALSE(ten.due(ten.every + 1));
  // A budget for more copies than steps: one a step, none at the end.
  const bp::CheckpointSpacing every = bp::checkpointSpacing(1e9, 1e3, 50);
  EXPECT_EQ(every.every, 1);
  EXPECT_EQ(every.most, 49);
  // No budget, one below a copy, no state, or no trace to speak of: none.
  for (const bp::CheckpointSpacing& off :
    { bp::checkpointSpacing(0.0, 1e6, 1000), bp::checkpointSpacing(0.9e6, 1e6, 1000),
      bp::checkpointSpacing(-1.0, 1e6, 1000), bp::checkpointSpacing(NAN, 1e6, 1000),
      bp::checkpointSpacing(1e9, 0.0, 1000), bp::checkpointSpacing(1e9, 1e6, 1) })
  {
    EXPECT_FALSE(off.on());
    EXPECT_FALSE(off.due(1));
  }
}

TEST(Checkpoints, TheLatestAtOrBeforeATime)
{
  bp::CheckpointIndex index;
  EXPECT_EQ(index.latestAtOrBefore(5.0, 1e-9).steps, -1);
  index.add(10, 1.0);
  index.add(20, 2.0);
  index.add(30, 3.0);
  EXPECT_EQ(index.latestAtOrBefore(0.5, 1e-9).steps, -1);
  EXPECT_EQ(index.latestAtOrBefore(2.5, 1e-9).steps, 20);
  EXPECT_EQ(index.latestAtOrBefore(2.0 - 1e-12, 1e-9).steps, 20); // within epsilon
  EXPECT_EQ(index.latestAtOrBefore(9.0, 1e-9).steps, 30);
  EXPECT_DOUBLE_EQ(index.timeOf(20), 2.0);
  index.clear();
  EXPECT_EQ(index.size(), 0u);
}

TEST(Checkpoints, AResumedTraceStepsToTheBitsOfOneThatNeverStopped)
{
  const bp::VectorField field =
    bptest::unsteadyFlow(bp::AnalyticFlow::DoubleGyre, bptest::grid(33, 0.0, 2.0, 2), 0.0, 1.0);
  bp::Parameters p;
  p.numberOfElements = 500;
  p.elementSize = 0.05f;
  p.emitterMin = { 0.2f, 0.2f, 0.0f };
  p.emitterMax = { 1.8f, 0.8f, 0.0f };
  p.lifetimeMin = 0.2f; // elements are reset and released again along the way
  p.lifetimeMax = 0.3f;
  p.trailLength = 4;
  p.trailInterval = 0.05;
  const double h = 0.01;
  auto straight = [&](int steps)
  {
    bp::CpuStepper s;
    EXPECT_EQ(s.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
    EXPECT_EQ(s.setField(field), "");
    s.initialize(0.0);
    for (int k = 0; k < steps; ++k)
    {
      s.step(k * h, h);
    }
    return std::vector<float>(s.particles()->positions());
  };
  bp::CpuStepper stepper;
  ASSERT_TRUE(stepper.keepsCheckpoints());
  ASSERT_EQ(stepper.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
  ASSERT_EQ(stepper.setField(field), "");
  stepper.initialize(0.0);
  for (int k = 0; k < 60; ++k)
  {
    if (k % 20 == 0 && k > 0)
    {
      stepper.keepCheckpoint(k, k * h);
    }
    stepper.step(k * h, h);
  }
  ASSERT_EQ(stepper.checkpoints().size(), 2u);
  // Back to step 20, and on to 35: the bits of a run straight to 35.
  stepper.resumeCheckpoint(20);
  EXPECT_EQ(stepper.cursor.steps, 20);
  EXPECT_DOUBLE_EQ(stepper.cursor.committed, 20 * h);
  for (int k = 20; k < 35; ++k)
  {
    stepper.step(k * h, h);
  }
  const std::vector<float> expected = straight(35);
  ASSERT_EQ(stepper.particles()->positions().size(), expected.size());
  EXPECT_EQ(0, std::memcmp(stepper.particles()->positions().data(), expected.data(),
                 expected.size() * sizeof(float)));
  // The checkpoint is kept as it was: resuming it again gives the same again.
  stepper.resumeCheckpoint(40);
  for (int k = 40; k < 45; ++k)
  {
    stepper.step(k * h, h);
  }
  const std::vector<float> at45 = straight(45);
  EXPECT_EQ(0, std::memcmp(stepper.particles()->positions().data(), at45.data(),
                 at45.size() * sizeof(float)));
  stepper.dropCheckpoints();
  EXPECT_EQ(stepper.checkpoints().size(), 0u);
}
