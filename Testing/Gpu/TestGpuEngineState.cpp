// SPDX-License-Identifier: BSD-3-Clause
// Save and resume on the GPU engine (Gpu/GpuEngineState.h): its state read
// back as the CPU engine saves it, a state the CPU engine saved going on on
// the GPU, and a state the GPU read back going on bit for bit.
#include "AnalyticFlows.h"
#include "Engine.h"
#include "EngineCall.h"
#include "GpuEngine.h"
#include "GpuStepper.h"
#include "ParticleLayout.h"
#include "SharedContext.h"
#include "WorkQueue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>

namespace
{
bp::GridGeometry grid(int nx, int ny, int nz, const std::array<double, 6>& b)
{
  bp::GridGeometry g;
  g.dims = { nx, ny, nz };
  for (int a = 0; a < 3; ++a)
  {
    g.origin[a] = b[2 * a];
    g.spacing[a] = (b[2 * a + 1] - b[2 * a]) / (g.dims[a] - 1);
  }
  return g;
}

bp::FieldSlice slice(const bp::GridGeometry& g, double t)
{
  bp::FieldSlice s;
  s.time = t;
  s.velocity = std::make_shared<std::vector<float>>(
    bp::sampleAnalyticFlow(bp::AnalyticFlow::DoubleGyre, g, t));
  return s;
}

enum class Kind
{
  Massless,
  Heavy,    ///< heavy particles: the record's slips
  SuperSet, ///< a super set's tube of Strip4 elements (links built at configure)
  Terminate ///< Boundary Terminate: elements with a particle out of the field are terminated
};

/// The unsteady double gyre, elements placed again several times over 60
/// steps, with poses, a trail of 3 poses and heavy particles or a super set
/// as `kind` says: every array of the record holds something.
struct System
{
  bp::GridGeometry g = grid(41, 21, 6, { 0, 2, 0, 1, 0, 0.25 });
  bp::VectorField field = bp::VectorField(g, slice(g, 0.0), slice(g, 2.0));
  bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  bp::Parameters p;
  static constexpr double dt = 0.01;

  explicit System(Kind kind)
  {
    p.numberOfElements = 333;
    p.elementSize = 0.1f;
    p.emitterMin = { 0.0f, 0.0f, 0.0f };
    p.emitterMax = { 2.0f, 1.0f, 0.25f };
    p.lifetimeMin = 0.15f;
    p.lifetimeMax = 0.6f;
    p.seed = 4;
    p.trackPoses = true;
    p.trailLength = 3;
    p.trailInterval = 0.02;
    if (kind == Kind::SuperSet)
    {
      shape = bp::builtinTemplate(bp::BuiltinShape::Strip4);
      p.linking = bp::Linking::Tube;
    }
    if (kind == Kind::Terminate)
    {
      // Released up to the field's sides, an element with a particle out is
      // terminated (not replaced before its lifetime ends).
      p.boundary = bp::Boundary::Terminate;
      p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
    }
    if (kind == Kind::Heavy)
    {
      p.inertia = bp::Inertia::MaxeyRiley;
      p.responseTime = 0.05f;
      p.densityRatio = 20.0f;
      p.gravity = { 0.2f, 0.0f, -1.0f };
    }
  }

  void start(bp::Engine& cpu) const
  {
    ASSERT_EQ(cpu.configure(this->shape, this->p), "");
    cpu.initialize(bp::serialRunner());
  }
  void start(bp::GpuEngine& gpu) const
  {
    ASSERT_EQ(gpu.configure(this->shape, this->p), "");
    ASSERT_EQ(gpu.setField(this->field), "");
    gpu.initialize();
  }
  /// Steps `from` to `to` (counts of dt).
  void run(bp::Engine& cpu, int from, int to) const
  {
    for (int k = from; k < to; ++k)
      cpu.step(this->field, k * dt, dt, bp::serialRunner());
  }
  void run(bp::GpuEngine& gpu, int from, int to) const
  {
    for (int k = from; k < to; ++k)
      gpu.step(k * dt, dt);
  }
};

float floatOf(std::uint32_t word)
{
  float value;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

/// The largest difference of each array of two states of one layout: words
/// that differ for the integer arrays, |a - b| for the float ones (a
/// quaternion's components taking b or -b, whichever is nearer).
std::map<std::string, double> differences(const bp::EngineState& a, const bp::EngineState& b)
{
  std::map<std::string, double> worst;
  EXPECT_EQ(a.recordWords, b.recordWords);
  EXPECT_EQ(a.elementCount(), b.elementCount());
  if (a.recordWords != b.recordWords || a.elementCount() != b.elementCount())
    return worst;
  for (std::size_t e = 0; e < a.elementCount(); ++e)
  {
    const std::uint32_t* x = &a.records[e * a.recordWords];
    const std::uint32_t* y = &b.records[e * b.recordWords];
    for (const bp::StateArray& array : a.layout)
    {
      double& w = worst[array.name];
      const bool quaternion = array.name == "Orientations" || array.name == "Poses";
      double sign = 1.0;
      if (quaternion)
      {
        double dot = 0.0;
        for (int k = 0; k < 4; ++k)
          dot += double(floatOf(x[k])) * floatOf(y[k]);
        sign = dot < 0.0 ? -1.0 : 1.0;
      }
      for (std::size_t k = 0; k < array.components; ++k)
      {
        const double d = array.type == bp::StateArray::Type::Float32
          ? std::abs(double(floatOf(x[k])) - sign * double(floatOf(y[k])))
          : double(x[k] != y[k]);
        w = std::max(w, d);
      }
      x += array.components;
      y += array.components;
    }
  }
  return worst;
}

/// GPU against CPU within the parity tests' tolerances (TestGpuEngine.cpp):
/// ids, generations, flags exact; lifetimes 1e-5; positions, forces, trail
/// positions 1e-4 of the field's diagonal, centres 1e-6 of it; quaternions
/// 1e-3; spins, difference quotients of the poses, 1e-2; slips 1e-3.
void expectParity(const bp::EngineState& gpu, const bp::EngineState& cpu, double diagonal)
{
  EXPECT_EQ(gpu.trailTimes, cpu.trailTimes);
  EXPECT_EQ(gpu.trailNewest, cpu.trailNewest);
  EXPECT_EQ(gpu.emitterMin, cpu.emitterMin);
  EXPECT_EQ(gpu.emitterMax, cpu.emitterMax);
  const std::map<std::string, double> tolerance = { { "Ids", 0.5 }, { "Generations", 0.5 },
    { "ResetFlags", 0.5 }, { "TrailGenerations", 0.5 }, { "Lifetimes", 1e-5 },
    { "InitialCenters", 1e-6 * diagonal }, { "Orientations", 1e-3 }, { "Poses", 1e-3 },
    { "Spins", 1e-2 }, { "Positions", 1e-4 * diagonal }, { "Forces", 1e-4 * diagonal },
    { "TrailPositions", 1e-4 * diagonal }, { "Slips", 1e-3 } };
  for (const auto& d : differences(gpu, cpu))
  {
    ASSERT_EQ(tolerance.count(d.first), 1u) << d.first;
    EXPECT_LT(d.second, tolerance.at(d.first)) << d.first << " differ by up to " << d.second;
    std::printf("  %s: within %.3g\n", d.first.c_str(), d.second);
  }
}

void expectSameBits(const bp::EngineState& a, const bp::EngineState& b)
{
  EXPECT_EQ(a.layout.size(), b.layout.size());
  EXPECT_EQ(a.recordWords, b.recordWords);
  EXPECT_TRUE(a.records == b.records) << "the records differ";
  for (const auto& d : differences(a, b))
    EXPECT_EQ(d.second, 0.0) << d.first << " differ by up to " << d.second;
  EXPECT_EQ(a.trailTimes, b.trailTimes);
  EXPECT_EQ(a.trailNewest, b.trailNewest);
  EXPECT_EQ(a.emitterMin, b.emitterMin);
  EXPECT_EQ(a.emitterMax, b.emitterMax);
}

class GpuEngineState : public ::testing::TestWithParam<Kind>
{
};

TEST_P(GpuEngineState, ReadsBackWhatTheCpuEngineSaves)
{
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(GetParam());
  bp::Engine cpu;
  bp::GpuEngine gpu;
  s.start(cpu);
  s.start(gpu);
  s.run(cpu, 0, 60);
  s.run(gpu, 0, 60);
  bp::EngineState read;
  ASSERT_EQ(gpu.readState(read), "");
  const bp::EngineState saved = cpu.saveState();
  ASSERT_EQ(read.layout.size(), saved.layout.size());
  for (std::size_t k = 0; k < saved.layout.size(); ++k)
    EXPECT_EQ(read.layout[k].name, saved.layout[k].name);
  expectParity(read, saved, s.g.diagonal());
  if (GetParam() == Kind::Terminate)
  {
    const auto& flags = cpu.resetFlags();
    EXPECT_GT(std::count_if(flags.begin(), flags.end(),
                [](std::uint8_t f) { return (f & bp::Terminated) != 0; }),
      0)
      << "the state holds terminated elements";
  }
  gpu.release();
}

TEST_P(GpuEngineState, GoesOnFromAStateTheCpuEngineSaved)
{
  // Saved by the CPU engine after 30 steps, loaded into a GPU engine freshly
  // placed, stepped to 60: as the GPU engine stepped from the start, within
  // the engines' parity.
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(GetParam());
  bp::Engine cpu;
  s.start(cpu);
  s.run(cpu, 0, 30);
  bp::GpuEngine resumed, straight;
  s.start(resumed);
  ASSERT_EQ(resumed.loadState(cpu.saveState()), "");
  bp::EngineState loaded;
  ASSERT_EQ(resumed.readState(loaded), "");
  expectSameBits(loaded, cpu.saveState()); // the upload keeps every bit
  s.run(resumed, 30, 60);
  s.start(straight);
  s.run(straight, 0, 60);
  bp::EngineState a, b;
  ASSERT_EQ(resumed.readState(a), "");
  ASSERT_EQ(straight.readState(b), "");
  expectParity(a, b, s.g.diagonal());
  resumed.release();
  straight.release();
}

TEST_P(GpuEngineState, AStateReadBackGoesOnBitForBit)
{
  // Read back after 30 steps of a run that goes on to 60; loaded into a
  // fresh engine and stepped to 60: the bits of the run that never stopped.
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(GetParam());
  bp::GpuEngine straight, resumed;
  s.start(straight);
  s.run(straight, 0, 30);
  bp::EngineState at30;
  ASSERT_EQ(straight.readState(at30), "");
  s.run(straight, 30, 60);
  s.start(resumed);
  ASSERT_EQ(resumed.loadState(at30), "");
  s.run(resumed, 30, 60);
  bp::EngineState a, b;
  ASSERT_EQ(straight.readState(a), "");
  ASSERT_EQ(resumed.readState(b), "");
  expectSameBits(b, a);
  // The steps after the state moved the elements: the state is what they went on from.
  const auto moved = differences(a, at30);
  EXPECT_GT(moved.at("Positions"), 1e-3);
  std::vector<float> x, y;
  straight.read(&x, nullptr, nullptr);
  resumed.read(&y, nullptr, nullptr);
  EXPECT_TRUE(x == y);
  straight.release();
  resumed.release();
}

std::string kindName(const ::testing::TestParamInfo<Kind>& info)
{
  return info.param == Kind::Heavy  ? "Heavy"
    : info.param == Kind::SuperSet  ? "SuperSet"
    : info.param == Kind::Terminate ? "Terminate"
                                    : "Massless";
}

INSTANTIATE_TEST_SUITE_P(Systems, GpuEngineState,
  ::testing::Values(Kind::Massless, Kind::Heavy, Kind::SuperSet, Kind::Terminate), kindName);

TEST(GpuStepperState, TheCommittedStateIsTheSavedCopyWhileAShortStepIsShown)
{
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(Kind::Massless);
  bp::GpuStepper stepper;
  ASSERT_EQ(stepper.configure(s.shape, s.p), "");
  ASSERT_EQ(stepper.setField(s.field), "");
  stepper.initialize(0.0);
  for (int k = 0; k < 20; ++k)
    stepper.step(k * s.dt, s.dt);
  bp::EngineState boundary, shown, committed, restored;
  ASSERT_TRUE(stepper.committedState(boundary));
  EXPECT_FALSE(stepper.cursor.showsPartialStep);
  // A display's replay runs the recorded calls only: no tracer sets the
  // stepper's cursor, so save() itself says a short step follows.
  stepper.save();
  stepper.step(20 * s.dt, 0.4 * s.dt);
  EXPECT_TRUE(stepper.cursor.showsPartialStep);
  ASSERT_EQ(stepper.engine().readState(shown), "");
  ASSERT_TRUE(stepper.committedState(committed));
  EXPECT_FALSE(shown.records == boundary.records); // the short step moved them
  expectSameBits(committed, boundary);
  // Taken back, the current textures are the boundary again.
  stepper.restore();
  EXPECT_FALSE(stepper.cursor.showsPartialStep);
  ASSERT_EQ(stepper.readCommittedState(restored), "");
  expectSameBits(restored, boundary);
  stepper.engine().release();
}

TEST(GpuStepperState, ADisplaysReplayReadsTheBoundaryOfTheTracersCursor)
{
  // The tracer records into a queue; the display replays the calls onto its
  // GpuStepper and reads back through the queue's reader (what the State
  // output calls): the boundary the tracer's cursor names, not the short
  // step the display draws.
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(Kind::Massless);
  std::shared_ptr<bp::WorkQueue> recorder;
  bp::DisplayWorkQueue display = bp::newDisplayWorkQueue(7, recorder);
  bp::WorkQueue& tracer = *recorder;
  bp::EngineState none;
  EXPECT_NE(tracer.readState(none).find("no display"), std::string::npos);
  bp::GpuStepper gpu;
  display.writer.setStateReader(
    [&](bp::EngineState& state)
    {
      for (const bp::EngineCall& call : display.writer.take())
      {
        const std::string error = call.applyTo(gpu);
        if (!error.empty())
          return error;
      }
      return gpu.readCommittedState(state);
    });
  EXPECT_NE(tracer.readState(none).find("holds no trace"), std::string::npos);
  ASSERT_EQ(tracer.configure(s.shape, s.p), "");
  ASSERT_EQ(tracer.setField(s.field), "");
  tracer.initialize(0.0);
  tracer.cursor.valid = true;
  for (int k = 0; k < 20; ++k)
    tracer.step(k * s.dt, s.dt);
  // The same trace on a stepper of its own, to the boundary and no further.
  bp::GpuStepper straight;
  ASSERT_EQ(straight.configure(s.shape, s.p), "");
  ASSERT_EQ(straight.setField(s.field), "");
  straight.initialize(0.0);
  for (int k = 0; k < 20; ++k)
    straight.step(k * s.dt, s.dt);
  bp::EngineState boundary;
  ASSERT_TRUE(straight.committedState(boundary));
  tracer.save();
  tracer.step(20 * s.dt, 0.4 * s.dt);
  tracer.cursor.showsPartialStep = true;
  bp::EngineState read;
  ASSERT_EQ(tracer.readState(read), "");
  EXPECT_FALSE(tracer.hasPending()); // the reader ran every call
  expectSameBits(read, boundary);
  bp::EngineState drawn;
  ASSERT_EQ(gpu.engine().readState(drawn), "");
  EXPECT_FALSE(drawn.records == boundary.records); // the display still shows the short step
  display.writer.setStateReader(nullptr);
  EXPECT_NE(tracer.readState(none).find("no display"), std::string::npos);
  gpu.engine().release();
  straight.engine().release();
}

TEST(GpuEngineStateRefusal, SaysWhatTheGpuCannotHold)
{
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(Kind::Massless);
  bp::Engine cpu;
  s.start(cpu);
  s.run(cpu, 0, 5);
  const bp::EngineState saved = cpu.saveState();
  bp::GpuEngine gpu;
  s.start(gpu);
  bp::EngineState before;
  ASSERT_EQ(gpu.readState(before), "");
  const std::size_t generation = 1; // Ids, then Generations
  const std::size_t flags = 2;

  bp::EngineState old = saved;
  old.records[3 * old.recordWords + generation] = bp::GpuMaxGeneration + 1;
  std::string error = gpu.loadState(old);
  EXPECT_NE(error.find("element 3 is in its generation 16777217"), std::string::npos) << error;

  bp::EngineState part = saved;
  part.records.resize(part.records.size() - part.recordWords);
  error = gpu.loadState(part);
  EXPECT_NE(error.find("332"), std::string::npos) << error;

  bp::EngineState pending = saved;
  pending.records[7 * pending.recordWords + flags] |= bp::AlignPending;
  error = gpu.loadState(pending);
  EXPECT_NE(error.find("element 7 waits for its Along Flow turn"), std::string::npos) << error;

  bp::EngineState other = saved;
  other.layout.pop_back();
  EXPECT_NE(gpu.loadState(other), "");

  // Each refusal left the engine as it was.
  bp::EngineState after;
  ASSERT_EQ(gpu.readState(after), "");
  expectSameBits(after, before);
  // The largest generation a float holds exactly loads.
  bp::EngineState exact = saved;
  exact.records[3 * exact.recordWords + generation] = bp::GpuMaxGeneration;
  ASSERT_EQ(gpu.loadState(exact), "");
  ASSERT_EQ(gpu.readState(after), "");
  EXPECT_EQ(after.records[3 * after.recordWords + generation], bp::GpuMaxGeneration);
  gpu.release();
}

TEST(GpuEngineStateQueue, ADisplaysReplayLoadsTheState)
{
  // The filter's side records the load into the display's queue; the
  // display's replay uploads it into its GPU engine.
  ASSERT_TRUE(bp::haveSharedContext());
  const System s(Kind::Massless);
  bp::Engine cpu;
  s.start(cpu);
  s.run(cpu, 0, 12);
  const bp::EngineState saved = cpu.saveState();
  bp::WorkQueue queue(1);
  ASSERT_EQ(queue.configure(s.shape, s.p), "");
  ASSERT_EQ(queue.setField(s.field), "");
  queue.initialize(0.0);
  ASSERT_EQ(queue.loadState(saved), "");
  bp::EngineState none;
  EXPECT_FALSE(queue.committedState(none)); // the state lives in the display
  bp::GpuStepper display;
  for (const bp::EngineCall& call : queue.take())
    ASSERT_EQ(call.applyTo(display), "");
  bp::EngineState loaded;
  ASSERT_TRUE(display.committedState(loaded));
  expectSameBits(loaded, saved);
  display.engine().release();
}
} // namespace
