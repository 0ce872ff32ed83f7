// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAnalyticFlowSource.h"
#include "vtkBoundParticleTracer.h"

#include "ElementTemplate.h"
#include "OutputArrays.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageAlgorithm.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

/// A uniform flow along +x whose time steps are float32 values (0.1f k), as
/// many files store them: they sit a hair off a 0.1 step grid.
class vtkFloatTimesSource : public vtkImageAlgorithm
{
public:
  static vtkFloatTimesSource* New();
  vtkTypeMacro(vtkFloatTimesSource, vtkImageAlgorithm);
  int Steps = 11;
  double Origin = 0.0;
  double Speed = 0.1;       ///< of `v`, the active vectors
  double OtherSpeed = -1.0; ///< of a second array `v_other`; none where negative
  int Executions = 0;       ///< how many times RequestData ran

protected:
  vtkFloatTimesSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    const int extent[6] = { 0, 10, 0, 10, 0, 10 };
    const double origin[3] = { this->Origin, this->Origin, this->Origin };
    const double spacing[3] = { 0.1, 0.1, 0.1 };
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    info->Set(vtkDataObject::ORIGIN(), origin, 3);
    info->Set(vtkDataObject::SPACING(), spacing, 3);
    std::vector<double> times;
    for (int k = 0; k < this->Steps; ++k)
      times.push_back(double(0.1f * float(k)));
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), int(times.size()));
    const double range[2] = { times.front(), times.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    ++this->Executions;
    vtkInformation* info = out->GetInformationObject(0);
    vtkImageData* image = vtkImageData::GetData(info);
    image->SetExtent(0, 10, 0, 10, 0, 10);
    image->SetOrigin(this->Origin, this->Origin, this->Origin);
    image->SetSpacing(0.1, 0.1, 0.1);
    vtkNew<vtkFloatArray> v;
    v->SetName("v");
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(image->GetNumberOfPoints());
    for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
      v->SetTuple3(i, this->Speed, 0.0, 0.0);
    image->GetPointData()->SetVectors(v);
    if (this->OtherSpeed >= 0.0)
    {
      vtkNew<vtkFloatArray> other;
      other->SetName("v_other");
      other->SetNumberOfComponents(3);
      other->SetNumberOfTuples(image->GetNumberOfPoints());
      for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
        other->SetTuple3(i, this->OtherSpeed, 0.0, 0.0);
      image->GetPointData()->AddArray(other);
    }
    if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
      image->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(),
        info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
    return 1;
  }
};
vtkStandardNewMacro(vtkFloatTimesSource);

#include "OutputArrays.h"
#include "TracerTestHelpers.h"

TEST(BoundParticleTracer, OutputSizesAndArrays)
{
  auto source = flow(bp::AnalyticFlow::ABC, 16);
  const struct
  {
    bp::BuiltinShape shape;
    int particles, triangles;
    bool strip; ///< one triangle strip per element
  } shapes[] = { { bp::BuiltinShape::Point, 1, 0, false },
    { bp::BuiltinShape::Strip16, 16, 14, true }, { bp::BuiltinShape::Cross, 12, 10, false },
    { bp::BuiltinShape::Fish, 23, 40, false } };
  for (const auto& s : shapes)
  {
    auto tracer = tracerOn(source, 37);
    tracer->SetElementShape(s.shape);
    vtkPolyData* out = at(tracer, 1.0);
    ASSERT_EQ(out->GetNumberOfPoints(), 37 * s.particles);
    if (s.strip)
    {
      // A strip of n points holds n - 2 triangles.
      ASSERT_EQ(out->GetNumberOfStrips(), 37);
      EXPECT_EQ(out->GetStrips()->GetNumberOfConnectivityIds() - 2 * 37, 37 * s.triangles);
      EXPECT_EQ(out->GetNumberOfPolys(), 0);
    }
    else if (s.triangles)
    {
      EXPECT_EQ(out->GetNumberOfPolys(), 37 * s.triangles);
      EXPECT_EQ(out->GetNumberOfVerts(), 0);
    }
    else
    {
      EXPECT_EQ(out->GetNumberOfVerts(), 37);
    }
    const struct
    {
      const char* name;
      int components;
    } arrays[] = { { "Normals", 3 }, { "Velocity", 3 }, { "Speed", 1 }, { "Force", 1 },
      { "Lifetime", 1 }, { "ElementId", 1 }, { "ParticleIndex", 1 }, { "Vorticity", 1 },
      { "Layer", 1 }, { "Radius", 1 } };
    for (const auto& a : arrays)
    {
      vtkDataArray* d = out->GetPointData()->GetArray(a.name);
      ASSERT_NE(d, nullptr) << a.name;
      EXPECT_EQ(d->GetNumberOfComponents(), a.components) << a.name;
      EXPECT_EQ(d->GetNumberOfTuples(), out->GetNumberOfPoints()) << a.name;
      for (int c = 0; c < a.components; ++c)
      {
        const double* r = d->GetRange(c);
        EXPECT_TRUE(std::isfinite(r[0]) && std::isfinite(r[1])) << a.name;
      }
    }
    EXPECT_EQ(out->GetPointData()->GetArray("ElementId")->GetRange()[1], 36);
    EXPECT_EQ(out->GetPointData()->GetArray("ParticleIndex")->GetRange()[1], s.particles - 1);
    EXPECT_NEAR(out->GetFieldData()->GetArray("SimulationTime")->GetTuple1(0), 1.0, 1e-12);
  }
}

TEST(BoundParticleTracer, VorticityArrayCanBeLeftOut)
{
  // Compute Vorticity changes the output's arrays, never the trace.
  auto source = flow(bp::AnalyticFlow::ABC);
  auto tracer = tracerOn(source, 50);
  vtkPolyData* out = at(tracer, 0.5);
  ASSERT_NE(out->GetPointData()->GetArray("Vorticity"), nullptr);
  EXPECT_GT(out->GetPointData()->GetArray("Vorticity")->GetRange()[1], 0.0);
  const std::vector<float> with = pointsOf(out);
  tracer->ComputeVorticityOff();
  out = at(tracer, 0.5);
  EXPECT_EQ(out->GetPointData()->GetArray("Vorticity"), nullptr);
  EXPECT_NE(out->GetPointData()->GetArray("Velocity"), nullptr);
  EXPECT_EQ(pointsOf(out), with);
  tracer->ComputeVorticityOn();
  out = at(tracer, 0.5);
  EXPECT_NE(out->GetPointData()->GetArray("Vorticity"), nullptr);
}

TEST(BoundParticleTracer, OutputArraysAreAVtkDataArraySelection)
{
  // The Output Arrays property (SetOutputArrayStatus) and a script's
  // GetOutputArraySelection() are one selection: the table's rows, in order,
  // the pose arrays off; a change through either reaches the output.
  auto source = flow(bp::AnalyticFlow::ABC);
  auto tracer = tracerOn(source, 50);
  vtkDataArraySelection* selection = tracer->GetOutputArraySelection();
  const auto& rows = bp::outputArrays();
  ASSERT_EQ(selection->GetNumberOfArrays(), int(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    EXPECT_STREQ(selection->GetArrayName(int(i)), rows[i].name);
    EXPECT_EQ(tracer->GetOutputArrayStatus(rows[i].name), rows[i].onByDefault ? 1 : 0);
  }
  tracer->SetOutputArrayStatus("NoSuchArray", 1); // warns, adds nothing
  EXPECT_EQ(selection->GetNumberOfArrays(), int(rows.size()));
  const std::vector<float> all = pointsOf(at(tracer, 0.5));
  selection->DisableArray("Speed");
  vtkPolyData* out = at(tracer, 0.5);
  EXPECT_EQ(out->GetPointData()->GetArray("Speed"), nullptr);
  EXPECT_NE(out->GetPointData()->GetArray("Velocity"), nullptr);
  EXPECT_EQ(pointsOf(out), all);
  tracer->SetOutputArrayStatus("Speed", 1);
  EXPECT_TRUE(selection->ArrayIsEnabled("Speed"));
  EXPECT_NE(at(tracer, 0.5)->GetPointData()->GetArray("Speed"), nullptr);
}

TEST(BoundParticleTracer, SteadyInputGetsTimeSteps)
{
  auto source = flow(bp::AnalyticFlow::ShearLayer);
  auto tracer = tracerOn(source);
  tracer->SetDuration(4.0);
  tracer->SetNumberOfTimeSteps(9);
  tracer->UpdateInformation();
  vtkInformation* info = tracer->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 9);
  EXPECT_DOUBLE_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[8], 4.0);
  const std::vector<float> start = pointsOf(at(tracer, 0.0));
  const std::vector<float> later = pointsOf(at(tracer, 0.5));
  EXPECT_NE(start, later); // the steady flow plays
}

TEST(BoundParticleTracer, ForwardContinuesAndEqualsAFreshRun)
{
  auto source = flow(bp::AnalyticFlow::Hurricane);
  auto incremental = tracerOn(source);
  incremental->SetLifetimeRange(0.3, 0.9); // resets happen along the way
  at(incremental, 1.0);
  const vtkIdType stepsTo1 = incremental->GetStepsInLastUpdate();
  const std::vector<float> pieces = pointsOf(at(incremental, 2.35));
  EXPECT_FALSE(incremental->GetLastUpdateReplayed());
  const vtkIdType stepsOn = incremental->GetStepsInLastUpdate();

  auto fresh = tracerOn(source);
  fresh->SetLifetimeRange(0.3, 0.9);
  const std::vector<float> direct = pointsOf(at(fresh, 2.35));
  EXPECT_TRUE(fresh->GetLastUpdateReplayed());
  // Continuing from 1.0 took only the steps after it.
  EXPECT_NEAR(double(stepsOn), double(fresh->GetStepsInLastUpdate() - stepsTo1), 2.0);
  EXPECT_EQ(pieces, direct);
}

TEST(BoundParticleTracer, BackwardResumesFromACheckpointAndChangesReplay)
{
  auto source = flow(bp::AnalyticFlow::VerticalShear);
  auto tracer = tracerOn(source);
  tracer->SetLifetimeRange(0.3, 0.9); // resets happen along the way
  // The automatic budget (half the trace's size) keeps some checkpoints.
  at(tracer, 2.0);
  const vtkIdType automatic = tracer->GetCheckpointSpacing();
  EXPECT_GT(automatic, 0);
  tracer->SetCheckpointMemory(64.0); // a checkpoint every step here
  at(tracer, 2.0);
  EXPECT_EQ(tracer->GetCheckpointSpacing(), 1);
  // Back to 0.7: from the latest checkpoint at or before it, not the start;
  // the same bits as a fresh run to 0.7, in fewer steps.
  const std::vector<float> back = pointsOf(at(tracer, 0.7));
  EXPECT_FALSE(tracer->GetLastUpdateReplayed());
  const vtkIdType resumedSteps = tracer->GetStepsInLastUpdate();
  EXPECT_LE(resumedSteps, 2); // the boundary before 0.7, then the short step to it
  auto fresh = tracerOn(source);
  fresh->SetLifetimeRange(0.3, 0.9);
  EXPECT_EQ(back, pointsOf(at(fresh, 0.7)));
  EXPECT_LT(resumedSteps, fresh->GetStepsInLastUpdate());
  // Back and forth across the checkpoints: every time the fresh run's bits.
  for (double t : { 1.9, 0.05, 1.33, 1.32, 0.71 })
  {
    const std::vector<float> resumed = pointsOf(at(tracer, t));
    auto other = tracerOn(source);
    other->SetLifetimeRange(0.3, 0.9);
    EXPECT_EQ(resumed, pointsOf(at(other, t))) << "t = " << t;
  }
  // With no checkpoint memory, back is a replay from the start, as before.
  tracer->SetCheckpointMemory(0.0);
  at(tracer, 2.0);
  EXPECT_EQ(back, pointsOf(at(tracer, 0.7)));
  EXPECT_TRUE(tracer->GetLastUpdateReplayed());
  EXPECT_EQ(tracer->GetStepsInLastUpdate(), fresh->GetStepsInLastUpdate());

  at(tracer, 0.9);
  EXPECT_FALSE(tracer->GetLastUpdateReplayed());
  tracer->SetSeed(12);
  const std::vector<float> reseeded = pointsOf(at(tracer, 0.9));
  EXPECT_TRUE(tracer->GetLastUpdateReplayed());
  EXPECT_NE(reseeded, pointsOf(at(fresh, 0.9)));

  source->SetResolution(20, 20, 20); // an upstream change replays too
  at(tracer, 0.9);
  EXPECT_TRUE(tracer->GetLastUpdateReplayed());
}

TEST(BoundParticleTracer, UnsteadyInputSteppedInPiecesEqualsAFreshRun)
{
  auto source = flow(bp::AnalyticFlow::DoubleGyre);
  source->SetResolution(40, 20, 2);
  source->SetBounds(0, 2, 0, 1, 0, 0.1);
  auto tracer = tracerOn(source);
  tracer->SetElementShape(bp::BuiltinShape::Square);
  tracer->UpdateInformation();
  // 11 input steps: the automatic time line's 101 frames, 10 per step.
  EXPECT_EQ(
    tracer->GetOutputInformation(0)->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 101);
  at(tracer, 0.8);
  at(tracer, 2.1);
  EXPECT_FALSE(tracer->GetLastUpdateReplayed());
  const std::vector<float> pieces = pointsOf(at(tracer, 3.75));
  auto fresh = tracerOn(source);
  fresh->SetElementShape(bp::BuiltinShape::Square);
  EXPECT_EQ(pieces, pointsOf(at(fresh, 3.75)));
  EXPECT_NEAR(fresh->GetSimulationTime(), 3.75, 1e-12);

  // Targets on the data's own time steps, the first and the last included.
  for (double t : { 4.0, 4.0, 0.0, 1.5, 10.0 })
  {
    vtkPolyData* out = at(tracer, t);
    EXPECT_EQ(out->GetNumberOfPoints(), 200 * 4) << "t = " << t;
    auto other = tracerOn(source);
    other->SetElementShape(bp::BuiltinShape::Square);
    EXPECT_EQ(pointsOf(out), pointsOf(at(other, t))) << "t = " << t;
  }
}

TEST(BoundParticleTracer, SameSeedSameTraceOtherSeedOtherTrace)
{
  auto source = flow(bp::AnalyticFlow::ABC, 16);
  auto a = tracerOn(source), b = tracerOn(source), c = tracerOn(source);
  c->SetSeed(99);
  EXPECT_EQ(pointsOf(at(a, 1.3)), pointsOf(at(b, 1.3)));
  EXPECT_NE(pointsOf(at(a, 1.3)), pointsOf(at(c, 1.3)));
}

TEST(BoundParticleTracer, DefaultsFollowTheField)
{
  auto source = flow(bp::AnalyticFlow::SolidBodyRotation, 21);
  auto tracer = tracerOn(source);
  vtkPolyData* out = at(tracer, 0.0);
  // The emitter covers the field; the element size and step follow its cells and speed.
  double b[6];
  out->GetBounds(b);
  EXPECT_LT(b[0], -0.8);
  EXPECT_GT(b[1], 0.8);
  const double cell = 0.1, maxSpeed = std::sqrt(2.0);
  EXPECT_NEAR(tracer->GetResolvedTimeStep(), 0.5 * cell / maxSpeed, 1e-6);
  EXPECT_NEAR(tracer->GetResolvedElementSize(), 2 * cell, 1e-9);
  tracer->SetStepSizeUnit(bp::StepUnit::Time);
  tracer->SetStepSize(0.01);
  tracer->SetElementSize(0.3);
  at(tracer, 0.0);
  EXPECT_DOUBLE_EQ(tracer->GetResolvedTimeStep(), 0.01);
  EXPECT_DOUBLE_EQ(tracer->GetResolvedElementSize(), 0.3);
}

namespace
{
/// A 21^3 image on [0, 1]^3 with v = (-0.2, -0.1, 0), away from the corner
/// x > 0.5, y > 0.5, whose points are outside the flow's domain (NaN vectors,
/// or vtkValidPointMask 0), or, without a hole, inside it like any other.
vtkSmartPointer<vtkImageData> imageWithAHole(bool nan, bool hole = true)
{
  auto img = image(21, 21, 21);
  img->SetSpacing(0.05, 0.05, 0.05);
  auto v = array("v", 3, img->GetNumberOfPoints(), 0.0f);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("vtkValidPointMask");
  mask->SetNumberOfTuples(img->GetNumberOfPoints());
  for (vtkIdType id = 0; id < img->GetNumberOfPoints(); ++id)
  {
    double x[3];
    img->GetPoint(id, x);
    const bool outside = hole && x[0] > 0.5 && x[1] > 0.5;
    const float u = outside && nan ? std::nanf("") : -0.2f;
    v->SetTuple3(id, u, -0.1, 0.0);
    mask->SetValue(id, outside && !nan ? 0 : 1);
  }
  img->GetPointData()->SetVectors(v);
  if (!nan)
    img->GetPointData()->AddArray(mask);
  return img;
}
} // namespace

/// How many of the 400 Square elements' centres lie in the hole's cells.
int centresInTheHole(vtkPolyData* out)
{
  const std::vector<float> xyz = pointsOf(out);
  EXPECT_EQ(xyz.size(), 3u * 400 * 4);
  int inHole = 0;
  for (std::size_t e = 0; 12 * e + 11 < xyz.size(); ++e)
  {
    float c[3] = { 0, 0, 0 };
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_TRUE(std::isfinite(xyz[12 * e + 3 * i + k]));
        c[k] += 0.25f * xyz[12 * e + 3 * i + k];
      }
    // The cells with a corner in the hole (x, y > 0.5) start at x, y = 0.5.
    inHole += c[0] > 0.5f && c[1] > 0.5f;
  }
  return inHole;
}

vtkSmartPointer<vtkBoundParticleTracer> holeTracer(vtkAlgorithm* producer)
{
  auto tracer = tracerOn(producer, 400);
  tracer->SetElementShape(1); // Square
  tracer->SetElementSize(0.04);
  tracer->SetLifetimeRange(0.5, 1.0); // several releases each by t = 2
  return tracer;
}

TEST(BoundParticleTracer, TracesAroundPointsOutsideTheDomain)
{
  // Without a hole, about a third of the elements sit in that corner.
  vtkNew<vtkTrivialProducer> whole;
  whole->SetOutput(imageWithAHole(false, false));
  const int withoutHole = centresInTheHole(at(holeTracer(whole), 2.0));
  EXPECT_GT(withoutHole, 60);
  for (const bool nan : { true, false })
  {
    SCOPED_TRACE(nan ? "NaN vectors" : "vtkValidPointMask");
    vtkNew<vtkTrivialProducer> producer;
    producer->SetOutput(imageWithAHole(nan));
    auto tracer = holeTracer(producer);
    ErrorLog errors(tracer);
    ErrorLog warningLog(tracer, vtkCommand::WarningEvent);
    std::vector<std::string>& warnings = warningLog.messages;
    vtkPolyData* out = at(tracer, 2.0);
    EXPECT_TRUE(errors.messages.empty()) << errors.messages[0];
    // The NaN share is reported (16.2% of the points); a mask is the data's own say.
    bool reported = false;
    for (const auto& w : warnings)
      reported = reported || w.find("have a NaN or Inf vector") != std::string::npos;
    EXPECT_EQ(reported, nan);
    // Releases never land in the hole, and the flow carries nothing into it.
    const int inHole = centresInTheHole(out);
    EXPECT_EQ(inHole, 0) << inHole << " element centres in the hole, " << withoutHole
                         << " without it";
  }
}

TEST(BoundParticleTracer, BadInputGivesAClearErrorAndEmptyOutput)
{
  {
    auto img = image(5, 5, 5);
    img->GetPointData()->AddArray(array("pressure", 1, 125, 1.0f));
    expectRejected(img, "no point vector array");
  }
  for (int components : { 1, 2 })
  {
    auto img = image(5, 5, 5);
    img->GetPointData()->AddArray(array("flat", components, 125, 1.0f));
    expectRejected(img, "component",
      [](vtkBoundParticleTracer* t)
      { t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "flat"); });
  }
  {
    auto img = image(5, 5, 5);
    auto v = array("v", 3, 125, std::nanf(""));
    img->GetPointData()->SetVectors(v);
    expectRejected(img, "Every point of the input is outside the flow's domain");
  }
  expectRejected(vtkSmartPointer<vtkImageData>::New(), "empty");
  {
    // A Vectors name the input lacks is an error naming what it has, not the
    // active vectors in its place.
    auto img = image(5, 5, 5);
    img->GetPointData()->SetVectors(array("velocity", 3, 125, 1.0f));
    expectRejected(img,
      "no array 'Velocity' for Vectors; its 3-component point arrays are 'velocity'",
      [](vtkBoundParticleTracer* t)
      { t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Velocity"); });
  }
  {
    auto img = image(1, 1, 1);
    img->GetPointData()->SetVectors(array("v", 3, 1, 1.0f));
    expectRejected(img, "single point");
  }
  {
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    pd->SetPoints(pts);
    // Any dataset is resampled; points without cells carry no flow.
    expectRejected(pd, "no cells");
  }
  auto good = image(5, 5, 5);
  good->GetPointData()->SetVectors(array("v", 3, 125, 1.0f));
  expectRejected(
    good, "NumberOfElements", [](vtkBoundParticleTracer* t) { t->SetNumberOfElements(0); });
  expectRejected(good, "exceeds the limit",
    [](vtkBoundParticleTracer* t) { t->SetNumberOfElements(vtkIdType(1) << 40); });
  expectRejected(good, "StepSize", [](vtkBoundParticleTracer* t) { t->SetStepSize(0.0); });
  expectRejected(good, "StepSize", [](vtkBoundParticleTracer* t) { t->SetStepSize(-1.0); });
  expectRejected(good, "ElementSize", [](vtkBoundParticleTracer* t) { t->SetElementSize(-2.0); });
  expectRejected(
    good, "LifetimeRange", [](vtkBoundParticleTracer* t) { t->SetLifetimeRange(2, 1); });
}

TEST(BoundParticleTracer, RecoversAfterBadInput)
{
  auto source = flow(bp::AnalyticFlow::ShearLayer, 12);
  auto tracer = tracerOn(source, 10);
  ErrorLog log(tracer);
  tracer->SetStepSize(-1.0);
  EXPECT_EQ(at(tracer, 0.5)->GetNumberOfPoints(), 0);
  tracer->SetStepSize(0.5);
  EXPECT_EQ(at(tracer, 0.5)->GetNumberOfPoints(), 10 * 8);
  EXPECT_EQ(log.messages.size(), 1u);
}

TEST(BoundParticleTracer, LongReplaysReportProgressAndHonourAbort)
{
  auto source = flow(bp::AnalyticFlow::ABC, 16);
  auto tracer = tracerOn(source, 50);
  struct Progress
  {
    int events = 0;
    int abortAfter = -1;
  } progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback(
    [](vtkObject* caller, unsigned long, void* data, void*)
    {
      auto* p = static_cast<Progress*>(data);
      if (++p->events == p->abortAfter)
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    });
  tracer->AddObserver(vtkCommand::ProgressEvent, onProgress);

  progress.abortAfter = 10;
  EXPECT_EQ(at(tracer, 8.0)->GetNumberOfPoints(), 0); // aborted: no output
  EXPECT_LT(progress.events, 14); // stopped at once (the executive adds its own reports)

  tracer->SetAbortExecute(0);
  progress.abortAfter = -1;
  progress.events = 0;
  const std::vector<float> after = pointsOf(at(tracer, 8.0));
  EXPECT_TRUE(tracer->GetLastUpdateReplayed());
  EXPECT_GT(progress.events, 100); // one report per step of the replay
  auto fresh = tracerOn(source, 50);
  EXPECT_EQ(after, pointsOf(at(fresh, 8.0)));
}

TEST(BoundParticleTracer, Float32TimeStepsDoNotStall)
{
  // A step of 0.1 in time units divides the float32 time steps' intervals
  // only approximately; stepping must land on each time step and go on.
  vtkNew<vtkFloatTimesSource> source;
  auto tracer = tracerOn(source, 20);
  tracer->SetStepSizeUnit(bp::StepUnit::Time);
  tracer->SetStepSize(0.1);
  tracer->SetElementSize(0.1);
  tracer->SetLifetimeRange(100, 100);
  for (int k = 1; k <= 10; ++k)
  {
    const double t = double(0.1f * float(k));
    EXPECT_EQ(at(tracer, t)->GetNumberOfPoints(), 20 * 8) << t;
    EXPECT_LE(tracer->GetStepsInLastUpdate(), 2) << t;
  }
}

TEST(BoundParticleTracer, AnArrayWhoseUnitsFitIsFoundForTheVectorsDefault)
{
  // The active vectors `v` cross 30 cells between two input time steps (0.1
  // apart), units that do not match; `v_other` crosses 0.1 cell.
  vtkNew<vtkFloatTimesSource> source;
  source->Speed = 30.0;
  source->OtherSpeed = 0.1;
  auto tracer = tracerOn(source, 20);
  ErrorLog warningLog(tracer, vtkCommand::WarningEvent);
  std::vector<std::string>& warnings = warningLog.messages;
  // Asking runs nothing: before the source ever ran there is nothing to read.
  EXPECT_STREQ(tracer->GetUnitsMismatchedVectors(), "");
  EXPECT_STREQ(tracer->GetUnitsFittingVectors(), "");
  EXPECT_EQ(source->Executions, 0);
  // Found by the request for information before Vectors is set, as ParaView
  // makes it before it sets the Vectors property's default, on the data the
  // time line's probe had the source deliver (once, at its first time step).
  tracer->UpdateInformation();
  EXPECT_EQ(source->Executions, 1);
  EXPECT_STREQ(tracer->GetUnitsMismatchedVectors(), "v");
  EXPECT_STREQ(tracer->GetUnitsFittingVectors(), "v_other");
  EXPECT_EQ(source->Executions, 1);
  // The units warning of `v` waits for an update that still has no Vectors
  // (ParaView sets its default first), and is said then, once.
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  at(tracer, 0.5);
  at(tracer, 0.6);
  const auto units = std::count_if(warnings.begin(), warnings.end(),
    [](const std::string& w) { return w.find("between two input time steps") != w.npos; });
  EXPECT_EQ(units, 1);
  // `v_other` chosen: no warning, and what was found stays.
  warnings.clear();
  tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "v_other");
  at(tracer, 0.5);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_STREQ(tracer->GetUnitsFittingVectors(), "v_other");
  // Both fit: nothing to prefer.
  vtkNew<vtkFloatTimesSource> fitting;
  fitting->OtherSpeed = 0.2;
  auto other = tracerOn(fitting, 20);
  other->UpdateInformation();
  EXPECT_STREQ(other->GetUnitsMismatchedVectors(), "");
  EXPECT_STREQ(other->GetUnitsFittingVectors(), "");
}

TEST(BoundParticleTracer, AnArrayWhoseUnitsFitIsFoundOnTheDataHeldBeforeAnyRequest)
{
  // pvpython sets the Vectors default as soon as Input is set, before it
  // asks the tracer for information: the data the input holds is read as it
  // is, at the time it holds, and nothing runs.
  vtkNew<vtkFloatTimesSource> source;
  source->Speed = 30.0;
  source->OtherSpeed = 0.1;
  source->UpdateTimeStep(double(0.1f * 3.0f));
  auto tracer = tracerOn(source, 20);
  EXPECT_STREQ(tracer->GetUnitsMismatchedVectors(), "v");
  EXPECT_STREQ(tracer->GetUnitsFittingVectors(), "v_other");
  EXPECT_EQ(source->Executions, 1);
  EXPECT_DOUBLE_EQ(
    source->GetOutputDataObject(0)->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()),
    double(0.1f * 3.0f));
}

TEST(BoundParticleTracer, TheTimeLineProbeLeavesItsInputAtTheTimeItsConsumersAsked)
{
  // The automatic time line probes the field at its first time step; the
  // source's output, shared with its other consumers, is left at the time
  // they asked for (here 0.5), not the probe's.
  vtkNew<vtkFloatTimesSource> source;
  const double held = double(0.1f * 5.0f);
  source->UpdateTimeStep(held);
  vtkImageData* output = vtkImageData::SafeDownCast(source->GetOutputDataObject(0));
  auto tracer = tracerOn(source, 20);
  tracer->UpdateInformation();
  // The time line resolved from the probe; the source run at the consumers'
  // time, the probe's, and theirs again.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  EXPECT_GT(tracer->GetOutputInformation(0)->Length(SDDP::TIME_STEPS()), 0);
  EXPECT_EQ(source->Executions, 3);
  EXPECT_EQ(source->GetOutputDataObject(0), output);
  EXPECT_DOUBLE_EQ(output->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), held);
  EXPECT_DOUBLE_EQ(source->GetOutputInformation(0)->Get(SDDP::UPDATE_TIME_STEP()), held);
  // Nothing held at another time: the probe's update is all.
  vtkNew<vtkFloatTimesSource> fresh;
  auto other = tracerOn(fresh, 20);
  other->UpdateInformation();
  EXPECT_EQ(fresh->Executions, 1);
}

TEST(BoundParticleTracer, FarFromTheOriginKeepsPrecision)
{
  // v = (0.1, 0, 0) on a grid a million units from the origin: after 0.5 time
  // units every particle has moved 0.05 along x, as near the origin.
  std::vector<double> moved;
  for (double origin : { 0.0, 1.0e6 })
  {
    vtkNew<vtkFloatTimesSource> source;
    source->Origin = origin;
    auto tracer = tracerOn(source, 10);
    tracer->SetElementShape(bp::BuiltinShape::Point);
    tracer->SetEmitterCenter(origin + 0.3, origin + 0.5, origin + 0.5);
    tracer->SetEmitterSize(0.2, 0.2, 0.2);
    tracer->SetLifetimeRange(100, 100);
    vtkPolyData* start = at(tracer, 0.0);
    const double x0 = start->GetPoint(3)[0];
    EXPECT_GT(x0, origin + 0.19);
    vtkPolyData* end = at(tracer, double(0.1f * 5.0f));
    moved.push_back(end->GetPoint(3)[0] - x0);
    if (origin > 0)
      EXPECT_EQ(end->GetPoints()->GetDataType(), VTK_DOUBLE);
    else
      EXPECT_EQ(end->GetPoints()->GetDataType(), VTK_FLOAT);
  }
  EXPECT_NEAR(moved[0], 0.05, 1e-5);
  EXPECT_NEAR(moved[1], 0.05, 1e-5);
}

TEST(BoundParticleTracer, ImagesWithAnOffsetExtentAreWhereTheySay)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetExtent(10, 20, 0, 10, 0, 10); // points at x in [1, 2]
  img->SetSpacing(0.1, 0.1, 0.1);
  img->GetPointData()->SetVectors(array("v", 3, 11 * 11 * 11, 0.0f));
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(img);
  auto tracer = tracerOn(producer, 100);
  tracer->SetElementShape(bp::BuiltinShape::Point);
  double b[6];
  at(tracer, 0.0)->GetBounds(b);
  EXPECT_GE(b[0], 1.0 - 1e-6);
  EXPECT_LE(b[1], 2.0 + 1e-6);

  auto rotated = image(5, 5, 5);
  rotated->GetPointData()->SetVectors(array("v", 3, 125, 1.0f));
  const double turn[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };
  rotated->SetDirectionMatrix(turn);
  expectRejected(rotated, "rotated");
}

TEST(BoundParticleTracer, SingleTimeStepIsSteadyAndTimeIsClamped)
{
  vtkNew<vtkFloatTimesSource> source;
  source->Steps = 1;
  auto tracer = tracerOn(source, 10);
  tracer->SetDuration(3.0);
  tracer->SetNumberOfTimeSteps(4);
  tracer->UpdateInformation();
  EXPECT_EQ(
    tracer->GetOutputInformation(0)->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 4);
  const std::vector<float> start = pointsOf(at(tracer, 0.0));
  EXPECT_NE(start, pointsOf(at(tracer, 1.0)));
  // Far past the range: the state at its end, not an ever longer run.
  at(tracer, 1.0e6);
  EXPECT_DOUBLE_EQ(tracer->GetSimulationTime(), 3.0);
}

TEST(BoundParticleTracer, NonFiniteSettingsAreRejected)
{
  auto good = image(5, 5, 5);
  good->GetPointData()->SetVectors(array("v", 3, 125, 1.0f));
  expectRejected(good, "ElementRotation",
    [](vtkBoundParticleTracer* t)
    {
      t->SetReleaseOrientation(bp::Orientation::Fixed);
      t->SetElementRotation(std::nan(""), 0, 0);
    });
  expectRejected(good, "Duration", [](vtkBoundParticleTracer* t) { t->SetDuration(INFINITY); });
  expectRejected(good, "emitter",
    [](vtkBoundParticleTracer* t)
    {
      t->SetEmitterCenter(std::nan(""), 0, 0);
      t->SetEmitterSize(1, 1, 1);
    });
}

TEST(BoundParticleTracer, AnUpdateExtentWithoutDataDoesNotReplay)
{
  auto source = flow(bp::AnalyticFlow::ShearLayer, 12);
  auto tracer = tracerOn(source, 20);
  at(tracer, 1.0);
  tracer->GetOutputInformation(0)->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), 0.2);
  tracer->PropagateUpdateExtent();
  at(tracer, 3.0);
  EXPECT_FALSE(tracer->GetLastUpdateReplayed());
}

TEST(BoundParticleTracer, AnyParticleLeavingPlacesElementsWhollyInside)
{
  auto source = flow(bp::AnalyticFlow::VerticalShear, 16);
  auto tracer = tracerOn(source, 300);
  tracer->SetResetWhen(bp::ResetWhen::AnyParticleLeaves);
  tracer->SetElementShape(bp::BuiltinShape::Strip16);
  tracer->SetElementSize(0.4);
  // Placement: every particle inside. (Later, an element may step past the
  // bounds in the step that flags it; it is reset before it is advected again.)
  double b[6];
  at(tracer, 0.0)->GetBounds(b);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_GE(b[2 * a], -1.0 - 1e-6);
    EXPECT_LE(b[2 * a + 1], 1.0 + 1e-6);
  }
  tracer->SetResetWhen(bp::ResetWhen::CenterLeaves); // the thesis' rule: elements may stick out
  at(tracer, 0.0)->GetBounds(b);
  EXPECT_GT(b[1], 1.05);
}

TEST(BoundParticleTracer, AnyMeshIsAnElement)
{
  // A Plane source of 3 x 3 quads is a cloth patch: 16 particles, 18 triangles.
  auto source = flow(bp::AnalyticFlow::ABC, 16);
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(3, 3);
  for (bp::MeshSprings mode :
    { bp::MeshSprings::Edges, bp::MeshSprings::EdgesAndDiagonals, bp::MeshSprings::AllPairs })
  {
    auto tracer = tracerOn(source, 25);
    tracer->SetTemplateConnection(plane->GetOutputPort());
    tracer->SetTemplateSprings(mode);
    vtkPolyData* out = at(tracer, 0.5);
    EXPECT_EQ(out->GetNumberOfPoints(), 25 * 16);
    EXPECT_EQ(out->GetNumberOfPolys(), 25 * 18);
    EXPECT_LT(out->GetPointData()->GetArray("Force")->GetRange()[1], 0.1);
  }
  // A changed template replays with the new shape.
  auto tracer = tracerOn(source, 25);
  tracer->SetTemplateConnection(plane->GetOutputPort());
  at(tracer, 0.5);
  plane->SetResolution(2, 2);
  EXPECT_EQ(at(tracer, 0.5)->GetNumberOfPoints(), 25 * 9);
  EXPECT_TRUE(tracer->GetLastUpdateReplayed());
}

TEST(BoundParticleTracer, TemplateLinesSpringsStiffnessAndPins)
{
  // A polyline of three particles: two springs, drawn as lines; particle 0 pinned.
  auto line = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(2, 0.2, 0);
  line->SetPoints(pts);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[3] = { 0, 1, 2 };
  lines->InsertNextCell(3, ids);
  line->SetLines(lines);
  vtkNew<vtkFloatArray> stiffness;
  stiffness->SetName("Stiffness");
  stiffness->InsertNextValue(0.5f);
  line->GetCellData()->AddArray(stiffness);
  vtkNew<vtkFloatArray> pinned;
  pinned->SetName("Pinned");
  pinned->InsertNextValue(1);
  pinned->InsertNextValue(0);
  pinned->InsertNextValue(0);
  line->GetPointData()->AddArray(pinned);

  auto source = flow(bp::AnalyticFlow::ABC, 16);
  auto tracer = tracerOn(source, 10);
  tracer->SetTemplateData(line);
  tracer->SetLifetimeRange(100, 100);
  tracer->SetEmitterCenter(0, 0, 0); // far from the bounds: no element leaves
  tracer->SetEmitterSize(0.5, 0.5, 0.5);
  const std::vector<float> start = pointsOf(at(tracer, 0.0));
  vtkPolyData* out = at(tracer, 1.0);
  EXPECT_EQ(out->GetNumberOfLines(), 10 * 2);
  const std::vector<float> later = pointsOf(out);
  for (int e = 0; e < 10; ++e)
  {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(later[9 * e + k], start[9 * e + k]); // the pinned particle
    EXPECT_NE(later[9 * e + 6], start[9 * e + 6]);   // the free end moves
  }

  stiffness->SetValue(0, 1.5f);
  line->Modified();
  ErrorLog log(tracer);
  EXPECT_EQ(at(tracer, 1.0)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(log.mentions("stiffness"));
}

TEST(BoundParticleTracer, AnEmptyTemplateIsRejected)
{
  auto source = flow(bp::AnalyticFlow::ABC, 8);
  auto tracer = tracerOn(source, 10);
  tracer->SetTemplateData(vtkSmartPointer<vtkPolyData>::New());
  ErrorLog log(tracer);
  EXPECT_EQ(at(tracer, 0.5)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(log.mentions("Element Template input has no points"));
}

TEST(BoundParticleTracer, BuiltinElementFilesTraceLikeTheBuiltins)
{
  // Elements/<Shape>.vtp, loaded as the Element Template, is the built-in shape.
  auto source = flow(bp::AnalyticFlow::Hurricane, 16);
  for (int shape = 0; shape < bp::enumCount<bp::BuiltinShape>(); ++shape)
  {
    const char* name = bp::enumName(bp::BuiltinShape(shape));
    SCOPED_TRACE(name);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((std::string(BOUNDPARTICLES_ELEMENTS_DIR) + "/" + name + ".vtp").c_str());
    auto fromFile = tracerOn(source, 30);
    fromFile->SetTemplateConnection(reader->GetOutputPort());
    fromFile->SetElementSize(0.2);
    auto builtin = tracerOn(source, 30);
    builtin->SetElementShape(shape);
    builtin->SetElementSize(0.2);
    vtkPolyData* a = at(fromFile, 0.6);
    vtkPolyData* b = at(builtin, 0.6);
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    EXPECT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
    const std::vector<float> pa = pointsOf(a), pb = pointsOf(b);
    double worst = 0.0;
    for (std::size_t k = 0; k < pa.size(); ++k)
      worst = std::max(worst, double(std::abs(pa[k] - pb[k])));
    EXPECT_LT(worst, 1e-5);
  }
}

namespace
{
/// A vtkRectilinearGrid over x, y in [0, 1] with the given z layers and the
/// velocity (wind(z), 0.1, 0) at every point.
vtkSmartPointer<vtkRectilinearGrid> layeredGrid(
  const std::vector<double>& z, double (*wind)(double), int nxy = 6)
{
  auto grid = vtkSmartPointer<vtkRectilinearGrid>::New();
  grid->SetDimensions(nxy, nxy, int(z.size()));
  vtkNew<vtkDoubleArray> xs, zs;
  for (int i = 0; i < nxy; ++i)
    xs->InsertNextValue(double(i) / (nxy - 1));
  for (double value : z)
    zs->InsertNextValue(value);
  grid->SetXCoordinates(xs);
  grid->SetYCoordinates(xs);
  grid->SetZCoordinates(zs);
  vtkNew<vtkFloatArray> v;
  v->SetName("wind");
  v->SetNumberOfComponents(3);
  for (std::size_t k = 0; k < z.size(); ++k)
    for (int j = 0; j < nxy; ++j)
      for (int i = 0; i < nxy; ++i)
        v->InsertNextTuple3(wind(z[k]), 0.1, 0.0);
  grid->GetPointData()->SetVectors(v);
  return grid;
}

double logWind(double z)
{
  return 5.0 * std::log1p(z / 0.05); // a boundary-layer profile
}
} // namespace

TEST(BoundParticleTracer, StretchedAltitudeLayersAreSampledExactly)
{
  // Layers crowded near the ground, as in thesis §3.4, and a wind that is a
  // known function of altitude: the sampled velocity at every particle is
  // the linear interpolation between the two layers around it.
  std::vector<double> z;
  for (int k = 0; k < 12; ++k)
    z.push_back(0.02 * (std::pow(1.45, k) - 1.0));
  auto grid = layeredGrid(z, logWind);
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(grid);
  auto tracer = tracerOn(producer, 300);
  tracer->SetElementShape(bp::BuiltinShape::Point);
  tracer->SetElementSize(0.01);
  ErrorLog errors(tracer);
  vtkPolyData* out = at(tracer, 0.05);
  ASSERT_TRUE(errors.messages.empty()) << errors.messages.front();
  ASSERT_EQ(out->GetNumberOfPoints(), 300);
  vtkDataArray* velocity = out->GetPointData()->GetArray("Velocity");
  ASSERT_NE(velocity, nullptr);
  int checked = 0, lowLayers = 0;
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    double p[3];
    out->GetPoint(id, p);
    const auto upper = std::upper_bound(z.begin(), z.end(), p[2]);
    if (upper == z.begin() || upper == z.end())
      continue; // outside the layers: reset elements sit on the bounds
    const std::size_t k = std::size_t(upper - z.begin()) - 1;
    const double w = (p[2] - z[k]) / (z[k + 1] - z[k]);
    const double expected = logWind(z[k]) + w * (logWind(z[k + 1]) - logWind(z[k]));
    EXPECT_NEAR(velocity->GetComponent(id, 0), expected, 1e-4 * std::max(1.0, expected))
      << "at z = " << p[2];
    EXPECT_NEAR(velocity->GetComponent(id, 1), 0.1, 1e-6);
    ++checked;
    lowLayers += k < 5;
  }
  EXPECT_GT(checked, 250);
  EXPECT_GT(lowLayers, 0); // the thin layers near the ground are exercised

  // A rectilinear grid with even axes traces exactly like the same image.
  auto even = layeredGrid({ 0.0, 0.2, 0.4, 0.6, 0.8, 1.0 }, logWind);
  auto img = image(6, 6, 6);
  img->SetSpacing(0.2, 0.2, 0.2);
  img->GetPointData()->SetVectors(even->GetPointData()->GetVectors());
  vtkNew<vtkTrivialProducer> evenProducer, imageProducer;
  evenProducer->SetOutput(even);
  imageProducer->SetOutput(img);
  auto onGrid = tracerOn(evenProducer, 50), onImage = tracerOn(imageProducer, 50);
  EXPECT_EQ(pointsOf(at(onGrid, 0.5)), pointsOf(at(onImage, 0.5)));

  // Layers out of order are an error that says so.
  auto broken = layeredGrid({ 0.0, 0.3, 0.2, 1.0 }, logWind);
  expectRejected(broken, "strictly increasing");
}

TEST(BoundParticleTracer, TimeStepsAreReadOnceAndAtMostThreeAreHeld)
{
  auto source = flow(bp::AnalyticFlow::DoubleGyre);
  source->SetResolution(20, 10, 2);
  source->SetBounds(0, 2, 0, 1, 0, 0.1);
  std::vector<double> requested;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&requested);
  counter->SetCallback(
    [](vtkObject* caller, unsigned long, void* log, void*)
    {
      auto* algorithm = static_cast<vtkAlgorithm*>(caller);
      vtkInformation* info = algorithm->GetOutputInformation(0);
      static_cast<std::vector<double>*>(log)->push_back(
        info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
    });
  source->AddObserver(vtkCommand::EndEvent, counter);
  auto tracer = tracerOn(source, 50);
  // Play forward four frames per data interval (time steps every 0.5).
  for (int frame = 0; frame <= 40; ++frame)
  {
    at(tracer, 0.125 * frame);
    EXPECT_LE(tracer->GetNumberOfCachedTimeSteps(), 3) << "frame " << frame;
  }
  // Each time step up to t = 5 was read once, in order.
  ASSERT_EQ(requested.size(), 11u);
  for (std::size_t k = 0; k < requested.size(); ++k)
    EXPECT_NEAR(requested[k], 0.5 * double(k), 1e-12);
  // Back to the start and forward again: a replay (no checkpoints kept)
  // reads what it needs, within the same bound.
  tracer->SetCheckpointMemory(0.0);
  for (int frame = 0; frame <= 40; ++frame)
  {
    at(tracer, 0.125 * frame);
  }
  requested.clear();
  at(tracer, 0.3);
  EXPECT_TRUE(tracer->GetLastUpdateReplayed());
  EXPECT_LE(tracer->GetNumberOfCachedTimeSteps(), 3);
  at(tracer, 1.2);
  EXPECT_LE(tracer->GetNumberOfCachedTimeSteps(), 3);
  EXPECT_EQ(requested.size(), 4u); // t = 0, 0.5, 1, 1.5
}

namespace
{
std::vector<double> offeredTimes(vtkBoundParticleTracer* tracer)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  tracer->UpdateInformation();
  vtkInformation* info = tracer->GetOutputInformation(0);
  const double* t = info->Get(SDDP::TIME_STEPS());
  return std::vector<double>(t, t + info->Length(SDDP::TIME_STEPS()));
}
} // namespace

TEST(BoundParticleTracer, AutomaticTimeLineKeepsAFrameWithinTenSteps)
{
  // Steady: the field probed before any update gives the range; each of the
  // 101 offered times is at most 10 of the steps the update then takes.
  for (const bp::AnalyticFlow which : { bp::AnalyticFlow::ABC, bp::AnalyticFlow::ShearLayer })
  {
    auto source = flow(which, 20);
    auto tracer = tracerOn(source, 50);
    const std::vector<double> times = offeredTimes(tracer);
    ASSERT_EQ(times.size(), 101u);
    at(tracer, times[50]);
    const double dt = tracer->GetResolvedTimeStep();
    EXPECT_LE((times[1] - times[0]) / dt, 10.0 + 1e-9) << "flow " << bp::enumName(which);
    EXPECT_GT((times[1] - times[0]) / dt, 1.0) << "flow " << bp::enumName(which);
    EXPECT_EQ(tracer->GetNumberOfCachedTimeSteps(), 1);
  }
  // Unsteady: frames between the input's time steps, the input's own included.
  auto gyre = flow(bp::AnalyticFlow::DoubleGyre, 60);       // a step is ~1/12 of 0.5
  gyre->SetNumberOfTimeSteps(3);                            // 0, 0.5, 1
  auto tracer = tracerOn(gyre, 50);
  const std::vector<double> times = offeredTimes(tracer);
  ASSERT_GT(times.size(), 3u);
  EXPECT_EQ(times.front(), 0.0);
  EXPECT_EQ(times.back(), 1.0);
  EXPECT_NE(std::find(times.begin(), times.end(), 0.5), times.end());
  at(tracer, 1.0);
  EXPECT_LE((times[1] - times[0]) / tracer->GetResolvedTimeStep(), 10.0 + 1e-9);
  // Out of range: an error, and the automatic frames.
  {
    ErrorLog errors(tracer);
    tracer->SetFramesPerInputStep(5000);
    EXPECT_EQ(offeredTimes(tracer), times);
    EXPECT_TRUE(errors.mentions("FramesPerInputStep must be 0 (automatic) to 1000 (it is 5000)"));
  }
  // The user's choices stay.
  tracer->SetFramesPerInputStep(1);
  EXPECT_EQ(offeredTimes(tracer), (std::vector<double>{ 0.0, 0.5, 1.0 }));
  auto steady = tracerOn(flow(bp::AnalyticFlow::ABC, 12), 10);
  steady->SetDuration(3.0);
  EXPECT_EQ(offeredTimes(steady).back(), 3.0);
}
