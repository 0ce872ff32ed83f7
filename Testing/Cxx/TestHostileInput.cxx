// SPDX-License-Identifier: BSD-3-Clause
// Hostile input (issue: bad input never kills or hangs ParaView): each case is
// rejected with a message that says what to fix, or traced with finite output.
#include "TracerTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkImageAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <chrono>
#include <cmath>
#include <limits>

/// A constant flow on an image, offering any time values (sorted or not).
class vtkHostileSource : public vtkImageAlgorithm
{
public:
  static vtkHostileSource* New();
  vtkTypeMacro(vtkHostileSource, vtkImageAlgorithm);
  std::vector<double> Times = { 0.0, 1.0 };
  double Speed = 0.1;
  double Origin = 0.0;
  double Spacing = 0.1;

protected:
  vtkHostileSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    const int extent[6] = { 0, 8, 0, 8, 0, 8 };
    const double origin[3] = { this->Origin, this->Origin, this->Origin };
    const double spacing[3] = { this->Spacing, this->Spacing, this->Spacing };
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    info->Set(vtkDataObject::ORIGIN(), origin, 3);
    info->Set(vtkDataObject::SPACING(), spacing, 3);
    info->Set(
      vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->Times.data(), int(this->Times.size()));
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkImageData* image = vtkImageData::GetData(out->GetInformationObject(0));
    image->SetExtent(0, 8, 0, 8, 0, 8);
    image->SetOrigin(this->Origin, this->Origin, this->Origin);
    image->SetSpacing(this->Spacing, this->Spacing, this->Spacing);
    image->GetPointData()->SetVectors(array("v", 3, image->GetNumberOfPoints(), 0.0f));
    for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
      image->GetPointData()->GetVectors()->SetTuple3(i, this->Speed, 0.5 * this->Speed, 0.0);
    return 1;
  }
};
vtkStandardNewMacro(vtkHostileSource);

namespace
{
vtkSmartPointer<vtkHostileSource> hostile(std::vector<double> times, double speed = 0.1)
{
  auto s = vtkSmartPointer<vtkHostileSource>::New();
  s->Times = std::move(times);
  s->Speed = speed;
  return s;
}

/// Updates `tracer` to t and expects an error naming `expected` and an empty output.
void expectRefused(vtkBoundParticleTracer* tracer, double t, const std::string& expected)
{
  ErrorLog log(tracer);
  tracer->UpdateTimeStep(t);
  EXPECT_TRUE(log.mentions(expected)) << "expected an error mentioning '" << expected << "', got "
                                      << (log.messages.empty() ? "none" : log.messages[0]);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
}

/// Every coordinate of the output is finite and within `reach` of the origin.
void expectFiniteWithin(vtkPolyData* pd, double reach)
{
  ASSERT_GT(pd->GetNumberOfPoints(), 0);
  double largest = 0.0;
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    for (double c : x)
    {
      ASSERT_TRUE(std::isfinite(c));
      largest = std::max(largest, std::abs(c));
    }
  }
  EXPECT_LE(largest, reach);
}

/// A regular n-gon fanned from its first corner: one corner with n springs.
vtkSmartPointer<vtkPolyData> polygon(int n)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(n);
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * 3.14159265358979 * i / n;
    points->InsertNextPoint(std::cos(a), std::sin(a), 0.0);
    polys->InsertCellPoint(i);
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}
} // namespace

TEST(HostileInput, TimeStepsOutOfOrderDuplicateOrNotFiniteAreRefused)
{
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  for (const auto& times : std::vector<std::vector<double>>{
         { 0, 2, 1, 3 }, { 0, 1, 1, 2 }, { 0, nan, 2 }, { 0, 1, inf } })
  {
    auto source = hostile(times);
    auto tracer = tracerOn(source, 20);
    expectRefused(tracer, 1.0, "time");
  }
}

TEST(HostileInput, AnInfiniteViewTimeShowsTheEnd)
{
  auto source = hostile({ 0, 1, 2 });
  auto tracer = tracerOn(source, 20);
  tracer->UpdateTimeStep(std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(tracer->GetSimulationTime(), 2.0);
  tracer->UpdateTimeStep(-std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(tracer->GetSimulationTime(), 0.0);
}

TEST(HostileInput, UnboundedWorkIsRefusedQuicklyWithTheReason)
{
  // A wrong byte order makes |v| ~ 4e8; a tiny step in time units; an
  // endless Duration on a steady field.
  const auto start = std::chrono::steady_clock::now();
  auto fast = hostile({ 0, 1 }, 4.3e8);
  expectRefused(tracerOn(fast, 20), 1.0, "steps");
  auto slow = hostile({ 0, 1 });
  auto tiny = tracerOn(slow, 20);
  tiny->SetStepSizeUnit(bp::StepUnit::Time);
  tiny->SetStepSize(1e-12);
  expectRefused(tiny, 1.0, "steps");
  auto steady = hostile({});
  auto endless = tracerOn(steady, 20);
  endless->SetDuration(1e12);
  expectRefused(endless, 1e12, "steps");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
}

TEST(HostileInput, VelocitiesAndSpacingsBeyondFloatArithmeticAreRefused)
{
  for (double speed : { 1e20, 1e30 })
  {
    auto source = hostile({}, speed);
    expectRefused(tracerOn(source, 20), 0.5, "byte order");
  }
  auto fine = hostile({});
  fine->Spacing = 1e-300;
  expectRefused(tracerOn(fine, 20), 0.5, "rescale");
  auto far = hostile({});
  far->Origin = 1e300;
  expectRefused(tracerOn(far, 20), 0.5, "rescale");
}

TEST(HostileInput, AutomaticValuesThatCannotWorkNameTheirCause)
{
  auto source = hostile({});
  auto tracer = tracerOn(source, 20);
  tracer->SetDuration(1e-300);
  expectRefused(tracer, 1e-300, "time span");
}

TEST(HostileInput, AnEmitterOutsideTheFieldIsRefused)
{
  auto source = hostile({});
  auto tracer = tracerOn(source, 20);
  tracer->SetEmitterCenter(50, 50, 50);
  tracer->SetEmitterSize(0.1, 0.1, 0.1);
  expectRefused(tracer, 0.5, "outside the field");
}

TEST(HostileInput, CompositeInputOfOverlappingBlocksIsTraced)
{
  // Two blocks over the same points (issue 28: composites are resampled; the
  // first block wins where they overlap).
  vtkNew<vtkMultiBlockDataSet> blocks;
  auto img = image(5, 5, 5);
  img->GetPointData()->SetVectors(array("v", 3, 125, 1.0f));
  blocks->SetBlock(0, img);
  blocks->SetBlock(1, img);
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(blocks);
  auto tracer = tracerOn(producer, 20);
  ErrorLog log(tracer);
  tracer->UpdateTimeStep(0.5);
  EXPECT_TRUE(log.messages.empty()) << log.messages[0];
  expectFiniteWithin(tracer->GetOutput(), 10.0);
}

TEST(HostileInput, TemplatesThatCannotBeReadAreRefused)
{
  auto source = hostile({});
  // A Stiffness array shorter than the lines.
  auto lines = polygon(6);
  lines->SetPolys(nullptr);
  vtkNew<vtkCellArray> segments;
  for (vtkIdType i = 0; i < 5; ++i)
  {
    const vtkIdType ids[2] = { i, i + 1 };
    segments->InsertNextCell(2, ids);
  }
  lines->SetLines(segments);
  lines->GetCellData()->AddArray(array("Stiffness", 1, 2, 1.0f));
  auto shortStiffness = tracerOn(source, 20);
  shortStiffness->SetTemplateData(lines);
  expectRefused(shortStiffness, 0.5, "Stiffness");
  // A point id beyond 32 bits (it used to wrap to 1).
  auto wrapped = polygon(6);
  vtkNew<vtkCellArray> bad;
  const vtkIdType ids[3] = { 0, (vtkIdType(1) << 32) + 1, 2 };
  bad->InsertNextCell(3, ids);
  wrapped->SetPolys(bad);
  auto wrapping = tracerOn(source, 20);
  wrapping->SetTemplateData(wrapped);
  expectRefused(wrapping, 0.5, "uses point");
  // All Pairs on a large mesh: more springs than a template may have.
  auto big = polygon(4000);
  auto pairs = tracerOn(source, 2);
  pairs->SetTemplateData(big);
  pairs->SetTemplateSprings(bp::MeshSprings::AllPairs);
  expectRefused(pairs, 0.5, "All Pairs");
}

TEST(HostileInput, JacobiStaysBoundedAtAnyFactorThePanelAllows)
{
  auto source = flow(bp::AnalyticFlow::ABC, 16);
  struct Case
  {
    bp::BuiltinShape shape;
    double factor;
    vtkSmartPointer<vtkPolyData> mesh;
  };
  const std::vector<Case> cases = { { bp::BuiltinShape::Paddlewheel, 1.0, nullptr },
    { bp::BuiltinShape::Fish, 1.0, nullptr }, { bp::BuiltinShape::Cross, 1.0, nullptr },
    { bp::BuiltinShape::Strip8, 0.2, polygon(100) } };
  for (const Case& c : cases)
  {
    auto tracer = tracerOn(source, 50);
    tracer->SetElementShape(c.shape);
    if (c.mesh)
      tracer->SetTemplateData(c.mesh);
    tracer->SetRestoration(bp::Restoration::Jacobi);
    tracer->SetRestorationIterations(4);
    tracer->SetRelaxationFactor(c.factor);
    tracer->SetDuration(2.0);
    tracer->UpdateTimeStep(2.0);
    // The field spans [-1, 1]: a diverging element would leave it by orders of magnitude.
    expectFiniteWithin(tracer->GetOutput(), 3.0);
  }
}
