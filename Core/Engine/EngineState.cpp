// SPDX-License-Identifier: BSD-3-Clause
// A trace's saved state (EngineState.h): the named values a resumed trace
// must match, how a mismatch is said, the checksum, and the checks a state
// must pass before an engine loads it. The engine's own part (its layout,
// save and load) is in EngineSaveState.cpp.
#include "EngineState.h"
#include "Engine.h"
#include "Surfaces.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <type_traits>

namespace bp
{
namespace
{
/// FNV-1a over values fed as little-endian bytes, so that a hash is the
/// same on every machine.
template <class Word, Word Basis, Word Prime>
class Fnv1a
{
public:
  void bytes(std::uint64_t v, int count)
  {
    for (int k = 0; k < count; ++k)
    {
      this->Value = Word((this->Value ^ Word((v >> (8 * k)) & 0xffu)) * Prime);
    }
  }
  void u32(std::uint32_t v) { this->bytes(v, 4); }
  void u64(std::uint64_t v) { this->bytes(v, 8); }
  void f32(float f)
  {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    this->u32(u);
  }
  void f64(double d)
  {
    std::uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    this->u64(u);
  }
  /// The characters alone, without the length text() puts first.
  void chars(const std::string& s)
  {
    for (const char c : s)
    {
      this->bytes(std::uint8_t(c), 1);
    }
  }
  void text(const std::string& s)
  {
    this->u64(s.size());
    this->chars(s);
  }
  Word value() const { return this->Value; }

private:
  Word Value = Basis;
};
using Hash32 = Fnv1a<std::uint32_t, 2166136261u, 16777619u>;
using Hash64 = Fnv1a<std::uint64_t, 14695981039346656037ull, 1099511628211ull>;

void add(std::vector<NamedValue>& values, const std::string& name, double value)
{
  values.push_back({ name, value });
}

template <class E>
void addEnum(std::vector<NamedValue>& values, const std::string& name, E value)
{
  add(values, name, double(static_cast<std::underlying_type_t<E>>(value)));
}

template <class T, std::size_t N>
void addArray(std::vector<NamedValue>& values, const std::string& name, const std::array<T, N>& a)
{
  for (std::size_t k = 0; k < N; ++k)
  {
    add(values, name + "[" + std::to_string(k) + "]", double(a[k]));
  }
}

bool sameBits(double a, double b)
{
  if (std::isnan(a) && std::isnan(b))
  {
    return true;
  }
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// The shortest text that reads back as `v`: as a float's where `v` is
/// one (0.1f says "0.1"), so that two values that differ never read alike.
std::string valueText(double v)
{
  if (std::isnan(v))
  {
    return "NaN";
  }
  if (std::isinf(v))
  {
    return v > 0 ? "inf" : "-inf";
  }
  if (v == std::floor(v) && std::abs(v) < 9.0e15)
  {
    return std::to_string((long long)v); // a count or a whole number, never "1.2e+02"
  }
  const bool isFloat =
    std::abs(v) <= double(std::numeric_limits<float>::max()) && sameBits(double(float(v)), v);
  std::string text;
  for (int digits = 1; digits <= 17; ++digits)
  {
    std::ostringstream out;
    out << std::setprecision(digits) << v;
    text = out.str();
    const double back = std::strtod(text.c_str(), nullptr);
    if (isFloat ? sameBits(double(float(back)), v) : sameBits(back, v))
    {
      break;
    }
  }
  return text;
}

std::string typeName(StateArray::Type type)
{
  switch (type)
  {
    case StateArray::Type::UInt32:
      return "32-bit integers";
    case StateArray::Type::UInt8:
      return "8-bit integers";
    case StateArray::Type::Float32:
      return "floats";
  }
  return "values of an unknown type";
}

/// What differs between the state's record layout and this trace's, or empty.
std::string layoutDifference(
  const std::vector<StateArray>& saved, const std::vector<StateArray>& now)
{
  const std::string why = ": it was saved with another element template or other settings";
  for (std::size_t k = 0; k < std::max(saved.size(), now.size()); ++k)
  {
    if (k >= saved.size())
    {
      return "the state lacks the element array " + now[k].name + why;
    }
    if (k >= now.size())
    {
      return "the state holds an element array " + saved[k].name + " this trace has not" + why;
    }
    const StateArray &a = saved[k], &b = now[k];
    if (a.name != b.name)
    {
      return "the state's element array " + std::to_string(k) + " is " + a.name +
        " where this trace's is " + b.name + why;
    }
    if (a.type != b.type)
    {
      return "the state's element array " + a.name + " holds " + typeName(a.type) +
        " where this trace's holds " + typeName(b.type) + why;
    }
    if (a.components != b.components)
    {
      return "the state's element array " + a.name + " holds " + std::to_string(a.components) +
        " values an element where this trace's holds " + std::to_string(b.components) + why;
    }
  }
  return std::string();
}

/// What is wrong with the records' ids (the first word of each), or empty.
std::string idsProblem(const EngineState& state, std::size_t words, std::size_t elements)
{
  const std::size_t count = state.records.size() / words;
  for (std::size_t r = 0; r < count; ++r)
  {
    const std::uint32_t id = state.records[r * words];
    if (id >= elements)
    {
      return "the state's element record " + std::to_string(r) + " carries id " +
        std::to_string(id) + ", but the trace has " + std::to_string(elements) + " elements";
    }
    if (r > 0 && id <= state.records[(r - 1) * words])
    {
      return "the state's element ids are repeated or out of order: id " + std::to_string(id) +
        " follows id " + std::to_string(state.records[(r - 1) * words]);
    }
  }
  return std::string();
}
} // namespace

std::vector<NamedValue> parameterValues(const Parameters& p)
{
  // Every member of Parameters, in declaration order (TestEngineState
  // checks the struct's size, so a member added there is added here too).
  std::vector<NamedValue> v;
  add(v, "numberOfElements", double(p.numberOfElements));
  add(v, "elementSize", p.elementSize);
  addArray(v, "emitterMin", p.emitterMin);
  addArray(v, "emitterMax", p.emitterMax);
  addEnum(v, "orientation", p.orientation);
  addArray(v, "frame", p.frame);
  add(v, "planeAxis", p.planeAxis);
  add(v, "lifetimeMin", p.lifetimeMin);
  add(v, "lifetimeMax", p.lifetimeMax);
  addEnum(v, "integrator", p.integrator);
  addEnum(v, "restoration", p.restoration);
  add(v, "iterations", p.iterations);
  add(v, "relaxation", p.relaxation);
  add(v, "shapeStiffness", p.shapeStiffness);
  add(v, "linearShapeMatching", p.linearShapeMatching ? 1.0 : 0.0);
  add(v, "linearBlend", p.linearBlend);
  addEnum(v, "linking", p.linking);
  add(v, "latticeWidth", p.latticeWidth);
  add(v, "linkStiffness", p.linkStiffness);
  addEnum(v, "resetWhen", p.resetWhen);
  addEnum(v, "boundary", p.boundary);
  // Restitution came with the walls (Bounce): before them every trace
  // reflected nothing, which its default 1 leaves as it was. Only Bounce
  // reads it, so any other Boundary saves 1: a trace whose hidden
  // Restitution was once changed still resumes a state that never bounced.
  const double restitution = p.boundary == Boundary::Bounce ? p.restitution : 1.0;
  v.push_back({ "restitution", restitution, 0.0, 1.0 });
  // The Surfaces came later: a state saved before them had none.
  Hash32 surfaces;
  std::size_t triangles = 0;
  if (p.surfaces)
  {
    const SurfaceTriangles& given = p.surfaces->triangles();
    triangles = given.cells.size();
    for (const float f : given.corners)
    {
      surfaces.f32(f);
    }
    for (std::size_t k = 0; k < triangles; ++k)
    {
      surfaces.u32(std::uint32_t(given.surfaces[k]));
      surfaces.u32(std::uint32_t(given.cells[k]));
      surfaces.u32(std::uint32_t(given.interaction[k]));
    }
  }
  v.push_back({ "surfaces.count", double(triangles), 0.0, 0.0 });
  v.push_back({ "surfaces.hash", triangles ? double(surfaces.value()) : 0.0, 0.0, 0.0 });
  addEnum(v, "releasePattern", p.releasePattern);
  addArray(v, "lattice.counts", p.lattice.counts);
  addArray(v, "lattice.origin", p.lattice.origin);
  addArray(v, "lattice.spacing", p.lattice.spacing);
  addEnum(v, "anchor", p.anchor);
  addEnum(v, "inertia", p.inertia);
  add(v, "responseTime", p.responseTime);
  add(v, "densityRatio", p.densityRatio);
  addArray(v, "gravity", p.gravity);
  Hash32 seeds;
  for (const float f : p.seedPoints)
  {
    seeds.f32(f);
  }
  add(v, "seedPoints.count", double(p.seedPoints.size()));
  add(v, "seedPoints.hash", double(seeds.value()));
  add(v, "releaseStart", p.releaseStart);
  add(v, "releaseStop", p.releaseStop);
  add(v, "releaseMinSpeed", p.releaseMinSpeed);
  add(v, "seed", double(p.seed));
  add(v, "trackPoses", p.trackPoses ? 1.0 : 0.0);
  add(v, "trailLength", p.trailLength);
  add(v, "trailStart", p.trailStart);
  add(v, "trailInterval", p.trailInterval);
  add(v, "ftleMinimumAge", p.ftleMinimumAge);
  return v;
}

std::vector<NamedValue> templateValues(const ElementTemplate& shape)
{
  Hash32 rest, springs, pinned;
  for (const auto& r : shape.rest)
  {
    rest.f32(r[0]);
    rest.f32(r[1]);
    rest.f32(r[2]);
  }
  for (const Spring& s : shape.springs)
  {
    springs.u32(s.a);
    springs.u32(s.b);
    springs.f32(s.restLength);
    springs.f32(s.stiffness);
  }
  for (std::size_t i = 0; i < shape.particleCount(); ++i)
  {
    // No flags pin nothing, as the engine reads them.
    pinned.u32(i < shape.pinned.size() && shape.pinned[i] ? 1u : 0u);
  }
  return { { "particles", double(shape.particleCount()) },
    { "springs", double(shape.springs.size()) }, { "rest positions (hash)", double(rest.value()) },
    { "springs (hash)", double(springs.value()) },
    { "pinned particles (hash)", double(pinned.value()) } };
}

std::vector<NamedValue> fieldStateValues(const FieldStateFacts& facts)
{
  // The names and values (and their order) are those of the first states
  // saved: a state keeps them, and one saved before must still resume.
  std::vector<NamedValue> values;
  const char* axes[3] = { "x", "y", "z" };
  for (int a = 0; a < 3; ++a)
  {
    values.push_back({ std::string("points along ") + axes[a], double(facts.dims[a]) });
  }
  for (int a = 0; a < 3; ++a)
  {
    // The corners of pieces split another way round to a few ulps of the
    // domain's size or place (2.2e-16 at 1 seen between 2 and 4 processes).
    const double from = facts.bounds[2 * a], to = facts.bounds[2 * a + 1];
    const double scale = std::max({ std::abs(from), std::abs(to), std::abs(to - from) });
    const double tolerance = 64.0 * std::numeric_limits<double>::epsilon() * scale;
    values.push_back({ std::string("bounds ") + axes[a] + " from", from, tolerance });
    values.push_back({ std::string("bounds ") + axes[a] + " to", to, tolerance });
  }
  // What the field is beyond its grid: which arrays, its time steps (the
  // schedule's breaks), its largest speed at the start. Its values after
  // the start are not compared.
  Hash32 vectors, weights, times;
  vectors.chars(facts.vectors);
  weights.chars(facts.releaseWeights);
  for (const double t : facts.inputTimes)
  {
    times.f64(t);
  }
  values.push_back({ "Vectors array (hash)", double(vectors.value()) + facts.vectorsAssociation });
  values.push_back({ "Release Weights array (hash)", double(weights.value()) });
  values.push_back({ FieldStateNames::TimeSteps, double(facts.inputTimes.size()) });
  values.push_back({ FieldStateNames::TimeStepsHash, double(times.value()) });
  values.push_back({ FieldStateNames::LargestStartSpeed, facts.startMaxSpeed });
  values.push_back({ FieldStateNames::TimeDirection, double(facts.timeDirection) });
  // Periodic came with the periodic domains: every trace before them had none.
  for (int a = 0; a < 3; ++a)
  {
    values.push_back(
      { std::string("periodic along ") + axes[a], facts.periodic[a] ? 1.0 : 0.0, 0.0, 0.0 });
  }
  // Kept to say where a state came from; the elements are split among the
  // resuming processes by their centres, whatever number saved them.
  values.push_back(
    { "processes", double(facts.processes), std::numeric_limits<double>::infinity() });
  return values;
}

std::string firstDifference(
  const std::vector<NamedValue>& saved, const std::vector<NamedValue>& now, const std::string& what)
{
  const auto say = [&what](const std::string& name, const std::string& a, const std::string& b)
  { return what + " " + name + ": the state's " + a + ", this trace's " + b; };
  const auto differ = [&say](const std::string& name, double a, double b)
  {
    // A float's shortest text may be a nearby double's too (0.1f, 0.1): then all the digits.
    std::string textA = valueText(a), textB = valueText(b);
    if (textA == textB)
    {
      std::ostringstream outA, outB;
      outA << std::setprecision(17) << a;
      outB << std::setprecision(17) << b;
      textA = outA.str();
      textB = outB.str();
    }
    return say(name, textA, textB);
  };
  std::map<std::string, const NamedValue*> current;
  std::map<std::string, double> before;
  for (const NamedValue& v : now)
  {
    current.emplace(v.name, &v); // the first of a name repeated
  }
  for (const NamedValue& v : saved)
  {
    before.emplace(v.name, v.value);
    const auto found = current.find(v.name);
    if (found == current.end())
    {
      return say(v.name, valueText(v.value), "none");
    }
    const NamedValue& mine = *found->second;
    // NaN is within no tolerance, but the same bits.
    const bool near = mine.tolerance > 0.0 &&
      (std::isinf(mine.tolerance) || std::abs(mine.value - v.value) <= mine.tolerance);
    if (!near && !sameBits(mine.value, v.value))
    {
      return differ(v.name, v.value, mine.value);
    }
  }
  for (const NamedValue& v : now)
  {
    // A setting the state predates agrees when this trace keeps it as it was.
    const bool standsFor = !std::isnan(v.whenAbsent) && sameBits(v.whenAbsent, v.value);
    if (before.find(v.name) == before.end() && !standsFor)
    {
      return say(v.name, "none", valueText(v.value));
    }
  }
  return std::string();
}

std::uint64_t stateChecksum(const TraceState& state)
{
  Hash64 h;
  h.u32(state.version);
  const EngineState& e = state.engine;
  h.u64(e.layout.size());
  for (const StateArray& a : e.layout)
  {
    h.text(a.name);
    h.u32(std::uint32_t(a.type));
    h.u64(a.components);
  }
  h.u64(e.recordWords);
  h.u64(e.records.size());
  for (const std::uint32_t word : e.records)
  {
    h.u32(word);
  }
  h.u64(e.trailTimes.size());
  for (const double t : e.trailTimes)
  {
    h.f64(t);
  }
  h.u32(std::uint32_t(e.trailNewest));
  for (int k = 0; k < 3; ++k)
  {
    h.f32(e.emitterMin[std::size_t(k)]);
    h.f32(e.emitterMax[std::size_t(k)]);
  }
  h.f64(state.time);
  h.u64(std::uint64_t(state.steps));
  h.f64(state.scheduleStart);
  h.f64(state.dt);
  for (const std::vector<NamedValue>* values : { &state.parameters, &state.shape, &state.field })
  {
    h.u64(values->size());
    for (const NamedValue& v : *values)
    {
      h.text(v.name);
      h.f64(v.value);
    }
  }
  return h.value();
}

std::string checkEngineState(
  const EngineState& state, const std::vector<StateArray>& layout, const Parameters& p)
{
  std::string error = layoutDifference(state.layout, layout);
  if (!error.empty())
  {
    return error;
  }
  std::size_t words = 0;
  for (const StateArray& a : layout)
  {
    words += a.components;
  }
  if (words == 0 || state.recordWords != words)
  {
    return "the state's element records are " + std::to_string(state.recordWords) +
      " words each where this trace's are " + std::to_string(words);
  }
  if (state.records.size() % words != 0)
  {
    return "the state's element records are cut short: " + std::to_string(state.records.size()) +
      " words are not whole records of " + std::to_string(words);
  }
  // Whole: a state's elements are every element of its trace (a piece of a
  // distributed run keeps its own after loading them all).
  if (state.elementCount() != p.numberOfElements)
  {
    return "the state holds " + std::to_string(state.elementCount()) +
      " elements where this trace has " + std::to_string(p.numberOfElements);
  }
  error = idsProblem(state, words, p.numberOfElements);
  if (!error.empty())
  {
    return error;
  }
  const std::size_t slots = std::size_t(std::max(p.trailLength, 0));
  if (state.trailTimes.size() != slots)
  {
    return "the state's trail ring keeps " + std::to_string(state.trailTimes.size()) +
      " poses where this trace's TrailLength keeps " + std::to_string(slots);
  }
  if (state.trailNewest < -1 || state.trailNewest >= int(slots))
  {
    return "the state's newest trail pose is in slot " + std::to_string(state.trailNewest) +
      ", not one of the trail ring's " + std::to_string(slots);
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!std::isfinite(state.emitterMin[std::size_t(k)]) ||
      !std::isfinite(state.emitterMax[std::size_t(k)]))
    {
      return "the state's emitter box is not finite";
    }
  }
  return std::string();
}

std::string checkTraceState(
  const TraceState& state, const ElementTemplate& shape, const Parameters& p)
{
  if (state.version != EngineStateVersion)
  {
    return "the state was saved by engine state version " + std::to_string(state.version) +
      "; this engine's is " + std::to_string(EngineStateVersion) + ": trace again from the start";
  }
  if (!std::isfinite(state.time) || !std::isfinite(state.scheduleStart) ||
    !std::isfinite(state.dt) || state.steps < 0)
  {
    return "the state's time, step count or step is not a number it could have been saved with";
  }
  return checkEngineState(state.engine, Engine::stateLayout(shape, p), p);
}

} // namespace bp
