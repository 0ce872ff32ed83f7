// SPDX-License-Identifier: BSD-3-Clause
// Distributed runs without MPI: pieces on threads exchange elements through
// memory, and must reproduce the single-process run.
#include "MemoryExchange.h"
#include "Partition.h"
#include "TestHelpers.h"

#include <cstdint>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <thread>

namespace
{

/// The whole grid's point extent [first, last] along each axis split in two
/// along x and, for four pieces, along y (or, with `slabs`, into `pieces`
/// slabs along z): piece k's point ranges.
std::vector<std::array<int, 6>> splitExtent(const bp::GridGeometry& g, int pieces, bool slabs)
{
  if (slabs)
  {
    // z only, as the tracer splits a field periodic along x and y
    // (bpvtk::pieceBlock): each block the whole of x and y.
    std::vector<std::array<int, 6>> out;
    const int cells = g.dims[2] - 1;
    for (int k = 0; k < pieces; ++k)
      out.push_back(
        { 0, g.dims[0] - 1, 0, g.dims[1] - 1, cells * k / pieces, cells * (k + 1) / pieces });
    return out;
  }
  const int mx = (g.dims[0] - 1) / 2, my = (g.dims[1] - 1) / 3;
  const int last[3] = { g.dims[0] - 1, g.dims[1] - 1, g.dims[2] - 1 };
  if (pieces == 2)
    return { { 0, mx, 0, last[1], 0, last[2] }, { mx, last[0], 0, last[1], 0, last[2] } };
  return { { 0, mx, 0, my, 0, last[2] }, { mx, last[0], 0, my, 0, last[2] },
    { 0, mx, my, last[1], 0, last[2] }, { mx, last[0], my, last[1], 0, last[2] } };
}

bp::Box boxOf(const bp::GridGeometry& g, const std::array<int, 6>& extent)
{
  bp::Box b;
  for (int a = 0; a < 3; ++a)
  {
    b[2 * a] = g.coordinate(a, extent[2 * a]);
    b[2 * a + 1] = g.coordinate(a, extent[2 * a + 1]);
  }
  return b;
}

/// The points of `extent` grown by `ghost` layers (within the grid), and
/// the whole axis along a periodic one (as the tracer asks its input for
/// them: PieceLayout::blockWithGhosts), as a field of its own.
bp::VectorField cut(const bp::VectorField& whole, std::array<int, 6> extent, int ghost)
{
  const bp::GridGeometry& g = whole.grid();
  bp::GridGeometry piece;
  piece.periodic = g.periodic;
  for (int a = 0; a < 3; ++a)
  {
    const bool wholeAxis = g.periodic[std::size_t(a)];
    extent[2 * a] = wholeAxis ? 0 : std::max(0, extent[2 * a] - ghost);
    extent[2 * a + 1] =
      wholeAxis ? g.dims[a] - 1 : std::min(g.dims[a] - 1, extent[2 * a + 1] + ghost);
    piece.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    piece.origin[a] = g.coordinate(a, extent[2 * a]);
    piece.spacing[a] = g.spacing[a];
  }
  auto values = std::make_shared<std::vector<float>>();
  const std::vector<float>& all = *whole.firstSlice().velocity;
  for (int k = extent[4]; k <= extent[5]; ++k)
    for (int j = extent[2]; j <= extent[3]; ++j)
      for (int i = extent[0]; i <= extent[1]; ++i)
      {
        const std::size_t id = (std::size_t(k) * g.dims[1] + j) * g.dims[0] + i;
        values->insert(values->end(), all.begin() + 3 * id, all.begin() + 3 * id + 3);
      }
  bp::FieldSlice s;
  s.velocity = values;
  return bp::VectorField(piece, s);
}

bp::Parameters parameters(bp::Orientation orientation = bp::Orientation::Random,
  bp::Boundary boundary = bp::Boundary::ReleaseAgain, bool trails = true)
{
  bp::Parameters p;
  p.boundary = boundary;
  p.restitution = 0.5f;
  p.orientation = orientation;
  p.numberOfElements = 300;
  p.elementSize = 0.12f;
  p.emitterMin = { -0.9f, -0.9f, -0.9f };
  p.emitterMax = { 0.9f, 0.9f, 0.9f };
  p.lifetimeMin = 0.3f;
  p.lifetimeMax = 0.6f;
  p.integrator = bp::Integrator::RK4;
  p.restoration = bp::Restoration::ShapeMatching;
  p.seed = 11;
  // Poses, spins and trails travel with the elements.
  p.trackPoses = true;
  p.trailLength = trails ? 3 : 0; // none with Periodic, as the tracer refuses them
  p.trailInterval = 0.1; // every 5 steps of 0.02
  return p;
}

struct Element
{
  std::uint32_t generation;
  std::vector<float> positions;
  std::vector<float> poseAndSpin;              ///< 8 floats
  std::vector<std::uint32_t> trailGenerations; ///< per slot, newest first
  std::vector<float> trailPositions;           ///< per slot, newest first
};

/// Element e's state in `engine`.
Element elementOf(const bp::Engine& engine, std::size_t e)
{
  const std::size_t n = engine.particlesPerElement(), E = engine.elementCount();
  Element d;
  d.generation = engine.generations()[e];
  const float* p = engine.positions().data() + 3 * e * n;
  d.positions.assign(p, p + 3 * n);
  d.poseAndSpin.assign(engine.poses().begin() + 4 * e, engine.poses().begin() + 4 * e + 4);
  d.poseAndSpin.insert(
    d.poseAndSpin.end(), engine.spins().begin() + 4 * e, engine.spins().begin() + 4 * e + 4);
  for (int k = 0; k < engine.parameters().trailLength; ++k)
  {
    const std::size_t slot = std::size_t(engine.trailSlot(k));
    d.trailGenerations.push_back(engine.trailGenerations()[slot * E + e]);
    const float* t = engine.trailPositions().data() + 3 * (slot * E + e) * n;
    d.trailPositions.insert(d.trailPositions.end(), t, t + 3 * n);
  }
  return d;
}

/// Runs the system on `pieces` threads; the state by element id, and the
/// number of elements that changed pieces.
std::map<std::uint32_t, Element> runDistributed(const bp::VectorField& whole, int pieces,
  bool ghostedPieces, int steps, double dt, long long& migrated, bp::Orientation orientation,
  bp::Boundary boundary, bool trails, bool slabs)
{
  const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape::Cross);
  const auto extents = splitExtent(whole.grid(), pieces, slabs);
  std::vector<bp::Box> boxes;
  for (const auto& e : extents)
    boxes.push_back(boxOf(whole.grid(), e));
  const bp::Partition partition(boxes);
  const int ghost =
    bp::ghostCellsNeeded(parameters().elementSize, whole.maxSpeed(), dt, whole.grid().cellLength());
  bptest::MemoryExchange exchange(pieces);
  const std::size_t count = std::size_t(pieces);
  std::vector<bp::Engine> engines(count);
  std::vector<std::string> errors(count);
  std::vector<long long> moved(count, 0);
  std::vector<std::thread> threads;
  for (int k = 0; k < pieces; ++k)
  {
    threads.emplace_back(
      [&, k]
      {
        const bp::VectorField field =
          ghostedPieces ? cut(whole, extents[std::size_t(k)], ghost) : whole;
        bp::Engine& engine = engines[std::size_t(k)];
        errors[std::size_t(k)] = engine.configure(shape, parameters(orientation, boundary, trails));
        engine.setDomain(whole.domain());
        // Along Flow samples this piece's field: right for the elements it keeps.
        engine.initialize(bp::serialRunner(), 0.0, &field);
        bp::keepOwned(engine, partition, k);
        for (int s = 0; s < steps; ++s)
        {
          engine.resetDue(bp::serialRunner(), s * dt, dt);
          std::string error;
          const long long left = bp::migrate(engine, partition, k, exchange.forPiece(k), error);
          moved[std::size_t(k)] += std::max(left, 0LL);
          if (!error.empty())
            errors[std::size_t(k)] = error;
          engine.step(field, s * dt, dt, bp::serialRunner());
        }
      });
  }
  for (auto& t : threads)
    t.join();
  std::map<std::uint32_t, Element> state;
  migrated = 0;
  for (int k = 0; k < pieces; ++k)
  {
    EXPECT_EQ(errors[std::size_t(k)], "");
    migrated += moved[std::size_t(k)];
    const bp::Engine& engine = engines[std::size_t(k)];
    for (std::size_t e = 0; e < engine.elementCount(); ++e)
    {
      const std::uint32_t id = engine.elementIds()[e];
      EXPECT_EQ(state.count(id), 0u) << "element " << id << " is held twice";
      state[id] = elementOf(engine, e);
    }
  }
  return state;
}

/// Expects runs on 2 and 4 pieces, with the whole field or ghosted pieces,
/// to reproduce `serial`, run on `whole` from the same parameters.
void expectPiecesReproduce(const bp::Engine& serial, const bp::VectorField& whole, int steps,
  double dt, bp::Orientation orientation, bp::Boundary boundary = bp::Boundary::ReleaseAgain,
  bool slabs = false)
{
  const std::size_t n = serial.particlesPerElement();
  const bool trails = serial.parameters().trailLength > 0;
  for (int pieces : { 2, 4 })
  {
    for (bool ghosted : { false, true })
    {
      long long migrated = 0;
      const auto state = runDistributed(
        whole, pieces, ghosted, steps, dt, migrated, orientation, boundary, trails, slabs);
      ASSERT_EQ(state.size(), serial.elementCount());
      // Elements crossed between pieces, and some were reset (lifetimes end).
      EXPECT_GT(migrated, 100) << pieces << " pieces";
      float worst = 0.0f, worstPose = 0.0f;
      int trailPoses = 0;
      for (std::size_t e = 0; e < serial.elementCount(); ++e)
      {
        const Element& d = state.at(std::uint32_t(e));
        const Element s = elementOf(serial, e);
        EXPECT_EQ(d.generation, s.generation);
        for (std::size_t i = 0; i < 3 * n; ++i)
          worst = std::max(worst, std::abs(d.positions[i] - s.positions[i]));
        for (std::size_t i = 0; i < 8; ++i)
          worstPose = std::max(worstPose, std::abs(d.poseAndSpin[i] - s.poseAndSpin[i]));
        EXPECT_EQ(d.trailGenerations, s.trailGenerations);
        for (std::size_t i = 0; i < d.trailPositions.size(); ++i)
          worst = std::max(worst, std::abs(d.trailPositions[i] - s.trailPositions[i]));
        trailPoses +=
          int(std::count(s.trailGenerations.begin(), s.trailGenerations.end(), s.generation));
      }
      if (trails)
        EXPECT_GT(trailPoses, 100); // trails of the elements' own generation
      EXPECT_LE(worstPose, ghosted ? 1e-2f : 0.0f) << pieces << " pieces, ghosted " << ghosted;
      // The whole field on every piece gives the same bits; ghosted pieces
      // locate cells from their own origin, which rounds differently.
      EXPECT_LE(worst, ghosted ? 1e-4f : 0.0f) << pieces << " pieces, ghosted " << ghosted;
    }
  }
}

} // namespace

TEST(Partition, EveryPositionHasOneOwner)
{
  const bp::Partition partition({ { 0, 1, 0, 1, 0, 0 }, { 1, 2, 0, 1, 0, 0 } });
  const float inFirst[3] = { 0.5f, 0.5f, 0.0f }, onFace[3] = { 1.0f, 0.5f, 0.0f },
              onTop[3] = { 2.0f, 1.0f, 0.0f }, beyond[3] = { 7.0f, -3.0f, 4.0f },
              before[3] = { -1.0f, 0.2f, 0.0f }, nan[3] = { NAN, 0.5f, 0.0f };
  EXPECT_EQ(partition.ownerOf(inFirst), 0);
  EXPECT_EQ(partition.ownerOf(onFace), 1); // closed below, open above
  EXPECT_EQ(partition.ownerOf(onTop), 1);  // the domain's upper faces are closed
  EXPECT_EQ(partition.ownerOf(beyond), 1); // the nearest point of the domain
  EXPECT_EQ(partition.ownerOf(before), 0);
  EXPECT_EQ(partition.ownerOf(nan), 0);
  EXPECT_EQ(partition.domain(), (bp::Box{ 0, 2, 0, 1, 0, 0 }));
  EXPECT_EQ(bp::Partition::validate({}), "no pieces");
  EXPECT_EQ(bp::Partition::validate({ { 0, 1, 2, 1, 0, 0 } }), "no pieces");
  EXPECT_NE(bp::Partition::validate({ { 0, NAN, 0, 1, 0, 0 } }), "");
  // A piece with nothing to own (min > max) is skipped.
  const bp::Partition withEmpty({ { 1, 0, 1, 0, 1, 0 }, { 0, 1, 0, 1, 0, 0 } });
  EXPECT_EQ(withEmpty.ownerOf(beyond), 1);
  EXPECT_EQ(withEmpty.domain(), (bp::Box{ 0, 1, 0, 1, 0, 0 }));
}

TEST(Partition, GhostLayersCoverAnElementAndAStep)
{
  // A size-0.5 element moving 0.25 per step on cells of 0.1: 8 cells and 2 more.
  EXPECT_EQ(bp::ghostCellsNeeded(0.5, 2.5, 0.1, 0.1), 10);
  EXPECT_EQ(bp::ghostCellsNeeded(0.5, 2.5, 0.1, 0.0), 2);
}

TEST(Partition, ElementRecordsRoundTrip)
{
  const bp::VectorField field = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(17));
  bp::Engine a, b;
  bp::Parameters p = parameters();
  p.numberOfElements = 10;
  ASSERT_EQ(a.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
  b = a;
  a.initialize(bp::serialRunner());
  b.initialize(bp::serialRunner());
  for (int s = 0; s < 20; ++s)
    a.step(field, s * 0.05, 0.05, bp::serialRunner());
  // Move elements 3 and 7 of a into b in place of b's own.
  std::vector<std::uint32_t> records;
  a.packElement(3, records);
  a.packElement(7, records);
  EXPECT_EQ(records.size(), 2 * a.recordWords());
  std::vector<std::uint8_t> leaving(10, 0);
  leaving[3] = leaving[7] = 1;
  ASSERT_EQ(b.exchange(leaving, records), "");
  ASSERT_EQ(b.elementCount(), 10u);
  const std::size_t n = a.particlesPerElement();
  for (std::size_t e : { 3u, 7u })
  {
    EXPECT_EQ(b.elementIds()[e], e);
    EXPECT_EQ(b.generations()[e], a.generations()[e]);
    EXPECT_EQ(b.lifetimes()[e], a.lifetimes()[e]);
    for (std::size_t i = 0; i < 3 * n; ++i)
      EXPECT_EQ(b.positions()[3 * e * n + i], a.positions()[3 * e * n + i]);
  }
  // Bad records are refused with a reason.
  EXPECT_NE(b.exchange(std::vector<std::uint8_t>(10, 0), records), ""); // held twice
  EXPECT_NE(b.exchange(std::vector<std::uint8_t>(9, 0), {}), "");
  records.pop_back();
  EXPECT_NE(b.exchange(std::vector<std::uint8_t>(10, 0), records), "");
}

TEST(Partition, PiecesReproduceTheSingleProcessRun)
{
  const bp::VectorField whole = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(33));
  const int steps = 60;
  const double dt = 0.02;
  // Along Flow: an element reset into another piece is turned there
  // (AlignPending), by the flow the single process samples.
  for (bp::Orientation orientation : { bp::Orientation::Random, bp::Orientation::AlongFlow })
  {
    SCOPED_TRACE(int(orientation));
    bp::Engine serial;
    ASSERT_EQ(
      serial.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), parameters(orientation)), "");
    serial.initialize(bp::serialRunner(), 0.0, &whole);
    for (int s = 0; s < steps; ++s)
      serial.step(whole, s * dt, dt, bp::serialRunner());
    expectPiecesReproduce(serial, whole, steps, dt, orientation);
  }
}

TEST(Partition, PiecesReproduceTheSingleProcessRunWithWalls)
{
  // The walls are the whole domain's sides (Engine::setDomain), not a
  // piece's: pieces split the field, and their elements stick, slide and
  // bounce as the single process's do.
  const bp::VectorField whole = bptest::steadyFlow(bp::AnalyticFlow::ABC, bptest::grid(33));
  const int steps = 60;
  const double dt = 0.02;
  for (bp::Boundary boundary : { bp::Boundary::Stick, bp::Boundary::Slip, bp::Boundary::Bounce })
  {
    SCOPED_TRACE(bp::enumName(boundary));
    bp::Engine serial;
    ASSERT_EQ(serial.configure(bp::builtinTemplate(bp::BuiltinShape::Cross),
                parameters(bp::Orientation::Random, boundary)),
      "");
    serial.initialize(bp::serialRunner(), 0.0, &whole);
    for (int s = 0; s < steps; ++s)
      serial.step(whole, s * dt, dt, bp::serialRunner());
    int onWall = 0;
    for (std::size_t q = 0; q < serial.positions().size(); q += 3)
      onWall += bp::onWall(whole.domain(), serial.positions().data() + q) ? 1 : 0;
    if (boundary != bp::Boundary::Bounce)
      EXPECT_GT(onWall, 20) << "the walls are met";
    expectPiecesReproduce(serial, whole, steps, dt, bp::Orientation::Random, boundary);
  }
}

TEST(Partition, PiecesReproduceTheSingleProcessRunAcrossAPeriodicSeam)
{
  // Periodic along x and y, split by the pieces into z slabs (as the tracer
  // splits such a field: bpvtk::pieceBlock) and, as where every axis is
  // periodic, along x and y themselves: each piece holds the whole of both
  // (the field across the seam, as the tracer asks for it), owns the
  // elements of its block, and an element moved by a period at the end of
  // a step (Engine::wrapPeriodic, on the whole field's domain) goes to its
  // new owner at the start of the next (migrate), where it has another.
  bp::GridGeometry g = bptest::grid(33);
  g.periodic = { true, true, false };
  const bp::VectorField whole = bptest::steadyFlow(bp::AnalyticFlow::ABC, g);
  ASSERT_TRUE(whole.domain().periodic[0] && whole.domain().periodic[1]);
  const int steps = 60;
  const double dt = 0.02;
  for (bp::Boundary boundary : { bp::Boundary::ReleaseAgain, bp::Boundary::Slip })
  {
    SCOPED_TRACE(bp::enumName(boundary));
    bp::Engine serial;
    ASSERT_EQ(serial.configure(bp::builtinTemplate(bp::BuiltinShape::Cross),
                parameters(bp::Orientation::Random, boundary, false)),
      "");
    serial.initialize(bp::serialRunner(), 0.0, &whole);
    // Elements cross the seams: a centre that jumps by more than half the
    // period (2) between two steps was moved by one.
    int jumps = 0;
    for (int s = 0; s < steps; ++s)
    {
      std::map<std::uint32_t, std::array<float, 3>> before;
      for (std::size_t e = 0; e < serial.elementCount(); ++e)
        before[serial.elementIds()[e]] = serial.centerOf(e);
      serial.step(whole, s * dt, dt, bp::serialRunner());
      for (std::size_t e = 0; e < serial.elementCount(); ++e)
      {
        const std::array<float, 3> c = serial.centerOf(e), b = before[serial.elementIds()[e]];
        jumps += std::abs(c[0] - b[0]) > 1.0f || std::abs(c[1] - b[1]) > 1.0f ? 1 : 0;
      }
    }
    EXPECT_GT(jumps, 100) << "elements cross the periodic seams"; // 313 when written
    for (std::size_t e = 0; e < serial.elementCount(); ++e)
      for (int a = 0; a < 2; ++a)
      {
        EXPECT_GE(serial.centerOf(e)[std::size_t(a)], -1.0f);
        EXPECT_LE(serial.centerOf(e)[std::size_t(a)], 1.0f);
      }
    for (bool slabs : { true, false })
    {
      SCOPED_TRACE(slabs ? "z slabs" : "x and y split");
      expectPiecesReproduce(serial, whole, steps, dt, bp::Orientation::Random, boundary, slabs);
    }
  }
}
