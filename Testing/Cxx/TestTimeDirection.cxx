// SPDX-License-Identifier: BSD-3-Clause
// Time Direction on the tracer: a backward trace releases at the end of the
// time line and turns elements the other way of a forward one, on the data's
// own time steps; heavy particles and a release window outside the data's
// times are said.
#include "TracerTestHelpers.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>

namespace
{
using SDDP = vtkStreamingDemandDrivenPipeline;
constexpr double Pi = 3.14159265358979323846;

/// Point elements in solid-body rotation (one turn per 2 pi about z) over
/// the time line [0, 2].
vtkSmartPointer<vtkBoundParticleTracer> rotating(vtkAlgorithm* source, bp::TimeDirection direction)
{
  auto tracer = tracerOn(source, 50);
  tracer->SetEngine(int(bp::EngineChoice::Cpu));
  tracer->SetElementShape(int(bp::BuiltinShape::Point));
  tracer->SetEmitterCenter(0.0, 0.0, 0.0);
  tracer->SetEmitterSize(0.8, 0.8, 0.8);
  tracer->SetLifetimeRange(100.0, 100.0);
  tracer->SetDuration(2.0);
  tracer->SetNumberOfTimeSteps(11);
  tracer->SetTimeDirection(int(direction));
  return tracer;
}

/// How far each element turned about z from `from` to `to`, in (-pi, pi].
std::vector<double> turns(const std::vector<float>& from, const std::vector<float>& to)
{
  std::vector<double> angles;
  for (std::size_t i = 0; i + 2 < from.size() && i + 2 < to.size(); i += 3)
  {
    double a = std::atan2(to[i + 1], to[i]) - std::atan2(from[i + 1], from[i]);
    a = a > Pi ? a - 2 * Pi : (a <= -Pi ? a + 2 * Pi : a);
    angles.push_back(a);
  }
  return angles;
}
} // namespace

TEST(TimeDirection, BackwardTurnsElementsTheOtherWayOnTheDatasTimeSteps)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation);
  auto forward = rotating(source, bp::TimeDirection::Forward);
  auto backward = rotating(source, bp::TimeDirection::Backward);
  EXPECT_STREQ(backward->GetTimeDirectionAsString(), "Backward");
  // The offered time steps stay the data's.
  for (auto* tracer : { forward.Get(), backward.Get() })
  {
    tracer->UpdateInformation();
    vtkInformation* info = tracer->GetOutputInformation(0);
    ASSERT_EQ(info->Length(SDDP::TIME_STEPS()), 11);
    EXPECT_DOUBLE_EQ(info->Get(SDDP::TIME_STEPS())[0], 0.0);
    EXPECT_DOUBLE_EQ(info->Get(SDDP::TIME_STEPS())[10], 2.0);
  }
  // Forward releases at 0 and turns by +1 to t = 1; backward releases at 2
  // and turns by -1 back to t = 1.
  const std::vector<float> forwardStart = pointsOf(at(forward, 0.0));
  const std::vector<float> forwardAt1 = pointsOf(at(forward, 1.0));
  const std::vector<float> backwardStart = pointsOf(at(backward, 2.0));
  const std::vector<float> backwardAt1 = pointsOf(at(backward, 1.0));
  EXPECT_DOUBLE_EQ(backward->GetSimulationTime(), 1.0);
  EXPECT_DOUBLE_EQ(
    backward->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 1.0);
  ASSERT_EQ(forwardStart.size(), 150u);
  ASSERT_EQ(backwardStart.size(), 150u);
  ASSERT_EQ(backwardAt1.size(), 150u);
  for (double a : turns(forwardStart, forwardAt1))
    EXPECT_NEAR(a, 1.0, 1e-3);
  for (double a : turns(backwardStart, backwardAt1))
    EXPECT_NEAR(a, -1.0, 1e-3);
  // Earlier times continue the backward trace; later ones go back to it.
  const std::vector<float> backwardAt0 = pointsOf(at(backward, 0.0));
  EXPECT_FALSE(backward->GetLastUpdateReplayed()) << "t = 0 continues on from t = 1";
  for (double a : turns(backwardStart, backwardAt0))
    EXPECT_NEAR(a, -2.0, 1e-3);
  EXPECT_EQ(pointsOf(at(backward, 1.0)), backwardAt1) << "t = 1 again, as before";
  auto fresh = rotating(source, bp::TimeDirection::Backward);
  EXPECT_EQ(pointsOf(at(fresh, 0.0)), backwardAt0) << "a fresh run to t = 0 is the same";
}

TEST(TimeDirection, HeavyParticlesBackwardAreRefusedWithAMessage)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation);
  auto tracer = rotating(source, bp::TimeDirection::Backward);
  tracer->SetInertia(int(bp::Inertia::MaxeyRiley));
  ErrorLog errors(tracer);
  EXPECT_EQ(at(tracer, 1.0)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions("Time Direction = Backward")) << errors.messages.size();
  tracer->SetInertia(int(bp::Inertia::None));
  EXPECT_EQ(at(tracer, 1.0)->GetNumberOfPoints(), 50) << "recovers once Inertia is None";
}

TEST(TimeDirection, ABackwardReleaseWindowOutsideTheDatasTimesIsSaid)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation);
  auto tracer = rotating(source, bp::TimeDirection::Backward);
  tracer->SetReleaseWindow(1);
  tracer->SetReleaseStart(5.0);
  tracer->SetReleaseStop(6.0);
  ErrorLog warnings(tracer, vtkCommand::WarningEvent);
  at(tracer, 1.0);
  EXPECT_TRUE(warnings.mentions("Release Window [5, 6] lies outside the offered times [0, 2]"))
    << (warnings.messages.empty() ? "" : warnings.messages.front());
  // Inside the window: released at its latest time, 1.5, and traced back.
  tracer->SetReleaseStart(0.5);
  tracer->SetReleaseStop(1.5);
  ErrorLog later(tracer, vtkCommand::WarningEvent);
  // A hidden element keeps its points but has no cells.
  EXPECT_EQ(at(tracer, 1.8)->GetNumberOfCells(), 0) << "not yet released at 1.8";
  EXPECT_GT(at(tracer, 1.0)->GetNumberOfCells(), 0);
  EXPECT_TRUE(later.messages.empty()) << later.messages.front();
}

// A window that ends before it starts is refused in the data's times, as
// forward, not in the trace's mirrored ones.
TEST(TimeDirection, AReversedReleaseWindowIsSaidInTheDatasTimes)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation);
  auto tracer = rotating(source, bp::TimeDirection::Backward);
  tracer->SetReleaseWindow(1);
  tracer->SetReleaseStart(1.5);
  tracer->SetReleaseStop(0.5);
  ErrorLog errors(tracer);
  EXPECT_EQ(at(tracer, 1.0)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions("ReleaseStart 1.5 is after ReleaseStop 0.5"))
    << (errors.messages.empty() ? "" : errors.messages.front());
}

// The output's Velocity is the data's at each point, in the data's sign, on
// a backward trace too (the trace samples the negated flow): solid-body
// rotation about z, u = (-y, x, 0).
TEST(TimeDirection, BackwardVelocityIsTheDatas)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation);
  auto tracer = rotating(source, bp::TimeDirection::Backward);
  vtkPolyData* out = at(tracer, 1.0);
  vtkDataArray* velocity = out->GetPointData()->GetArray("Velocity");
  ASSERT_NE(velocity, nullptr);
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3], u[3];
    out->GetPoint(i, x);
    velocity->GetTuple(i, u);
    worst = std::max({ worst, std::abs(u[0] + x[1]), std::abs(u[1] - x[0]) });
  }
  EXPECT_LT(worst, 0.02) << "Velocity is not (-y, x): its sign is the trace's";
}

// Both engines trace backward: Engine GPU is taken as asked, without a word
// (with no display to run it, this process's output is the CPU engine's;
// python.Representation draws the GPU engine's backward trace).
TEST(TimeDirection, EngineGpuTracesBackwardWithoutAWarning)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation);
  auto tracer = rotating(source, bp::TimeDirection::Backward);
  tracer->SetEngine(int(bp::EngineChoice::Gpu));
  ErrorLog warnings(tracer, vtkCommand::WarningEvent);
  EXPECT_EQ(at(tracer, 1.0)->GetNumberOfPoints(), 50);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
}
