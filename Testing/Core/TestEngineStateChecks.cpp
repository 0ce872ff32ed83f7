// SPDX-License-Identifier: BSD-3-Clause
// A trace's saved state (Core/Engine/EngineState.h): what refuses a state
// that cannot resume, and says why; the named values a resumed trace
// compares, how a difference is said, and the checksum. Resuming itself:
// TestEngineState.cpp.
#include "EngineState.h"
#include "Surfaces.h"
#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>

namespace
{
struct Saved
{
  bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  bp::Parameters p;
  bp::TraceState state;
};

/// A trace of 20 elements with trails, 5 steps on.
Saved aTrace()
{
  Saved s;
  s.p.numberOfElements = 20;
  s.p.elementSize = 0.1f;
  s.p.emitterMin = { -0.5f, -0.5f, -0.5f };
  s.p.emitterMax = { 0.5f, 0.5f, 0.5f };
  s.p.trailLength = 2;
  s.p.trailInterval = 0.04;
  const bp::VectorField field = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(9));
  bp::Engine engine;
  EXPECT_EQ(engine.configure(s.shape, s.p), "");
  engine.initialize(bp::serialRunner());
  for (int k = 0; k < 5; ++k)
    engine.step(field, k * 0.02, 0.02, bp::serialRunner());
  s.state.engine = engine.saveState();
  s.state.time = 0.1;
  s.state.steps = 5;
  s.state.dt = 0.02;
  s.state.parameters = bp::parameterValues(s.p);
  s.state.shape = bp::templateValues(s.shape);
  return s;
}

/// `state` is refused with a message holding every one of `words`, and an
/// engine of `shape` and `p` refuses its engine state as it stands (unless
/// only the trace's part is wrong).
void expectRefused(const bp::TraceState& state, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const std::vector<std::string>& words, bool engineToo = true)
{
  const std::string message = bp::checkTraceState(state, shape, p);
  for (const std::string& word : words)
    EXPECT_NE(message.find(word), std::string::npos) << "\"" << message << "\" lacks " << word;
  if (!engineToo)
    return;
  bp::Engine engine;
  ASSERT_EQ(engine.configure(shape, p), "");
  engine.initialize(bp::serialRunner());
  const std::vector<std::uint32_t> before = engine.saveState().records;
  EXPECT_NE(engine.loadState(state.engine), "") << message;
  EXPECT_EQ(engine.saveState().records, before); // nothing taken from a refused state
}
} // namespace

TEST(EngineState, BadStatesAreRefusedWithTheirReason)
{
  const Saved good = aTrace();
  ASSERT_EQ(bp::checkTraceState(good.state, good.shape, good.p), "");
  const std::size_t words = good.state.engine.recordWords;
  const auto changed = [&good](const std::function<void(bp::TraceState&)>& change)
  {
    bp::TraceState s = good.state;
    change(s);
    return s;
  };
  const bp::TraceState newer = changed([](bp::TraceState& s) { s.version = 3; });
  expectRefused(newer, good.shape, good.p,
    { "version 3", "this engine's is 2", "trace again from the start" }, false);
  // Another template, trails off, more elements than the trace has.
  expectRefused(good.state, bp::builtinTemplate(bp::BuiltinShape::Strip8), good.p,
    { "element array Positions", "another element template" });
  bp::Parameters noTrails = good.p;
  noTrails.trailLength = 0;
  expectRefused(good.state, good.shape, noTrails, { "TrailGenerations", "this trace has not" });
  bp::Parameters fewer = good.p;
  fewer.numberOfElements = 10;
  expectRefused(good.state, good.shape, fewer, { "holds 20 elements", "this trace has 10" });
  bp::Parameters more = good.p;
  more.numberOfElements = 30; // a part of a state would lose the rest for good
  expectRefused(good.state, good.shape, more, { "holds 20 elements", "this trace has 30" });
  // Records of another size, or cut short.
  expectRefused(changed([](bp::TraceState& s) { ++s.engine.recordWords; }), good.shape, good.p,
    { std::to_string(words + 1) + " words each", "this trace's are " + std::to_string(words) });
  expectRefused(changed([](bp::TraceState& s) { s.engine.recordWords = 0; }), good.shape, good.p,
    { "0 words each" });
  expectRefused(changed([](bp::TraceState& s) { s.engine.recordWords = std::size_t(-1); }),
    good.shape, good.p, { "words each" });
  expectRefused(changed([](bp::TraceState& s) { s.engine.records.pop_back(); }), good.shape, good.p,
    { "cut short" });
  expectRefused(changed([](bp::TraceState& s) { s.engine = bp::EngineState(); }), good.shape,
    good.p, { "lacks the element array Ids" });
  // Ids repeated, out of order, out of range (each record starts with its id).
  expectRefused(changed([&](bp::TraceState& s) { s.engine.records[words] = s.engine.records[0]; }),
    good.shape, good.p, { "ids are repeated or out of order", "id 0 follows id 0" });
  expectRefused(
    changed([&](bp::TraceState& s) { std::swap(s.engine.records[0], s.engine.records[words]); }),
    good.shape, good.p, { "ids are repeated or out of order" });
  for (std::uint32_t id : { 20u, 0xffffffffu })
    expectRefused(changed([&](bp::TraceState& s) { s.engine.records[19 * words] = id; }),
      good.shape, good.p,
      { "record 19 carries id " + std::to_string(id), "the trace has 20 elements" });
  // The trail ring.
  expectRefused(changed([](bp::TraceState& s) { s.engine.trailTimes.pop_back(); }), good.shape,
    good.p, { "trail ring keeps 1 poses", "TrailLength keeps 2" });
  for (int slot : { 2, -2, std::numeric_limits<int>::max() })
    expectRefused(changed([slot](bp::TraceState& s) { s.engine.trailNewest = slot; }), good.shape,
      good.p, { "trail pose is in slot " + std::to_string(slot) });
  // Values no engine saves.
  expectRefused(changed([](bp::TraceState& s) { s.engine.emitterMax[1] = NAN; }), good.shape,
    good.p, { "emitter box is not finite" });
  for (const auto& change :
    std::vector<std::function<void(bp::TraceState&)>>{ [](bp::TraceState& s) { s.time = NAN; },
      [](bp::TraceState& s) { s.steps = -1; }, [](bp::TraceState& s) { s.dt = INFINITY; } })
    expectRefused(changed(change), good.shape, good.p, { "time, step count or step" }, false);
  // A state is every element of its trace: none, or some, would lose the rest.
  const bp::TraceState none = changed([](bp::TraceState& s) { s.engine.records.clear(); });
  expectRefused(none, good.shape, good.p, { "holds 0 elements", "this trace has 20" });
}

TEST(EngineState, ASuperSetLoadsWholeAndIsStillNotSplitAmongPieces)
{
  bp::Parameters p;
  p.numberOfElements = 12;
  p.linking = bp::Linking::Sheet;
  p.elementSize = 0.1f;
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  bp::Engine a, b;
  ASSERT_EQ(a.configure(shape, p), "");
  ASSERT_EQ(b.configure(shape, p), "");
  a.initialize(bp::serialRunner());
  b.initialize(bp::serialRunner());
  bp::EngineState state = a.saveState();
  state.records.resize(state.records.size() - state.recordWords);
  EXPECT_NE(b.loadState(state).find("holds 11 elements"), std::string::npos);
  EXPECT_EQ(b.loadState(a.saveState()), "");
  EXPECT_NE(b.exchange(std::vector<std::uint8_t>(12, 0), {}).find("super set cannot be split"),
    std::string::npos);
}

TEST(EngineState, ParameterValuesNameEveryMember)
{
  // Whoever adds a member to bp::Parameters adds it to bp::parameterValues
  // (Core/Engine/EngineState.cpp) and to `changes` below, in declaration
  // order, then sets the size here (a resumed trace compares every setting).
  static_assert(sizeof(void*) != 8 || sizeof(bp::Parameters) == 312,
    "bp::Parameters changed: add the new member to bp::parameterValues and to this test");
  using P = bp::Parameters;
  // `count` triangles that do `kind`.
  const auto surfaceOf = [](std::size_t count, bp::SurfaceInteraction kind)
  {
    bp::SurfaceTriangles t;
    for (std::size_t k = 0; k < count; ++k)
      t.corners.insert(t.corners.end(), { 0, 0, float(k), 1, 0, float(k), 0, 1, float(k) });
    t.interaction.assign(count, kind);
    return std::make_shared<const bp::SurfaceSet>(t);
  };
  struct Change
  {
    std::string name;
    std::function<void(P&)> change;
  };
  std::vector<Change> changes;
  const auto add = [&changes](const std::string& name, std::function<void(P&)> change) {
    changes.push_back({ name, std::move(change) });
  };
  const auto addArray = [&add](const std::string& name, std::size_t count,
                          const std::function<void(P&, std::size_t)>& change)
  {
    for (std::size_t k = 0; k < count; ++k)
      add(name + "[" + std::to_string(k) + "]", [change, k](P& p) { change(p, k); });
  };
  add("numberOfElements", [](P& p) { p.numberOfElements = 7; });
  add("elementSize", [](P& p) { p.elementSize = 0.5f; });
  addArray("emitterMin", 3, [](P& p, std::size_t k) { p.emitterMin[k] = -0.5f; });
  addArray("emitterMax", 3, [](P& p, std::size_t k) { p.emitterMax[k] = 0.5f; });
  add("orientation", [](P& p) { p.orientation = bp::Orientation::Fixed; });
  addArray("frame", 9, [](P& p, std::size_t k) { p.frame[k] += 0.25f; });
  add("planeAxis", [](P& p) { p.planeAxis = 2; });
  add("lifetimeMin", [](P& p) { p.lifetimeMin = 0.5f; });
  add("lifetimeMax", [](P& p) { p.lifetimeMax = 3.0f; });
  add("integrator", [](P& p) { p.integrator = bp::Integrator::RK4; });
  add("restoration", [](P& p) { p.restoration = bp::Restoration::ShapeMatching; });
  add("iterations", [](P& p) { p.iterations = 3; });
  add("relaxation", [](P& p) { p.relaxation = 0.3f; });
  add("shapeStiffness", [](P& p) { p.shapeStiffness = 0.5f; });
  add("linearShapeMatching", [](P& p) { p.linearShapeMatching = true; });
  add("linearBlend", [](P& p) { p.linearBlend = 0.25f; });
  add("linking", [](P& p) { p.linking = bp::Linking::Chain; });
  add("latticeWidth", [](P& p) { p.latticeWidth = 4; });
  add("linkStiffness", [](P& p) { p.linkStiffness = 0.5f; });
  add("resetWhen", [](P& p) { p.resetWhen = bp::ResetWhen::AnyParticleLeaves; });
  add("boundary", [](P& p) { p.boundary = bp::Boundary::Terminate; });
  add("restitution", [](P& p) { p.restitution = 0.5f; });
  add("surfaces.count", [&](P& p) { p.surfaces = surfaceOf(2, bp::SurfaceInteraction::Gate); });
  add("surfaces.hash", [&](P& p) { p.surfaces = surfaceOf(1, bp::SurfaceInteraction::Outlet); });
  add("releasePattern", [](P& p) { p.releasePattern = bp::ReleasePattern::Lattice; });
  addArray("lattice.counts", 3, [](P& p, std::size_t k) { p.lattice.counts[k] = 5; });
  addArray("lattice.origin", 3, [](P& p, std::size_t k) { p.lattice.origin[k] = 0.5f; });
  addArray("lattice.spacing", 3, [](P& p, std::size_t k) { p.lattice.spacing[k] = 0.1f; });
  add("anchor", [](P& p) { p.anchor = bp::Anchor::Centre; });
  add("inertia", [](P& p) { p.inertia = bp::Inertia::MaxeyRiley; });
  add("responseTime", [](P& p) { p.responseTime = 0.1f; });
  add("densityRatio", [](P& p) { p.densityRatio = 2.0f; });
  addArray("gravity", 3, [](P& p, std::size_t k) { p.gravity[k] = -9.81f; });
  add("seedPoints.count", [](P& p) { p.seedPoints.insert(p.seedPoints.end(), { 0, 0, 0 }); });
  add("seedPoints.hash", [](P& p) { p.seedPoints[4] = std::nextafter(0.5f, 1.0f); });
  add("releaseStart", [](P& p) { p.releaseStart = 1.0; });
  add("releaseStop", [](P& p) { p.releaseStop = 2.0; });
  add("releaseMinSpeed", [](P& p) { p.releaseMinSpeed = 0.1f; });
  add("seed", [](P& p) { p.seed = 99; });
  add("trackPoses", [](P& p) { p.trackPoses = true; });
  add("trailLength", [](P& p) { p.trailLength = 4; });
  add("trailStart", [](P& p) { p.trailStart = 0.5; });
  add("trailInterval", [](P& p) { p.trailInterval = 0.1; });
  add("ftleMinimumAge", [](P& p) { p.ftleMinimumAge = 1.0; });
  P base;
  base.seedPoints = { 0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f };
  base.boundary = bp::Boundary::Bounce; // the one Boundary that reads restitution
  base.surfaces = surfaceOf(1, bp::SurfaceInteraction::Gate);
  const std::vector<bp::NamedValue> values = bp::parameterValues(base);
  ASSERT_EQ(values.size(), changes.size());
  for (std::size_t k = 0; k < values.size(); ++k)
    EXPECT_EQ(values[k].name, changes[k].name); // in declaration order
  for (const Change& c : changes)
  {
    P p = base;
    c.change(p);
    const std::string said = bp::firstDifference(values, bp::parameterValues(p), "the setting");
    EXPECT_EQ(said.rfind("the setting " + c.name + ": the state's ", 0), 0u) << said;
  }
  // A hash of 32 bits: exact in a double.
  const auto hash = std::find_if(values.begin(), values.end(),
    [](const bp::NamedValue& v) { return v.name == "seedPoints.hash"; });
  ASSERT_NE(hash, values.end());
  EXPECT_EQ(hash->value, std::floor(hash->value));
  EXPECT_GE(hash->value, 0.0);
  EXPECT_LT(hash->value, 4294967296.0);
}

TEST(EngineState, TemplateValuesChangeWithWhatAStepDependsOn)
{
  const bp::ElementTemplate cross = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const std::vector<bp::NamedValue> values = bp::templateValues(cross);
  bp::ElementTemplate same = cross;
  same.name = "renamed";
  same.pinned.assign(cross.particleCount(), 0); // no flags pin nothing too
  EXPECT_EQ(bp::firstDifference(values, bp::templateValues(same), "the template"), "");
  const std::vector<std::pair<std::string, std::function<void(bp::ElementTemplate&)>>> changes = {
    { "particles",
      [](bp::ElementTemplate& t) {
        t.rest.push_back({ 0, 0, 0 });
      } },
    { "springs", [](bp::ElementTemplate& t) { t.springs.pop_back(); } },
    { "rest positions (hash)", [](bp::ElementTemplate& t) { t.rest[1][2] += 0.125f; } },
    { "springs (hash)", [](bp::ElementTemplate& t) { t.springs[0].stiffness = 0.5f; } },
    { "springs (hash)", [](bp::ElementTemplate& t) { t.springs[1].restLength *= 2.0f; } },
    { "springs (hash)", [](bp::ElementTemplate& t) { std::swap(t.springs[0].a, t.springs[0].b); } },
    { "pinned particles (hash)",
      [](bp::ElementTemplate& t)
      {
        t.pinned.assign(t.particleCount(), 0);
        t.pinned[1] = 1;
      } },
  };
  for (const auto& [name, change] : changes)
  {
    bp::ElementTemplate t = cross;
    change(t);
    const std::string said = bp::firstDifference(values, bp::templateValues(t), "the template");
    EXPECT_EQ(said.rfind("the template " + name + ":", 0), 0u) << said;
  }
}

TEST(EngineState, AStateFromBeforeASettingStandsForItsValueThen)
{
  // Restitution came with the walls: a state saved before them carries no
  // such name and resumes a trace that reflects as every trace did then.
  bp::Parameters p;
  p.boundary = bp::Boundary::Bounce;
  std::vector<bp::NamedValue> before = bp::parameterValues(p);
  before.erase(std::remove_if(before.begin(), before.end(),
                 [](const bp::NamedValue& v) { return v.name == "restitution"; }),
    before.end());
  EXPECT_EQ(bp::firstDifference(before, bp::parameterValues(p), "the setting"), "");
  p.restitution = 0.5f;
  EXPECT_EQ(bp::firstDifference(before, bp::parameterValues(p), "the setting"),
    "the setting restitution: the state's none, this trace's 0.5");
  // A name this trace lacks is still a difference, whatever it stood for.
  EXPECT_EQ(bp::firstDifference(bp::parameterValues(p), before, "the setting"),
    "the setting restitution: the state's 0.5, this trace's none");
}

TEST(EngineState, RestitutionCountsOnlyWhereTheBoundaryBounces)
{
  // A hidden Restitution once changed must not keep a Slip trace from
  // resuming a state saved with the default.
  bp::Parameters p;
  p.boundary = bp::Boundary::Slip;
  const std::vector<bp::NamedValue> saved = bp::parameterValues(p);
  p.restitution = 0.25f;
  EXPECT_EQ(bp::firstDifference(saved, bp::parameterValues(p), "the setting"), "");
  p.boundary = bp::Boundary::Bounce;
  EXPECT_EQ(bp::firstDifference(saved, bp::parameterValues(p), "the setting"),
    "the setting boundary: the state's 3, this trace's 4"); // Slip, Bounce
}

TEST(EngineState, FirstDifferenceSaysWhichAndBothValues)
{
  using V = std::vector<bp::NamedValue>;
  const V saved = { { "a", 1.0 }, { "b", 0.1f }, { "c", NAN } };
  EXPECT_EQ(bp::firstDifference(saved, saved, "the setting"), "");
  // Another NaN is still NaN; the order of the names does not matter.
  EXPECT_EQ(bp::firstDifference(
              saved, { { "c", -std::nan("7") }, { "a", 1.0 }, { "b", 0.1f } }, "the setting"),
    "");
  EXPECT_EQ(
    bp::firstDifference(saved, { { "a", 1.0 }, { "b", 0.2f }, { "c", NAN } }, "the setting"),
    "the setting b: the state's 0.1, this trace's 0.2");
  EXPECT_EQ(bp::firstDifference({ { "z", 0.0 } }, { { "z", -0.0 } }, "the field"),
    "the field z: the state's 0, this trace's -0");
  EXPECT_EQ(bp::firstDifference(saved, { { "a", 1.0 }, { "b", 0.1f } }, "the setting"),
    "the setting c: the state's NaN, this trace's none");
  EXPECT_EQ(bp::firstDifference({ { "a", 1.0 } }, { { "a", 1.0 }, { "d", INFINITY } }, "the field"),
    "the field d: the state's none, this trace's inf");
  EXPECT_EQ(
    bp::firstDifference({ { "n", 4294967295.0 } }, { { "n", 4294967294.0 } }, "the template"),
    "the template n: the state's 4294967295, this trace's 4294967294");
  // Neighbouring floats, neighbouring doubles, and a float beside the double
  // it rounds to never read alike.
  const auto values = [](const std::string& said)
  {
    const std::size_t a = said.find("the state's ") + 12, comma = said.find(',', a);
    const std::size_t b = said.find("this trace's ") + 13;
    return std::make_pair(said.substr(a, comma - a), said.substr(b));
  };
  for (const auto& [x, y] :
    std::vector<std::pair<double, double>>{ { 0.1f, std::nextafter(0.1f, 1.0f) },
      { 0.1, std::nextafter(0.1, 1.0) }, { 0.1f, 0.1 }, { 1e30f, std::nextafter(1e30f, 0.0f) } })
  {
    const std::string said = bp::firstDifference({ { "x", x } }, { { "x", y } }, "the setting");
    const auto [a, b] = values(said);
    EXPECT_NE(a, b) << said;
    EXPECT_EQ(
      std::strtod(a.c_str(), nullptr) == x || float(std::strtod(a.c_str(), nullptr)) == x, true)
      << said;
  }
}

TEST(EngineState, TheChecksumChangesWithAnyWordOrValue)
{
  const Saved good = aTrace();
  const std::uint64_t sum = bp::stateChecksum(good.state);
  bp::TraceState copy = good.state;
  EXPECT_EQ(bp::stateChecksum(copy), sum);
  std::set<std::uint64_t> sums = { sum };
  for (std::size_t k = 0; k < copy.engine.records.size(); ++k)
  {
    copy.engine.records[k] ^= 1u << (k % 32);
    EXPECT_TRUE(sums.insert(bp::stateChecksum(copy)).second) << "word " << k;
    copy.engine.records[k] = good.state.engine.records[k];
  }
  const std::vector<std::function<void(bp::TraceState&)>> changes = {
    [](bp::TraceState& s) { s.version = 3; },
    [](bp::TraceState& s) { s.engine.layout[2].name = "Flags"; },
    [](bp::TraceState& s) { s.engine.layout[3].type = bp::StateArray::Type::UInt32; },
    [](bp::TraceState& s) { ++s.engine.layout[4].components; },
    [](bp::TraceState& s) { ++s.engine.recordWords; },
    [](bp::TraceState& s) { s.engine.records.pop_back(); },
    [](bp::TraceState& s) { s.engine.trailTimes[1] = std::nextafter(s.engine.trailTimes[1], 9.0); },
    [](bp::TraceState& s) { s.engine.trailNewest = -1; },
    [](bp::TraceState& s) { s.engine.emitterMin[2] = -0.25f; },
    [](bp::TraceState& s) { s.engine.emitterMax[0] = 0.25f; },
    [](bp::TraceState& s) { s.time = std::nextafter(s.time, 1.0); },
    [](bp::TraceState& s) { ++s.steps; },
    [](bp::TraceState& s) { s.scheduleStart = -0.0; },
    [](bp::TraceState& s) { s.dt = 0.01; },
    [](bp::TraceState& s) { s.parameters[5].value += 1.0; },
    [](bp::TraceState& s) { s.parameters[5].name = "other"; },
    [](bp::TraceState& s) { s.shape.pop_back(); },
    [](bp::TraceState& s) {
      s.field.push_back({ "origin[0]", 0.0 });
    },
  };
  for (std::size_t k = 0; k < changes.size(); ++k)
  {
    bp::TraceState s = good.state;
    changes[k](s);
    EXPECT_TRUE(sums.insert(bp::stateChecksum(s)).second) << "change " << k;
  }
}

TEST(EngineState, FieldStateValuesKeepTheNamesAndHashesOfTheFirstStates)
{
  // The values the tracer saved before they moved to Core (its own FNV-1a
  // over the names' characters and the times' bytes): a state saved then
  // must still resume.
  bp::FieldStateFacts facts;
  facts.dims = { 24, 20, 2 };
  facts.bounds = { -1, 1, 0, 1.8, 0.25, 0.25 };
  facts.vectors = "velocity";
  facts.vectorsAssociation = 1;
  facts.releaseWeights = "w";
  facts.inputTimes = { 0.0, 0.5, 1.0 };
  facts.startMaxSpeed = 2.5;
  facts.timeDirection = 1;
  facts.processes = 2;
  const std::vector<std::pair<std::string, double>> expected = { { "points along x", 24 },
    { "points along y", 20 }, { "points along z", 2 }, { "bounds x from", -1 },
    { "bounds x to", 1 }, { "bounds y from", 0 }, { "bounds y to", 1.8 }, { "bounds z from", 0.25 },
    { "bounds z to", 0.25 }, { "Vectors array (hash)", 846470194.0 + 1 },
    { "Release Weights array (hash)", 4060888886.0 }, { "time steps", 3 },
    { "time steps (hash)", 3521701429.0 }, { "largest speed at the start", 2.5 },
    { "Time Direction (0 Forward, 1 Backward)", 1 }, { "periodic along x", 0 },
    { "periodic along y", 0 }, { "periodic along z", 0 }, { "processes", 2 } };
  const std::vector<bp::NamedValue> values = bp::fieldStateValues(facts);
  ASSERT_EQ(values.size(), expected.size());
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    EXPECT_EQ(values[k].name, expected[k].first);
    EXPECT_EQ(values[k].value, expected[k].second) << values[k].name;
  }
  // No Release Weights: the hash of no characters, FNV-1a's basis.
  facts.releaseWeights.clear();
  EXPECT_EQ(bp::fieldStateValues(facts)[10].value, 2166136261.0);
}

TEST(EngineState, AStateFromBeforePeriodicStandsForNoPeriodicAxis)
{
  bp::FieldStateFacts facts;
  facts.dims = { 9, 9, 9 };
  facts.bounds = { -1, 1, -1, 1, -1, 1 };
  facts.vectors = "velocity";
  std::vector<bp::NamedValue> before = bp::fieldStateValues(facts);
  before.erase(std::remove_if(before.begin(), before.end(),
                 [](const bp::NamedValue& v) { return v.name.rfind("periodic", 0) == 0; }),
    before.end());
  EXPECT_EQ(bp::firstDifference(before, bp::fieldStateValues(facts), "the field's"), "");
  facts.periodic[1] = true;
  EXPECT_EQ(bp::firstDifference(before, bp::fieldStateValues(facts), "the field's"),
    "the field's periodic along y: the state's none, this trace's 1");
  // A state saved periodic resumes only a periodic trace.
  EXPECT_EQ(bp::firstDifference(bp::fieldStateValues(facts), before, "the field's"),
    "the field's periodic along x: the state's 0, this trace's none");
  bp::FieldStateFacts other = facts;
  other.periodic[1] = false;
  EXPECT_EQ(
    bp::firstDifference(bp::fieldStateValues(facts), bp::fieldStateValues(other), "the field's"),
    "the field's periodic along y: the state's 1, this trace's 0");
}

TEST(EngineState, AFieldOnAnotherNumberOfProcessesAgrees)
{
  bp::FieldStateFacts facts;
  facts.dims = { 24, 24, 24 };
  facts.bounds = { 1e6, 1e6 + 4, -1, 1, -1, 1 };
  facts.vectors = "velocity";
  facts.inputTimes = { 0.0 };
  facts.startMaxSpeed = 1.75;
  facts.processes = 2;
  const std::vector<bp::NamedValue> saved = bp::fieldStateValues(facts);
  // Another process count, and corners rounded another way (seen: 1 on 2
  // processes, 0.9999999999999998 on 4).
  bp::FieldStateFacts other = facts;
  other.processes = 4;
  other.bounds[1] = std::nextafter(std::nextafter(1e6 + 4, 0.0), 0.0);
  other.bounds[3] = 0.9999999999999998;
  EXPECT_EQ(bp::firstDifference(saved, bp::fieldStateValues(other), "the field's"), "");
  // But not another grid: a bound moved by a billionth of the domain, a
  // point more, or the largest speed a bit off.
  other = facts;
  other.bounds[3] = 1 + 2e-9;
  EXPECT_EQ(bp::firstDifference(saved, bp::fieldStateValues(other), "the field's"),
    "the field's bounds y to: the state's 1, this trace's 1.000000002");
  other = facts;
  other.bounds[0] = 1e6 + 1e-6;
  EXPECT_EQ(bp::firstDifference(saved, bp::fieldStateValues(other), "the field's")
              .rfind("the field's bounds x from:", 0),
    0u);
  other = facts;
  other.dims[2] = 25;
  EXPECT_EQ(bp::firstDifference(saved, bp::fieldStateValues(other), "the field's"),
    "the field's points along z: the state's 24, this trace's 25");
  other = facts;
  other.startMaxSpeed = std::nextafter(1.75, 2.0);
  EXPECT_EQ(bp::firstDifference(saved, bp::fieldStateValues(other), "the field's")
              .rfind("the field's largest speed at the start:", 0),
    0u);
}

TEST(EngineState, FirstDifferenceTakesTheTracesTolerance)
{
  const std::vector<bp::NamedValue> now = { { "a", 1.0, 0.5 }, { "b", 2.0, INFINITY } };
  EXPECT_EQ(bp::firstDifference({ { "a", 1.5 }, { "b", -7.0 } }, now, "the field's"), "");
  EXPECT_EQ(bp::firstDifference({ { "a", 1.6 }, { "b", 2.0 } }, now, "the field's"),
    "the field's a: the state's 1.6, this trace's 1");
  // NaN lies within no tolerance; a name missing is still said.
  EXPECT_EQ(bp::firstDifference({ { "a", NAN }, { "b", 2.0 } }, now, "the field's"),
    "the field's a: the state's NaN, this trace's 1");
  EXPECT_EQ(bp::firstDifference({ { "a", 1.0 } }, now, "the field's"),
    "the field's b: the state's none, this trace's 2");
}
