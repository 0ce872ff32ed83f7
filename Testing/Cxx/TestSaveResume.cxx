// SPDX-License-Identifier: BSD-3-Clause
// Save and resume through the tracer: its State output (port 2) written as
// a .vtp file, and a new tracer that goes on from it (Initial State File)
// with the bits of a trace that never stopped; the state filled only when
// asked for; a state that does not fit said, nothing lost.
#include "TracerTestHelpers.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkPassThrough.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <unistd.h>

namespace
{
using SDDP = vtkStreamingDemandDrivenPipeline;

/// A file in the system's temporary folder, removed when it goes.
struct TempFile
{
  std::string path;
  explicit TempFile(const std::string& name)
    : path("/tmp/bp-save-resume-" + std::to_string(::getpid()) + "-" + name)
  {
  }
  ~TempFile() { std::remove(this->path.c_str()); }
};

/// Elements in the unsteady double gyre over its time line [0, 5].
vtkSmartPointer<vtkBoundParticleTracer> gyreTracer(
  vtkAlgorithm* source, const std::function<void(vtkBoundParticleTracer*)>& adjust = {})
{
  auto tracer = tracerOn(source, 120);
  tracer->SetEngine(int(bp::EngineChoice::Cpu));
  tracer->SetElementShape(int(bp::BuiltinShape::Strip8));
  tracer->SetLifetimeRange(0.6, 1.4); // elements reset during the trace
  tracer->SetDuration(5.0);
  tracer->SetNumberOfTimeSteps(21);
  if (adjust)
  {
    adjust(tracer);
  }
  return tracer;
}

vtkSmartPointer<vtkAnalyticFlowSource> gyre()
{
  auto source = flow(bp::AnalyticFlow::DoubleGyre, 16);
  source->SetNumberOfTimeSteps(11);
  return source;
}

/// The tracer's State output at time t, as a consumer (a writer) reads it.
vtkSmartPointer<vtkPolyData> stateAt(vtkBoundParticleTracer* tracer, double t)
{
  vtkNew<vtkPassThrough> reader;
  reader->SetInputConnection(tracer->GetOutputPort(2));
  reader->UpdateTimeStep(t);
  auto state = vtkSmartPointer<vtkPolyData>::New();
  state->ShallowCopy(reader->GetOutputDataObject(0));
  return state;
}

/// The state at time t written to `path` (Binary, or ASCII).
void saveState(
  vtkBoundParticleTracer* tracer, double t, const std::string& path, bool ascii = false)
{
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(stateAt(tracer, t));
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(copy);
  writer->SetFileName(path.c_str());
  if (ascii)
  {
    writer->SetDataModeToAscii();
  }
  else
  {
    writer->SetDataModeToBinary();
  }
  ASSERT_EQ(writer->Write(), 1);
}

/// Every point array's values and the points, as raw bytes per name.
std::map<std::string, std::vector<double>> everything(vtkPolyData* pd)
{
  std::map<std::string, std::vector<double>> all;
  all["points"] = std::vector<double>();
  for (float v : pointsOf(pd))
    all["points"].push_back(v);
  for (int a = 0; a < pd->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetPointData()->GetArray(a);
    if (!array)
      continue;
    std::vector<double>& values = all[array->GetName()];
    for (vtkIdType k = 0; k < array->GetNumberOfValues(); ++k)
      values.push_back(array->GetVariantValue(k).ToDouble());
  }
  return all;
}

void expectSameOutput(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  ASSERT_GT(a->GetNumberOfPoints(), 0) << what;
  const auto x = everything(a), y = everything(b);
  ASSERT_EQ(x.size(), y.size()) << what;
  for (const auto& entry : x)
  {
    const auto other = y.find(entry.first);
    ASSERT_NE(other, y.end()) << what << ": " << entry.first;
    // Bit for bit (NaN-free outputs: == on doubles made from the same floats).
    EXPECT_TRUE(entry.second == other->second) << what << ": " << entry.first << " differs";
  }
}

/// Saves `configured` at `saveAt`, resumes a new one at `later` from the
/// file, and compares it with a trace that never stopped.
void expectResumeMatches(const std::function<void(vtkBoundParticleTracer*)>& adjust, double saveAt,
  double later, const std::string& what)
{
  auto source = gyre();
  TempFile file("state.vtp");
  auto saver = gyreTracer(source, adjust);
  saveState(saver, saveAt, file.path);
  auto straight = gyreTracer(source, adjust);
  vtkNew<vtkPolyData> expected;
  expected->DeepCopy(at(straight, later));
  const vtkIdType straightSteps = straight->GetStepsInLastUpdate();

  auto resumed = gyreTracer(source, adjust);
  resumed->SetInitialStateFile(file.path.c_str());
  ErrorLog errors(resumed);
  expectSameOutput(at(resumed, later), expected, what + ", resumed");
  EXPECT_TRUE(errors.messages.empty()) << what << ": " << errors.messages.front();
  EXPECT_LT(resumed->GetStepsInLastUpdate(), straightSteps)
    << what << ": the resumed trace goes on from the state, not from the start";
  EXPECT_GT(resumed->GetStepsInLastUpdate(), 0) << what;
}
} // namespace

TEST(SaveResume, AResumedTraceHasTheBitsOfOneThatNeverStopped)
{
  expectResumeMatches({}, 1.5, 3.5, "defaults");
  expectResumeMatches(
    [](vtkBoundParticleTracer* t)
    {
      t->SetIntegrator(int(bp::Integrator::RK4));
      t->SetTrails(1);
      t->SetTrailLength(5);
      t->SetTrailSpacing(2);
      t->SetRestoration(int(bp::Restoration::ShapeMatching));
    },
    2.0, 4.25, "RK4, trails, shape matching");
  expectResumeMatches([](vtkBoundParticleTracer* t)
    { t->SetTimeDirection(int(bp::TimeDirection::Backward)); },
    3.0, 1.25, "backward");
}

TEST(SaveResume, TimesBeforeTheStateAreTracedFromTheStartAndLaterOnesFromIt)
{
  auto source = gyre();
  TempFile file("early.vtp");
  saveState(gyreTracer(source), 2.5, file.path);
  auto straight = gyreTracer(source);
  auto resumed = gyreTracer(source);
  resumed->SetInitialStateFile(file.path.c_str());
  for (double t : { 1.0, 3.0, 2.5, 4.0, 0.5 })
  {
    vtkNew<vtkPolyData> expected;
    expected->DeepCopy(at(straight, t));
    const vtkIdType straightSteps = straight->GetStepsInLastUpdate();
    expectSameOutput(at(resumed, t), expected, "t = " + std::to_string(t));
    if (t == 3.0)
    {
      // From 1 to 3 the work passes the state's time: it goes on from the
      // state (a replay that loads it), not from 1.
      EXPECT_TRUE(resumed->GetLastUpdateReplayed());
      EXPECT_LT(resumed->GetStepsInLastUpdate(), straightSteps / 2)
        << "from 2.5, not from 1: " << straightSteps << " steps from 1";
    }
  }
}

TEST(SaveResume, AStateOfALongerTraceIsSaid)
{
  auto source = gyre();
  TempFile file("longer.vtp");
  saveState(gyreTracer(source), 4.5, file.path);
  auto fewerSteps = flow(bp::AnalyticFlow::DoubleGyre, 16);
  fewerSteps->SetNumberOfTimeSteps(7); // to 3
  auto shorter = gyreTracer(fewerSteps);
  shorter->SetInitialStateFile(file.path.c_str());
  ErrorLog errors(shorter);
  EXPECT_EQ(at(shorter, 1.0)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions("lies past this trace's times"))
    << (errors.messages.empty() ? "(none)" : errors.messages.front());
}

TEST(SaveResume, TheStateOutputIsFilledOnlyWhenAskedForAndLeavesTheElementsAsTheyAre)
{
  auto source = gyre();
  auto tracer = gyreTracer(source);
  const std::vector<float> shown = pointsOf(at(tracer, 2.0));
  EXPECT_EQ(tracer->GetOutputDataObject(2)->GetNumberOfElements(vtkDataObject::CELL), 0)
    << "an update of the elements leaves it empty";
  const vtkIdType steps = tracer->GetStepsInLastUpdate();
  // The trace at the time shown (2), whatever time its reader asks for (a
  // writer asks for the time last asked of that output: in the GUI, the
  // time the tracer was applied at).
  vtkSmartPointer<vtkPolyData> state = stateAt(tracer, 3.0);
  EXPECT_DOUBLE_EQ(state->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 2.0);
  vtkDataArray* stateTime = state->GetFieldData()->GetArray("bpTime");
  ASSERT_NE(stateTime, nullptr);
  EXPECT_LE(stateTime->GetTuple1(0), 2.0) << "the last step boundary at or before it";
  EXPECT_GT(stateTime->GetTuple1(0), 1.5);
  EXPECT_EQ(state->GetNumberOfCells(), 120) << "one poly-vertex per element";
  EXPECT_EQ(state->GetNumberOfPoints(), 120 * 8);
  EXPECT_NE(state->GetCellData()->GetArray("bpPositions"), nullptr);
  EXPECT_NE(state->GetFieldData()->GetAbstractArray("bpChecksum"), nullptr);
  EXPECT_EQ(pointsOf(tracer->GetOutput()), shown) << "the elements' output is left as it was";
  EXPECT_EQ(tracer->GetStepsInLastUpdate(), steps) << "and so is its report";
  // The elements then go on from where the state was taken, as a fresh trace.
  const std::vector<float> later = pointsOf(at(tracer, 3.5));
  EXPECT_DOUBLE_EQ(stateAt(tracer, 0.0)->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()),
    3.5)
    << "once another time is shown, the state is that time's";
  EXPECT_EQ(later, pointsOf(at(gyreTracer(source), 3.5)));
}

TEST(SaveResume, AStateThatDoesNotFitIsSaidAndNothingIsLost)
{
  auto source = gyre();
  TempFile binary("good.vtp"), ascii("ascii.vtp"), cut("cut.vtp"), notState("elements.vtp");
  auto saver = gyreTracer(source);
  saveState(saver, 2.0, binary.path);
  saveState(saver, 2.0, ascii.path, true);
  {
    std::ifstream in(binary.path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(cut.path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(at(saver, 2.0));
    writer->SetFileName(notState.path.c_str());
    writer->Write();
  }
  struct Case
  {
    std::string path, expected;
    std::function<void(vtkBoundParticleTracer*)> adjust;
  };
  const std::vector<Case> cases = {
    { "/tmp/bp-no-such-state.vtp", "no such file", {} },
    { ascii.path, "saved as ASCII", {} },
    { cut.path, "cannot be read", {} },
    { notState.path, "not a Bound Particles state", {} },
    { binary.path, "numberOfElements: the state's 120, this trace's 60",
      [](vtkBoundParticleTracer* t) { t->SetNumberOfElements(60); } },
    { binary.path, "the template's",
      [](vtkBoundParticleTracer* t) { t->SetElementShape(int(bp::BuiltinShape::Cross)); } },
    { binary.path, "seed", [](vtkBoundParticleTracer* t) { t->SetSeed(5); } },
  };
  for (const Case& c : cases)
  {
    auto tracer = gyreTracer(source, c.adjust);
    tracer->SetInitialStateFile(c.path.c_str());
    ErrorLog errors(tracer);
    EXPECT_EQ(at(tracer, 3.0)->GetNumberOfPoints(), 0) << c.expected;
    EXPECT_TRUE(errors.mentions(c.expected))
      << c.expected << " in: " << (errors.messages.empty() ? "(none)" : errors.messages.front());
    // Cleared, the trace goes on from the start.
    tracer->SetInitialStateFile("");
    EXPECT_GT(at(tracer, 3.0)->GetNumberOfPoints(), 0) << c.expected;
  }
  // A different field (another resolution) is said by the grid.
  auto other = flow(bp::AnalyticFlow::DoubleGyre, 20);
  other->SetNumberOfTimeSteps(11);
  auto tracer = gyreTracer(other);
  tracer->SetInitialStateFile(binary.path.c_str());
  ErrorLog errors(tracer);
  EXPECT_EQ(at(tracer, 3.0)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions("the field's points along x: the state's 16, this trace's 20"))
    << (errors.messages.empty() ? "(none)" : errors.messages.front());
}
