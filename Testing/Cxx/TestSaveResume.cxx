// SPDX-License-Identifier: BSD-3-Clause
// Save and resume through the tracer: its State output (port 2) written as
// a .vtp file, and a new tracer that goes on from it (Initial State File)
// with the bits of a trace that never stopped; the state filled only when
// asked for; a state that does not fit said, nothing lost; the GPU
// display's state read back through its work queue (a display without GL).
#include "TracerTestHelpers.h"

#include "BoundParticleWorkQueues.h"
#include "EngineCall.h"
#include "TracerState.h"
#include "WorkQueue.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkPassThrough.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
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

namespace
{
/// The cell arrays (the engine's records) and bpTime of a state, by name.
std::map<std::string, std::vector<double>> records(vtkPolyData* state)
{
  std::map<std::string, std::vector<double>> all;
  for (int a = 0; a < state->GetCellData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = state->GetCellData()->GetArray(a);
    std::vector<double>& values = all[array->GetName()];
    for (vtkIdType k = 0; k < array->GetNumberOfValues(); ++k)
      values.push_back(array->GetVariantValue(k).ToDouble());
  }
  if (vtkDataArray* time = state->GetFieldData()->GetArray("bpTime"))
    all["bpTime"] = { time->GetTuple1(0) };
  return all;
}

/// A Bound Particles display without GL: it replays the queue's calls on a
/// CPU stepper (the GPU engine's stand-in: the calls are the same), keeps
/// whether a short step is shown as GpuStepper does (save() sets it), and
/// lends the queue its read-back, as vtkBoundParticleRepresentation does.
struct FakeDisplay
{
  bp::DisplayWorkQueue display = bpvtk::NewWorkQueue();
  bp::CpuStepper engine;
  int reads = 0;

  FakeDisplay()
  {
    this->display.writer.setStateReader(
      [this](bp::EngineState& state)
      {
        ++this->reads;
        this->run();
        return this->engine.committedState(state) ? std::string()
                                                  : std::string("the engine holds no trace");
      });
  }
  ~FakeDisplay() { this->display.writer.setStateReader(nullptr); }

  /// The queued calls, as a render runs them.
  void run()
  {
    for (const bp::EngineCall& call : this->display.writer.take())
    {
      ASSERT_EQ(call.applyTo(this->engine), "");
      using Kind = bp::EngineCall::Kind;
      const bool shows = call.kind == Kind::Save;
      const bool back = call.kind == Kind::Restore || call.kind == Kind::Configure ||
        call.kind == Kind::Initialize || call.kind == Kind::LoadState;
      this->engine.cursor.showsPartialStep =
        shows || (!back && this->engine.cursor.showsPartialStep);
    }
  }

  /// The tracer's elements shown at t for this display (its request key on
  /// port 0), then the request taken back, as the display does once it drew.
  void show(vtkBoundParticleTracer* tracer, double t)
  {
    vtkInformation* elements = tracer->GetOutputInformation(0);
    elements->Set(vtkBoundParticleTracer::GPU_WORK_QUEUE(), this->display.queue->id());
    tracer->UpdateTimeStep(t);
    elements->Set(vtkBoundParticleTracer::GPU_WORK_QUEUE(), 0);
  }
};
} // namespace

TEST(SaveResume, TheGpuDisplaysStateIsReadBackThroughItsQueue)
{
  auto source = gyre();
  const auto onGpu = [](vtkBoundParticleTracer* t) { t->SetEngine(int(bp::EngineChoice::Gpu)); };
  auto tracer = gyreTracer(source, onGpu);
  auto cpu = gyreTracer(source);
  FakeDisplay display;
  display.show(tracer, 2.3);
  EXPECT_NE(tracer->GetOutput()->GetFieldData()->GetArray("BoundParticlesWorkQueue"), nullptr)
    << "the update recorded for the display";
  display.run(); // the render
  ASSERT_FALSE(display.display.queue->hasPending());

  // Saved with the request taken back (0 on port 0): still the display's
  // trace, read back through its queue, on the boundary before 2.3; the
  // CPU engine replaying the same calls has the CPU tracer's bits.
  // The CPU tracer's state at t: the elements shown there first (the State
  // output saves the time shown).
  vtkNew<vtkPolyData> expected;
  const auto cpuStateAt = [&](double t)
  {
    cpu->UpdateTimeStep(t);
    expected->DeepCopy(stateAt(cpu, t));
  };
  cpuStateAt(2.3);
  ErrorLog errors(tracer);
  vtkSmartPointer<vtkPolyData> state = stateAt(tracer, 2.3);
  EXPECT_EQ(display.reads, 1);
  EXPECT_EQ(state->GetFieldData()->GetAbstractArray("bpStateNote"), nullptr);
  EXPECT_TRUE(records(state) == records(expected)) << "the display's state, on its boundary";
  EXPECT_LT(records(state)["bpTime"][0], 2.3);
  // Standing on that boundary, nothing was recorded: what it draws stays.
  EXPECT_FALSE(display.display.queue->hasPending());
  EXPECT_TRUE(display.engine.cursor.showsPartialStep);
  bp::TraceState read;
  EXPECT_EQ(bpvtk::readStatePolyData(state, read), "");

  // The display lost its state after it showed 2.6: the State update
  // replays into its queue, reads it back, and records the short step again
  // so that the display draws 2.6 once more.
  display.show(tracer, 2.6);
  display.run();
  display.display.writer.stateLost();
  cpuStateAt(2.6);
  state = stateAt(tracer, 2.6);
  EXPECT_EQ(display.reads, 2);
  EXPECT_TRUE(records(state) == records(expected)) << "replayed for the display, then read";
  const std::vector<bp::EngineCall> after = display.display.writer.take();
  ASSERT_EQ(after.size(), 3u) << "the field, save and the short step, for the display to draw";
  EXPECT_EQ(after[1].kind, bp::EngineCall::Kind::Save);
  EXPECT_EQ(after[2].kind, bp::EngineCall::Kind::Step);
  EXPECT_TRUE(errors.messages.empty()) << errors.messages.front();

  // A display that cannot read back (gone, or no context yet): a note, no
  // error (ParaView asks for every output of a source it updates).
  display.display.writer.setStateReader(nullptr);
  display.show(tracer, 2.9);
  state = stateAt(tracer, 2.9);
  EXPECT_NE(bpvtk::readStatePolyData(state, read)
              .find("the GPU display's state could not be read back: no display reads"),
    std::string::npos)
    << bpvtk::readStatePolyData(state, read);
  EXPECT_TRUE(errors.messages.empty()) << errors.messages.front();
}
