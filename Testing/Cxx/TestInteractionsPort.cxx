// SPDX-License-Identifier: BSD-3-Clause
// The tracer's Interactions output (port 3, Filters/TracerInteractions.h): on
// a uniform flow into the +x side, Stick records each particle's first
// contact once, on the side and with its normal; Release Again records each
// element that leaves at its centre; going back in time (a checkpoint
// resumed) gives the events of a straight trace to that time, and forward
// again those of before.
#include "TracerTestHelpers.h"

#include "Interactions.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkPassThrough.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <map>
#include <tuple>
#include <utility>

namespace
{
/// A uniform flow (1, 0.2, 0) on [0, 1]^3 (11 points a side): elements
/// drift onto the +x side, some onto +y.
vtkSmartPointer<vtkTrivialProducer> intoTheSide()
{
  auto img = image(11, 11, 11);
  auto v = array("v", 3, img->GetNumberOfPoints(), 0.0f);
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
  {
    v->SetComponent(i, 0, 1.0);
    v->SetComponent(i, 1, 0.2);
  }
  img->GetPointData()->SetVectors(v);
  auto producer = vtkSmartPointer<vtkTrivialProducer>::New();
  producer->SetOutput(img);
  return producer;
}

vtkSmartPointer<vtkBoundParticleTracer> tracer(vtkAlgorithm* source, bp::Boundary boundary)
{
  auto t = tracerOn(source, 40);
  t->SetBoundary(boundary);
  t->SetElementShape(bp::BuiltinShape::Strip4);
  t->SetDuration(2.0);
  t->SetNumberOfTimeSteps(21);
  t->SetLifetimeRange(5.0, 5.0);
  return t;
}

/// Port 3 asked for at `time` (the port a consumer of it asks).
vtkPolyData* interactionsAt(vtkBoundParticleTracer* t, double time)
{
  t->UpdateInformation();
  t->GetOutputInformation(3)->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), time);
  t->Update(3);
  return vtkPolyData::SafeDownCast(t->GetOutputDataObject(3));
}

/// Every event as a comparable row: (Time, ElementId, ParticleIndex,
/// Interaction, SurfaceId, x, y, z).
using Row = std::tuple<double, int, int, int, int, double, double, double>;
std::vector<Row> rows(vtkPolyData* pd)
{
  std::vector<Row> out;
  auto* time = vtkDoubleArray::SafeDownCast(pd->GetPointData()->GetArray("Time"));
  auto* id = vtkIntArray::SafeDownCast(pd->GetPointData()->GetArray("ElementId"));
  auto* particle = vtkIntArray::SafeDownCast(pd->GetPointData()->GetArray("ParticleIndex"));
  auto* kind = vtkIntArray::SafeDownCast(pd->GetPointData()->GetArray("Interaction"));
  auto* side = vtkIntArray::SafeDownCast(pd->GetPointData()->GetArray("SurfaceId"));
  if (pd->GetNumberOfPoints() == 0)
    return out;
  EXPECT_TRUE(time && id && particle && kind && side);
  if (!(time && id && particle && kind && side))
    return out;
  for (vtkIdType k = 0; k < pd->GetNumberOfPoints(); ++k)
  {
    double p[3];
    pd->GetPoint(k, p);
    out.emplace_back(time->GetValue(k), id->GetValue(k), particle->GetValue(k), kind->GetValue(k),
      side->GetValue(k), p[0], p[1], p[2]);
  }
  return out;
}
} // namespace

TEST(InteractionsPort, StickRecordsEachParticlesFirstContactOnce)
{
  auto source = intoTheSide();
  auto t = tracer(source, bp::Boundary::Stick);
  vtkPolyData* events = interactionsAt(t, 2.0);
  ASSERT_TRUE(events);
  const std::vector<Row> all = rows(events);
  ASSERT_GT(all.size(), 40u); // most particles of 40 strips reach x = 1
  EXPECT_EQ(events->GetNumberOfVerts(), events->GetNumberOfPoints());
  std::map<std::pair<int, int>, int> perParticle;
  std::map<int, int> sides;
  auto* normals = events->GetPointData()->GetArray("Normal");
  ASSERT_TRUE(normals);
  ASSERT_TRUE(events->GetPointData()->GetArray("ElementVelocity"));
  EXPECT_EQ(events->GetPointData()->GetArray("ElementVelocity")->GetNumberOfComponents(), 3);
  for (std::size_t k = 0; k < all.size(); ++k)
  {
    const auto& [time, id, particle, kind, side, x, y, z] = all[k];
    ++perParticle[{ id, particle }];
    EXPECT_EQ(kind, int(bp::Interaction::Stuck));
    EXPECT_GE(particle, 0);
    // Mostly +x; +y, or another side an element was released across.
    ASSERT_TRUE(side >= 0 && side < 6) << side;
    const double p[3] = { x, y, z };
    EXPECT_NEAR(p[side / 2], side % 2 ? 1.0 : 0.0, 1e-6) << "on the side met";
    const double* n = normals->GetTuple3(vtkIdType(k));
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(n[a], a != side / 2 ? 0.0 : side % 2 ? 1.0 : -1.0);
    sides[side] += 1;
    EXPECT_GT(time, 0.0);
    EXPECT_LE(time, 2.0 + 1e-9);
    if (k > 0)
      EXPECT_LE(all[k - 1], all[k]) << "in (Time, ElementId, ParticleIndex) order";
  }
  for (const auto& c : perParticle)
    EXPECT_EQ(c.second, 1) << "element " << c.first.first << " particle " << c.first.second;
  EXPECT_GT(sides[1], int(all.size()) / 2); // the flow's side
  auto* names =
    vtkStringArray::SafeDownCast(events->GetFieldData()->GetAbstractArray("InteractionNames"));
  ASSERT_TRUE(names);
  EXPECT_EQ(names->GetValue(int(bp::Interaction::Stuck)), "Stuck");

  // Going back in time (from a checkpoint) gives the straight trace's events to
  // that time, and forward again those of before.
  const std::vector<Row> later = all;
  const std::vector<Row> back = rows(interactionsAt(t, 0.7));
  auto fresh = tracer(source, bp::Boundary::Stick);
  EXPECT_EQ(back, rows(interactionsAt(fresh, 0.7)));
  EXPECT_LT(back.size(), later.size());
  for (const Row& r : back)
    EXPECT_LE(std::get<0>(r), 0.7 + 1e-9);
  EXPECT_EQ(rows(interactionsAt(t, 2.0)), later);
  // A time between two frames (a short step shown and taken back).
  const std::vector<Row> between = rows(interactionsAt(t, 1.05));
  EXPECT_EQ(between, rows(interactionsAt(fresh, 1.05)));
  EXPECT_EQ(rows(interactionsAt(t, 2.0)), later);
}

TEST(InteractionsPort, ReleaseAgainRecordsEachElementThatLeaves)
{
  auto source = intoTheSide();
  auto t = tracer(source, bp::Boundary::ReleaseAgain);
  const std::vector<Row> all = rows(interactionsAt(t, 2.0));
  ASSERT_GT(all.size(), 20u);
  std::map<std::pair<int, double>, int> perStep;
  for (const auto& [time, id, particle, kind, side, x, y, z] : all)
  {
    EXPECT_EQ(kind, int(bp::Interaction::Released));
    EXPECT_EQ(particle, -1);
    ASSERT_TRUE(side == 1 || side == 3) << side;
    EXPECT_GT(side == 1 ? x : y, 1.0); // the centre beyond the side
    ++perStep[{ id, time }];
  }
  for (const auto& c : perStep)
    EXPECT_EQ(c.second, 1);
  // The elements port is the trace of before (the events change nothing).
  EXPECT_GT(t->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(InteractionsPort, IsFilledOnlyWhenAskedForOrConsumed)
{
  // An update for the elements with nothing consuming port 3 leaves it as it
  // was, not generated (playing builds nothing for it); asking for it then
  // fills it at the time shown, and a consumer keeps it filled.
  auto source = intoTheSide();
  auto t = tracer(source, bp::Boundary::Stick);
  t->UpdateTimeStep(1.05); // between two frames: a short step shown
  EXPECT_EQ(vtkPolyData::SafeDownCast(t->GetOutputDataObject(3))->GetNumberOfPoints(), 0);
  const vtkMTimeType elements = t->GetOutput()->GetMTime();
  const vtkIdType steps = t->GetStepsInLastUpdate();
  const std::vector<Row> asked = rows(interactionsAt(t, 1.05));
  ASSERT_FALSE(asked.empty());
  // The events of the time shown: nothing stepped, the elements left as they are.
  EXPECT_EQ(t->GetOutput()->GetMTime(), elements);
  EXPECT_EQ(t->GetStepsInLastUpdate(), steps);
  auto fresh = tracer(source, bp::Boundary::Stick);
  EXPECT_EQ(asked, rows(interactionsAt(fresh, 1.05)));
  // After the State output took the short step back: the same events.
  t->UpdateInformation();
  t->GetOutputInformation(2)->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), 1.05);
  t->Update(2);
  EXPECT_GT(vtkPolyData::SafeDownCast(t->GetOutputDataObject(2))->GetNumberOfPoints(), 0);
  EXPECT_EQ(rows(interactionsAt(t, 1.05)), asked);
  EXPECT_EQ(t->GetOutput()->GetMTime(), elements);
  vtkNew<vtkTrivialProducer> unused; // nothing: a consumer is any algorithm on the port
  vtkNew<vtkPassThrough> consumer;
  consumer->SetInputConnection(t->GetOutputPort(3));
  t->UpdateTimeStep(2.0);
  const std::vector<Row> consumed = rows(vtkPolyData::SafeDownCast(t->GetOutputDataObject(3)));
  EXPECT_GT(consumed.size(), asked.size());
  EXPECT_EQ(consumed, rows(interactionsAt(fresh, 2.0)));
}

TEST(InteractionsPort, PlayingAppendsTheStepsAddedAndGoingBackCutsTheRest)
{
  // Shown while playing, the output appends the events of the steps added
  // (its arrays kept and grown: the cost of an update is the events added,
  // not the trace's), the short step shown at a frame between two step
  // boundaries taken off first; each frame's events are a new trace's to
  // that time. Going back in time keeps the events of before and cuts the
  // rest; forward again appends them.
  auto source = intoTheSide();
  auto t = tracer(source, bp::Boundary::Stick);
  vtkDataArray* kept = nullptr;
  std::size_t before = 0;
  for (int frame = 1; frame <= 20; ++frame)
  {
    const double time = 0.1 * frame;
    vtkPolyData* pd = interactionsAt(t, time);
    const std::vector<Row> shown = rows(pd);
    auto fresh = tracer(source, bp::Boundary::Stick);
    ASSERT_EQ(shown, rows(interactionsAt(fresh, time))) << "at " << time;
    EXPECT_EQ(pd->GetNumberOfVerts(), pd->GetNumberOfPoints());
    EXPECT_GE(shown.size(), before);
    before = shown.size();
    vtkDataArray* times = pd->GetPointData()->GetArray("Time");
    if (kept && times)
      EXPECT_EQ(times, kept) << "appended to at " << time;
    if (times)
      kept = times;
  }
  ASSERT_TRUE(kept);
  ASSERT_GT(before, 40u);
  const std::vector<Row> played = rows(interactionsAt(t, 2.0));
  auto fresh = tracer(source, bp::Boundary::Stick);
  const std::vector<Row> back = rows(interactionsAt(t, 0.75));
  EXPECT_EQ(back, rows(interactionsAt(fresh, 0.75)));
  EXPECT_LT(back.size(), played.size());
  EXPECT_EQ(rows(interactionsAt(t, 2.0)), played);
}

TEST(InteractionsPort, ABackwardTraceIsInTheTracesOrder)
{
  // The events follow the trace: in a backward trace the data's time of
  // each event (Time) decreases along the output.
  auto source = intoTheSide();
  auto t = tracer(source, bp::Boundary::Stick);
  t->SetTimeDirection(bp::TimeDirection::Backward);
  const std::vector<Row> all = rows(interactionsAt(t, 0.0));
  ASSERT_GT(all.size(), 10u);
  EXPECT_GT(std::get<0>(all.front()), std::get<0>(all.back()));
  for (std::size_t k = 1; k < all.size(); ++k)
    EXPECT_GE(std::get<0>(all[k - 1]), std::get<0>(all[k]));
}
