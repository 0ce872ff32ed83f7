// SPDX-License-Identifier: BSD-3-Clause
// A trace's saved state (Core/Engine/EngineState.h): a trace resumed from
// it, on an engine configured and initialised alike, steps to the bits of
// one that never stopped: on one engine, through the stepper verbs, and on
// the pieces of a distributed run. Its checks: TestEngineStateChecks.cpp.
#include "EngineState.h"
#include "MemoryExchange.h"
#include "ReleaseLattice.h"
#include "Stepper.h"
#include "TestHelpers.h"
#include "WorkQueue.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <map>
#include <thread>

namespace
{
template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() &&
    (a.empty() || !std::memcmp(a.data(), b.data(), a.size() * sizeof(T)));
}

/// Every array of `b` has the bits of `a`'s, and the trail ring and emitter box too.
void expectSameBits(const bp::Engine& a, const bp::Engine& b)
{
  EXPECT_TRUE(sameBits(a.elementIds(), b.elementIds()));
  EXPECT_TRUE(sameBits(a.generations(), b.generations()));
  EXPECT_TRUE(sameBits(a.resetFlags(), b.resetFlags()));
  EXPECT_TRUE(sameBits(a.lifetimes(), b.lifetimes()));
  EXPECT_TRUE(sameBits(a.initialCenters(), b.initialCenters()));
  EXPECT_TRUE(sameBits(a.orientations(), b.orientations()));
  EXPECT_TRUE(sameBits(a.poses(), b.poses()));
  EXPECT_TRUE(sameBits(a.spins(), b.spins()));
  EXPECT_TRUE(sameBits(a.positions(), b.positions()));
  EXPECT_TRUE(sameBits(a.forces(), b.forces()));
  EXPECT_TRUE(sameBits(a.slips(), b.slips()));
  EXPECT_TRUE(sameBits(a.trailGenerations(), b.trailGenerations()));
  EXPECT_TRUE(sameBits(a.trailPositions(), b.trailPositions()));
  EXPECT_TRUE(sameBits(a.trailTimes(), b.trailTimes()));
  if (a.parameters().trailLength > 0)
  {
    EXPECT_EQ(a.trailSlot(0), b.trailSlot(0));
  }
  EXPECT_EQ(a.parameters().emitterMin, b.parameters().emitterMin);
  EXPECT_EQ(a.parameters().emitterMax, b.parameters().emitterMax);
}

/// `saved` as a file keeps it: each array of the layout on its own, of its
/// type (array-major, where records are element-major), then back.
bp::EngineState throughAFile(bp::EngineState saved)
{
  const std::size_t words = saved.recordWords, E = saved.elementCount();
  std::size_t sum = 0;
  for (const bp::StateArray& a : saved.layout)
    sum += a.components;
  EXPECT_EQ(sum, words);
  std::map<std::string, std::vector<float>> floats;
  std::map<std::string, std::vector<std::uint32_t>> integers;
  std::map<std::string, std::vector<std::uint8_t>> bytes;
  std::size_t offset = 0;
  for (const bp::StateArray& a : saved.layout)
  {
    for (std::size_t e = 0; e < E; ++e)
      for (std::size_t c = 0; c < a.components; ++c)
      {
        const std::uint32_t w = saved.records[e * words + offset + c];
        float f;
        std::memcpy(&f, &w, sizeof f);
        if (a.type == bp::StateArray::Type::Float32)
          floats[a.name].push_back(f);
        else if (a.type == bp::StateArray::Type::UInt32)
          integers[a.name].push_back(w);
        else
          bytes[a.name].push_back(std::uint8_t(w));
      }
    offset += a.components;
  }
  std::fill(saved.records.begin(), saved.records.end(), 0xdeadbeefu);
  offset = 0;
  for (const bp::StateArray& a : saved.layout)
  {
    for (std::size_t e = 0; e < E; ++e)
      for (std::size_t c = 0; c < a.components; ++c)
      {
        std::uint32_t& w = saved.records[e * words + offset + c];
        const std::size_t k = e * a.components + c;
        if (a.type == bp::StateArray::Type::Float32)
          std::memcpy(&w, &floats[a.name][k], sizeof w);
        else if (a.type == bp::StateArray::Type::UInt32)
          w = integers[a.name][k];
        else
          w = bytes[a.name][k];
      }
    offset += a.components;
  }
  return saved;
}

struct Case
{
  std::string name;
  bp::Parameters p;
  bp::BuiltinShape shape = bp::BuiltinShape::Cross;
  bool unsteady = false;
  bool movesEmitter = false; ///< in situ: the emitter box changes before the save
};

bp::Parameters baseParameters()
{
  bp::Parameters p;
  p.numberOfElements = 40;
  p.elementSize = 0.12f;
  p.emitterMin = { -0.7f, -0.7f, -0.7f };
  p.emitterMax = { 0.7f, 0.7f, 0.7f };
  p.lifetimeMin = 0.08f; // elements reset along the way, before and after the save
  p.lifetimeMax = 0.25f;
  p.iterations = 2;
  p.seed = 5;
  p.trackPoses = true;
  // Every 2 steps of 0.02: 6 poses in 12 steps, so that the newest slot at
  // the save is not the last (where a ring never recorded would point too).
  p.trailLength = 4;
  p.trailInterval = 0.04;
  return p;
}

std::vector<Case> cases()
{
  std::vector<Case> all;
  int k = 0;
  for (bp::Integrator integrator :
    { bp::Integrator::Euler, bp::Integrator::RK2, bp::Integrator::RK4 })
    for (bp::Restoration restoration : { bp::Restoration::AveragedJacobi, bp::Restoration::Jacobi,
           bp::Restoration::GaussSeidel, bp::Restoration::ShapeMatching })
    {
      Case c{ "integrator " + std::to_string(int(integrator)) + ", restoration " +
          std::to_string(int(restoration)),
        baseParameters() };
      c.p.integrator = integrator;
      c.p.restoration = restoration;
      c.unsteady = (k++ % 2) == 1;
      all.push_back(c);
    }
  const auto add = [&all](const std::string& name, const std::function<void(Case&)>& change)
  {
    Case c{ name, baseParameters() };
    c.p.integrator = bp::Integrator(all.size() % 3);
    change(c);
    all.push_back(c);
  };
  add("linear shape matching, Fish",
    [](Case& c)
    {
      c.p.restoration = bp::Restoration::ShapeMatching;
      c.p.linearShapeMatching = true;
      c.shape = bp::BuiltinShape::Fish;
    });
  add("Maxey-Riley with gravity",
    [](Case& c)
    {
      c.p.restoration = bp::Restoration::ShapeMatching;
      c.p.inertia = bp::Inertia::MaxeyRiley;
      c.p.responseTime = 0.05f;
      c.p.densityRatio = 3.0f;
      c.p.gravity = { 0.0f, 0.0f, -2.0f };
      c.unsteady = true;
    });
  add("Maxey-Riley points, no trails",
    [](Case& c)
    {
      c.shape = bp::BuiltinShape::Point;
      c.p.inertia = bp::Inertia::MaxeyRiley;
      c.p.responseTime = 0.1f;
      c.p.densityRatio = 0.5f; // bubbles: 1 would follow the flow, with no slip
      c.p.gravity = { 0.0f, -1.0f, 0.0f };
      c.p.trailLength = 0;
    });
  add("Anchor Centre", [](Case& c) { c.p.anchor = bp::Anchor::Centre; });
  add("Release Pattern Lattice",
    [](Case& c)
    {
      c.p.releasePattern = bp::ReleasePattern::Lattice;
      c.p.lattice = bp::releaseLattice(c.p.emitterMin, c.p.emitterMax, 27, 0.0);
      c.p.numberOfElements = c.p.lattice.size();
    });
  add("seed points, Fixed",
    [](Case& c)
    {
      c.p.seedPoints = { 0.1f, 0.2f, 0.3f, -0.5f, 0.0f, 0.4f, 0.6f, -0.6f, 0.0f };
      c.p.orientation = bp::Orientation::Fixed;
      c.p.frame = { 0, 1, 0, -1, 0, 0, 0, 0, 1 };
    });
  add("super set (Tube)",
    [](Case& c)
    {
      c.p.linking = bp::Linking::Tube;
      c.p.numberOfElements = 30;
      c.p.lifetimeMin = 0.05f;
      c.p.lifetimeMax = 0.2f;
    });
  add("a release window that opens after the save",
    [](Case& c)
    {
      c.p.releaseStart = 0.3;
      c.p.releaseStop = 0.4;
    });
  add("Along Flow, any particle leaves, a least release speed",
    [](Case& c)
    {
      c.p.orientation = bp::Orientation::AlongFlow;
      c.p.resetWhen = bp::ResetWhen::AnyParticleLeaves;
      c.p.releaseMinSpeed = 0.3f;
      c.unsteady = true;
    });
  add("an emitter box moved in situ", [](Case& c) { c.movesEmitter = true; });
  return all;
}

bp::Engine started(const Case& c, const bp::VectorField& field)
{
  bp::Engine engine;
  EXPECT_EQ(engine.configure(bp::builtinTemplate(c.shape), c.p), "");
  engine.initialize(bp::serialRunner(), 0.0, &field);
  return engine;
}

/// "name type components" per array, for comparisons that print.
std::string layoutText(const std::vector<bp::StateArray>& layout)
{
  std::string text;
  for (const bp::StateArray& a : layout)
    text += a.name + " " + std::to_string(int(a.type)) + " " + std::to_string(a.components) + "; ";
  return text;
}

std::uint64_t generationsSum(const bp::Engine& engine)
{
  std::uint64_t sum = 0;
  for (std::uint32_t g : engine.generations())
    sum += g;
  return sum;
}
} // namespace

TEST(EngineState, ResumedFromASavedStateStepsToTheBitsOfOneThatNeverStopped)
{
  const bp::GridGeometry g = bptest::grid(17);
  const bp::VectorField steady = bptest::steadyFlow(bp::AnalyticFlow::ABC, g);
  const bp::VectorField unsteady = bptest::unsteadyFlow(bp::AnalyticFlow::ABC, g, 0.0, 1.0);
  const double h = 0.02;
  const int before = 12, after = 13;
  for (const Case& c : cases())
  {
    SCOPED_TRACE(c.name);
    const bp::VectorField& field = c.unsteady ? unsteady : steady;
    bp::Engine a = started(c, field);
    for (int s = 0; s < before; ++s)
    {
      if (c.movesEmitter && s == before / 2)
        a.setEmitter({ -0.2f, -0.2f, -0.2f }, { 0.3f, 0.3f, 0.3f });
      a.step(field, s * h, h, bp::serialRunner());
    }
    const bp::EngineState saved = a.saveState();
    ASSERT_EQ(saved.elementCount(), c.p.numberOfElements);
    EXPECT_EQ(layoutText(saved.layout), layoutText(a.stateLayout()));
    EXPECT_EQ(layoutText(saved.layout),
      layoutText(bp::Engine::stateLayout(bp::builtinTemplate(c.shape), c.p)));
    EXPECT_EQ(saved.recordWords, bp::Engine::recordWords(bp::builtinTemplate(c.shape), c.p));
    // A fresh engine, configured and initialised alike, takes the state.
    bp::Engine b = started(c, field);
    ASSERT_EQ(b.loadState(throughAFile(saved)), "");
    expectSameBits(a, b);
    const std::uint64_t generations = generationsSum(a);
    for (int s = before; s < before + after; ++s)
    {
      a.step(field, s * h, h, bp::serialRunner());
      b.step(field, s * h, h, bp::serialRunner());
    }
    EXPECT_GT(generationsSum(a), generations); // elements were reset after the save
    expectSameBits(a, b);
  }
}

TEST(EngineState, TheStepperSavesTheCommittedStateWhileAShortStepIsShown)
{
  const bp::VectorField field =
    bptest::unsteadyFlow(bp::AnalyticFlow::DoubleGyre, bptest::grid(33, 0.0, 2.0, 2), 0.0, 1.0);
  bp::Parameters p = baseParameters();
  p.emitterMin = { 0.2f, 0.2f, 0.0f };
  p.emitterMax = { 1.8f, 0.8f, 0.0f };
  p.elementSize = 0.05f;
  p.numberOfElements = 200;
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const double h = 0.01;
  const auto start = [&](bp::CpuStepper& s)
  {
    EXPECT_EQ(s.configure(shape, p), "");
    EXPECT_EQ(s.setField(field), "");
    s.initialize(0.0);
  };
  bp::CpuStepper a;
  start(a);
  for (int k = 0; k < 20; ++k)
    a.step(k * h, h);
  const bp::EngineState boundary = a.engine().saveState();
  // A short step shown past the boundary, as the tracer shows one.
  a.save();
  a.step(20 * h, 0.4 * h);
  a.cursor.showsPartialStep = true;
  bp::EngineState committed;
  ASSERT_TRUE(a.committedState(committed));
  EXPECT_TRUE(sameBits(committed.records, boundary.records));
  EXPECT_TRUE(sameBits(committed.trailTimes, boundary.trailTimes));
  // Without one, the state is the engine's as it stands.
  a.cursor.showsPartialStep = false;
  bp::EngineState shown;
  ASSERT_TRUE(a.committedState(shown));
  EXPECT_TRUE(sameBits(shown.records, a.engine().saveState().records));
  EXPECT_FALSE(sameBits(shown.records, boundary.records));
  // Resumed on another stepper, it goes on as the one that took its short step back.
  bp::CpuStepper b;
  start(b);
  ASSERT_EQ(b.loadState(committed), "");
  a.restore();
  for (int k = 20; k < 45; ++k)
  {
    a.step(k * h, h);
    b.step(k * h, h);
  }
  expectSameBits(a.engine(), b.engine());
  // The GPU engine's queue keeps its state in its renderer's textures: it
  // has none to give, and takes one only for a system it configured
  // (TestWorkQueue: one configured records the load).
  bp::WorkQueue queue(1);
  EXPECT_FALSE(queue.committedState(committed));
  EXPECT_NE(queue.loadState(committed).find("before its system is configured"), std::string::npos);
}

TEST(EngineState, AWholeStateResumesOnThePiecesOfADistributedRun)
{
  const bp::VectorField whole = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(17));
  bp::Parameters p = baseParameters();
  p.numberOfElements = 200;
  p.integrator = bp::Integrator::RK4;
  p.restoration = bp::Restoration::ShapeMatching;
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const double h = 0.02;
  const int before = 10, after = 25;
  // One process that never stops, through the same verbs.
  bp::CpuStepper serial;
  ASSERT_EQ(serial.configure(shape, p), "");
  ASSERT_EQ(serial.setField(whole), "");
  serial.initialize(0.0);
  for (int s = 0; s < before; ++s)
    serial.step(s * h, h);
  bp::EngineState saved;
  ASSERT_TRUE(serial.committedState(saved));
  for (int s = before; s < before + after; ++s)
    serial.step(s * h, h);
  const bp::Engine& reference = serial.engine();
  const std::size_t n = reference.particlesPerElement();
  for (int pieces : { 2, 4 })
  {
    SCOPED_TRACE(std::to_string(pieces) + " pieces");
    std::vector<bp::Box> boxes;
    for (int k = 0; k < pieces; ++k)
    {
      const double x = k % 2 ? 0.25 : -1.0, X = k % 2 ? 1.0 : 0.25;
      const double y = pieces == 2 || k < 2 ? -1.0 : -0.5, Y = pieces == 2 || k >= 2 ? 1.0 : -0.5;
      boxes.push_back({ x, X, y, Y, -1.0, 1.0 });
    }
    const bp::Partition partition(boxes);
    bptest::MemoryExchange exchange(pieces);
    std::vector<std::unique_ptr<bp::DistributedStepper>> steppers;
    for (int k = 0; k < pieces; ++k)
    {
      steppers.emplace_back(
        new bp::DistributedStepper(bp::serialRunner(), exchange.forPiece(k), &bp::releaseMaskOf));
      bp::DistributedStepper& s = *steppers.back();
      ASSERT_EQ(s.configure(shape, p), "");
      ASSERT_EQ(s.setField(whole), "");
      s.setPieces(partition, whole.domain(), k);
      s.initialize(0.0);
      ASSERT_EQ(s.loadState(saved), "");
    }
    std::vector<std::thread> threads;
    for (int k = 0; k < pieces; ++k)
      threads.emplace_back(
        [&, k]
        {
          for (int s = before; s < before + after; ++s)
            steppers[std::size_t(k)]->step(s * h, h);
        });
    for (auto& t : threads)
      t.join();
    std::size_t held = 0;
    long long migrated = 0;
    for (const auto& stepper : steppers)
    {
      EXPECT_EQ(stepper->takeExchangeError(), "");
      migrated += stepper->takeMigrated();
      const bp::Engine& piece = stepper->engine();
      EXPECT_TRUE(sameBits(piece.trailTimes(), reference.trailTimes()));
      for (std::size_t e = 0; e < piece.elementCount(); ++e, ++held)
      {
        const std::uint32_t id = piece.elementIds()[e];
        ASSERT_LT(id, reference.elementCount());
        EXPECT_EQ(piece.generations()[e], reference.generations()[id]);
        EXPECT_EQ(piece.lifetimes()[e], reference.lifetimes()[id]);
        EXPECT_EQ(0,
          std::memcmp(piece.positions().data() + 3 * n * e,
            reference.positions().data() + 3 * n * id, 3 * n * sizeof(float)))
          << "element " << id;
        EXPECT_EQ(0,
          std::memcmp(
            piece.poses().data() + 4 * e, reference.poses().data() + 4 * id, 4 * sizeof(float)));
      }
    }
    EXPECT_EQ(held, reference.elementCount()); // each element on one piece
    EXPECT_GT(migrated, 10);
  }
}

TEST(EngineState, GoldenBitsOfThisVersion)
{
  // A state of this EngineStateVersion, by its checksum: when a change to
  // the engine's arithmetic or to the state's layout changes it, states
  // saved before no longer resume to the same bits, so bump
  // EngineStateVersion (EngineState.h) and set the new checksum here. Every
  // value is exact in float (a solid rotation sampled on a grid of quarter
  // units, a fixed orientation, no pose fit), so the bits are the same on
  // every machine (fp-contract off: Core/CMakeLists.txt).
  bp::GridGeometry g = bptest::grid(9);
  auto velocity = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        velocity->insert(velocity->end(),
          { -0.5f * float(g.coordinate(1, j)), 0.5f * float(g.coordinate(0, i)), 0.25f });
  bp::FieldSlice slice;
  slice.velocity = velocity;
  const bp::VectorField field(g, slice);
  bp::Parameters p;
  p.numberOfElements = 16;
  p.elementSize = 0.25f;
  p.emitterMin = { -0.5f, -0.5f, -0.5f };
  p.emitterMax = { 0.5f, 0.5f, 0.5f };
  p.orientation = bp::Orientation::Fixed;
  p.lifetimeMin = 0.125f;
  p.lifetimeMax = 0.25f;
  p.iterations = 2;
  p.seed = 3;
  p.trailLength = 2;
  p.trailInterval = 0.125;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
  engine.initialize(bp::serialRunner());
  for (int s = 0; s < 12; ++s)
    engine.step(field, s * 0.03125, 0.03125, bp::serialRunner());
  bp::TraceState state;
  state.engine = engine.saveState();
  EXPECT_GT(generationsSum(engine), 0u);
  EXPECT_EQ(bp::EngineStateVersion, 2u);
  EXPECT_EQ(bp::stateChecksum(state), 0x0a073e57142dced4ull)
    << std::hex << bp::stateChecksum(state);
}
