// SPDX-License-Identifier: BSD-3-Clause
// Time Direction = Backward (TimeDirection.h): the trace runs in its own time,
// the data's mirrored, through the reversed flow. Elements traced backward
// land where the flow brings them from, and a trace forward then backward
// over the same interval comes back to its start.
#include "TestHelpers.h"

#include "StepSchedule.h"
#include "Stepper.h"
#include "TimeDirection.h"
#include "TracePlan.h"
#include "TraceSettings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
constexpr double Pi = 3.14159265358979323846;

/**
 * Point elements released at `seeds` at the trace's start and followed to the
 * data's time `target` as the filter does: the plan's time line in
 * `direction`, the data's time steps of `flow` (a steady flow when `times` is
 * empty, over [0, duration]) set as the trace's slices, steps of `dt` along
 * the schedule. Returns the elements' positions.
 */
std::vector<float> trace(bp::TimeDirection direction, bp::AnalyticFlow flow,
  const std::vector<double>& times, double duration, const std::vector<float>& seeds, double target,
  double dt, bp::Integrator integrator = bp::Integrator::RK4)
{
  const bp::GridGeometry g = bptest::grid(65, -1.0, 1.0, 1);
  bp::TracePlan plan;
  EXPECT_EQ(plan.setTimes(times, duration, 11, 1, direction), "");
  bp::Parameters p;
  p.numberOfElements = seeds.size() / 3;
  p.elementSize = 0.05f;
  p.seedPoints = seeds;
  p.lifetimeMin = p.lifetimeMax = 1000.0f;
  p.integrator = integrator;
  bp::CpuStepper stepper;
  EXPECT_EQ(stepper.configure(bp::builtinTemplate(bp::BuiltinShape::Point), p), "");
  // The data's time step of the trace's index k, as the trace samples it.
  auto slice = [&](int k)
  {
    bp::FieldSlice s;
    const int count = int(times.size());
    s.time = times.empty() ? 0.0 : times[bp::dataIndex(direction, k, count)];
    s.velocity = std::make_shared<std::vector<float>>(bp::sampleAnalyticFlow(flow, g, s.time));
    return bp::traceSlice(direction, s);
  };
  auto setField = [&](double t)
  {
    const std::vector<int> ids = plan.intervalAt(t, true);
    stepper.setField(plan.unsteady() ? bp::VectorField(g, slice(ids[0]), slice(ids[1]))
                                     : bp::VectorField(g, slice(0)));
    return plan.unsteady() ? plan.inputTimes()[ids[1]] : plan.outputTimes().back();
  };
  double t = plan.startTime();
  setField(t);
  stepper.initialize(t);
  const bp::StepSchedule schedule(
    t, dt, plan.unsteady() ? plan.inputTimes() : std::vector<double>());
  const double goal = plan.targetOf(true, target);
  while (t < goal - plan.epsilon())
  {
    const double end = std::min(goal, setField(t));
    t = bp::advance(schedule, t, end, [&](double at, double h) { stepper.step(at, h); });
    if (t < end - schedule.epsilon())
    {
      stepper.step(t, end - t); // a short step onto a target between boundaries
      t = end;
    }
  }
  return stepper.engine().positions();
}

/// The angle solid-body rotation turns by per time unit (about +z).
double turningRate()
{
  const double p[3] = { 0.5, 0.0, 0.0 }, bounds[6] = { -1, 1, -1, 1, -1, 1 };
  double v[3];
  bp::analyticVelocity(bp::AnalyticFlow::SolidBodyRotation, p, 0.0,
    { bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5] }, v);
  return v[1] / p[0];
}
} // namespace

TEST(TimeDirection, TheTraceTimeIsTheDatasMirrorBackward)
{
  using bp::TimeDirection;
  EXPECT_EQ(bp::traceTimes(TimeDirection::Forward, { 0.0, 0.5, 2.0 }),
    (std::vector<double>{ 0.0, 0.5, 2.0 }));
  EXPECT_EQ(bp::traceTimes(TimeDirection::Backward, { 0.0, 0.5, 2.0 }),
    (std::vector<double>{ -2.0, -0.5, -0.0 }));
  EXPECT_EQ(bp::dataIndex(TimeDirection::Backward, 0, 3), 2);
  EXPECT_EQ(bp::dataIndex(TimeDirection::Forward, 0, 3), 0);
  // The window's latest time releases first backward.
  const std::array<double, 2> window = bp::traceWindow(TimeDirection::Backward, 1.0, 3.0);
  EXPECT_EQ(window[0], -3.0);
  EXPECT_EQ(window[1], -1.0);
  bp::FieldSlice s;
  s.time = 2.0;
  s.velocity = std::make_shared<std::vector<float>>(std::vector<float>{ 1.0f, -2.0f, 0.5f });
  const bp::FieldSlice reversed = bp::traceSlice(TimeDirection::Backward, s);
  EXPECT_EQ(reversed.time, -2.0);
  EXPECT_EQ(*reversed.velocity, (std::vector<float>{ -1.0f, 2.0f, -0.5f }));
  EXPECT_EQ((*s.velocity)[0], 1.0f) << "the data's slice is left as it was";
  EXPECT_EQ(bp::traceSlice(TimeDirection::Forward, s).velocity, s.velocity);
}

TEST(TimeDirection, APlanBackwardOffersTheDatasTimesAndStartsAtTheirEnd)
{
  bp::TracePlan plan;
  ASSERT_EQ(plan.setTimes({ 0.0, 1.0, 2.0 }, 10.0, 101, 2, bp::TimeDirection::Backward), "");
  EXPECT_EQ(plan.offeredTimes(), (std::vector<double>{ 0.0, 0.5, 1.0, 1.5, 2.0 }));
  EXPECT_EQ(plan.startTime(), -2.0) << "the trace starts at the data's end";
  EXPECT_EQ(plan.inputTimes(), (std::vector<double>{ -2.0, -1.0, -0.0 }));
  EXPECT_EQ(plan.dataTimeOf(0), 2.0);
  EXPECT_EQ(plan.dataTimeOf(2), 0.0);
  EXPECT_EQ(plan.targetOf(true, 0.5), -0.5);
  EXPECT_EQ(plan.targetOf(true, 5.0), -2.0) << "past the data's end: the trace's start";
  EXPECT_EQ(plan.targetOf(true, -5.0), 0.0) << "before the data's start: the trace's end";
  EXPECT_EQ(plan.targetOf(false, 0.0), -2.0);
  // Stepping on from the start needs the data's last interval, trace indices {0, 1}.
  EXPECT_EQ(plan.needed(plan.startTime(), -0.5), (std::vector<int>{ 0, 1 }));
  // Forward is as it was.
  ASSERT_EQ(plan.setTimes({ 0.0, 1.0, 2.0 }, 10.0, 101, 2), "");
  EXPECT_EQ(plan.direction(), bp::TimeDirection::Forward);
  EXPECT_EQ(plan.offeredTimes(), plan.outputTimes());
  EXPECT_EQ(plan.dataTimeOf(0), 0.0);
}

// What the plan says of a trace's times, it says in the data's times: a
// backward trace's own are their mirror, which the user never sees.
TEST(TimeDirection, APlansMessagesGiveTheDatasTimes)
{
  bp::TracePlan plan;
  ASSERT_EQ(plan.setTimes({ 0.0, 1.0, 2.0 }, 10.0, 101, 2, bp::TimeDirection::Backward), "");
  const std::string message = plan.checkWork(-2.0, -0.5, 1e-9);
  EXPECT_NE(message.find("Reaching t = 0.5 from t = 2 "), std::string::npos) << message;
}

TEST(TimeDirection, SolidBodyRotationBackwardReachesTheAnalyticEarlierPositions)
{
  // Released at t = pi (the steady time line's end), traced back to t = pi / 2 and to 0.
  const std::vector<float> seeds = { 0.5f, 0.0f, 0.0f, 0.0f, -0.3f, 0.0f, -0.2f, 0.4f, 0.0f };
  const double duration = Pi, w = turningRate();
  ASSERT_NE(w, 0.0);
  for (double target : { Pi / 2, 0.0 })
  {
    const std::vector<float> q = trace(bp::TimeDirection::Backward,
      bp::AnalyticFlow::SolidBodyRotation, {}, duration, seeds, target, 0.01);
    // x(t) = R(w (t - T)) x(T).
    const double a = w * (target - duration), c = std::cos(a), s = std::sin(a);
    for (std::size_t e = 0; e < seeds.size() / 3; ++e)
    {
      const float* x = seeds.data() + 3 * e;
      EXPECT_NEAR(q[3 * e], c * x[0] - s * x[1], 1e-5) << "element " << e << " at t " << target;
      EXPECT_NEAR(q[3 * e + 1], s * x[0] + c * x[1], 1e-5) << "element " << e;
      EXPECT_NEAR(q[3 * e + 2], 0.0, 1e-6);
    }
  }
  // Forward turns the other way.
  const std::vector<float> forward = trace(bp::TimeDirection::Forward,
    bp::AnalyticFlow::SolidBodyRotation, {}, duration, seeds, Pi / 2, 0.01);
  EXPECT_NEAR(forward[1], 0.5 * std::sin(w * Pi / 2), 1e-5);
}

TEST(TimeDirection, ForwardThenBackwardOverTheSameIntervalReturnsToTheStart)
{
  // The double gyre, unsteady: 11 time steps over [0, 5]; every integrator
  // comes back, RK4 within 1e-6 of the domain (its side is 2).
  const std::vector<double> times = bp::analyticFlowTimeSteps(bp::AnalyticFlow::DoubleGyre, 11);
  const std::vector<float> start = { -0.5f, 0.3f, 0.0f, 0.25f, -0.6f, 0.0f, 0.7f, 0.55f, 0.0f,
    -0.1f, -0.05f, 0.0f };
  const double tolerance[3] = { 0.1, 1e-5, 2e-6 }; // Euler: first order, 0.045 here
  for (int m = 0; m < 3; ++m)
  {
    const bp::Integrator integrator = bp::Integrator(m);
    const std::vector<float> there = trace(bp::TimeDirection::Forward, bp::AnalyticFlow::DoubleGyre,
      times, 0.0, start, times.back(), 0.01, integrator);
    const std::vector<float> back = trace(bp::TimeDirection::Backward, bp::AnalyticFlow::DoubleGyre,
      times, 0.0, there, times.front(), 0.01, integrator);
    double moved = 0.0, worst = 0.0;
    for (std::size_t e = 0; e < start.size() / 3; ++e)
    {
      moved = std::max<double>(moved, bptest::distance(&there[3 * e], &start[3 * e]));
      worst = std::max<double>(worst, bptest::distance(&back[3 * e], &start[3 * e]));
    }
    EXPECT_GT(moved, 0.1) << "the flow carries the elements away first";
    EXPECT_LT(worst, tolerance[m]) << bp::enumName(integrator);
  }
}

TEST(TimeDirection, HeavyParticlesAreTracedForwardOnly)
{
  bp::TraceSettings s;
  s.engine.inertia = bp::Inertia::MaxeyRiley;
  s.timeDirection = bp::TimeDirection::Backward;
  const bp::Resolution r = bp::resolveSettings(s, bp::FieldFacts());
  EXPECT_NE(r.error.find("Time Direction = Backward"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("Inertia"), std::string::npos);
  s.timeDirection = bp::TimeDirection::Forward;
  EXPECT_EQ(bp::resolveSettings(s, bp::FieldFacts()).error, "");
  s.engine.inertia = bp::Inertia::None;
  s.timeDirection = bp::TimeDirection::Backward;
  EXPECT_EQ(bp::resolveSettings(s, bp::FieldFacts()).error, "");
}
