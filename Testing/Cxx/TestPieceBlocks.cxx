// SPDX-License-Identifier: BSD-3-Clause
// The blocks a distributed run splits the field into (Filters/TracerParallel.h,
// bpvtk::pieceBlock): with periodic axes, the processes split the others, so
// that each holds whole periodic axes over a part of the rest, not the whole
// field; the blocks a process owns and asks for (PieceLayout::setWholeExtent,
// blockWithGhosts) agree on every process.
#include "TracerParallel.h"

#include "vtkDummyController.h"
#include "vtkExtentTranslator.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Extent = std::array<int, 6>;
using Axes = std::array<bool, 3>;

std::string text(const Extent& e)
{
  std::ostringstream out;
  out << "[" << e[0] << "," << e[1] << "]x[" << e[2] << "," << e[3] << "]x[" << e[4] << "," << e[5]
      << "]";
  return out.str();
}

/// Every piece's block of `whole` (pieceBlock); fails where a piece has none.
std::vector<Extent> blocks(const Extent& whole, int pieces, const Axes& periodic)
{
  std::vector<Extent> out(static_cast<std::size_t>(pieces));
  for (int p = 0; p < pieces; ++p)
  {
    EXPECT_TRUE(bpvtk::pieceBlock(p, pieces, whole.data(), periodic, out[std::size_t(p)].data()))
      << "piece " << p << " of " << pieces << " of " << text(whole);
  }
  return out;
}

/// vtkExtentTranslator's block split of `whole` (the executive's).
Extent translated(const Extent& whole, int piece, int pieces)
{
  vtkNew<vtkExtentTranslator> translator;
  Extent block{};
  Extent copy = whole;
  EXPECT_TRUE(translator->PieceToExtentThreadSafe(
    piece, pieces, 0, copy.data(), block.data(), vtkExtentTranslator::BLOCK_MODE, 0));
  return block;
}

/// The blocks' cells along `axis` cover the whole axis once: sorted by their
/// start, each begins where the last ended (blocks that span the same range
/// of `axis` count once).
void expectTiles(const std::vector<Extent>& pieces, const Extent& whole, int axis)
{
  std::vector<std::pair<int, int>> ranges;
  for (const Extent& b : pieces)
  {
    ranges.emplace_back(b[2 * axis], b[2 * axis + 1]);
  }
  std::sort(ranges.begin(), ranges.end());
  ranges.erase(std::unique(ranges.begin(), ranges.end()), ranges.end());
  int at = whole[2 * axis];
  for (const auto& r : ranges)
  {
    EXPECT_EQ(r.first, at) << "axis " << axis;
    EXPECT_GT(r.second, r.first) << "axis " << axis;
    at = r.second;
  }
  EXPECT_EQ(at, whole[2 * axis + 1]) << "axis " << axis;
}

/// Each block spans the whole of each periodic axis and a part (not the
/// whole) of `split`, and the blocks tile `split`.
void expectSplitAlong(const Extent& whole, const Axes& periodic, int split, int pieces)
{
  const auto all = blocks(whole, pieces, periodic);
  for (int p = 0; p < pieces; ++p)
  {
    const Extent& b = all[std::size_t(p)];
    std::cout << "  " << text(whole) << " periodic " << periodic[0] << periodic[1] << periodic[2]
              << ", piece " << p << " of " << pieces << ": " << text(b) << "\n";
    for (int a = 0; a < 3; ++a)
    {
      if (periodic[std::size_t(a)])
      {
        EXPECT_EQ(b[2 * a], whole[2 * a]) << "piece " << p << " axis " << a;
        EXPECT_EQ(b[2 * a + 1], whole[2 * a + 1]) << "piece " << p << " axis " << a;
      }
    }
    EXPECT_TRUE(b[2 * split] > whole[2 * split] || b[2 * split + 1] < whole[2 * split + 1])
      << "piece " << p << " of " << pieces << " holds the whole non-periodic axis " << split << ": "
      << text(b);
  }
  expectTiles(all, whole, split);
}
} // namespace

TEST(PieceBlocks, PeriodicAxesAreWholeAndTheOthersSplit)
{
  // The review's fields: periodic in x and y, only z left to split; a
  // channel periodic along x and z, only y left to split.
  for (int pieces : { 2, 4 })
  {
    expectSplitAlong({ 0, 20, 0, 10, 0, 4 }, { true, true, false }, 2, pieces);
    expectSplitAlong({ -10, 10, -5, 5, -2, 2 }, { true, true, false }, 2, pieces);
    expectSplitAlong({ -10, 10, -5, 5, -12, 12 }, { true, true, false }, 2, pieces);
    expectSplitAlong({ 0, 127, 0, 63, 0, 95 }, { true, false, true }, 1, pieces);
  }
  // Two axes left: both split at 4 pieces where the translator splits so.
  const Extent box{ 0, 40, 0, 30, 0, 30 };
  const auto four = blocks(box, 4, { true, false, false });
  for (const Extent& b : four)
  {
    EXPECT_EQ(b[0], 0);
    EXPECT_EQ(b[1], 40);
  }
  expectTiles(four, box, 1);
  expectTiles(four, box, 2);
}

TEST(PieceBlocks, WithoutPeriodicAxesTheExecutivesSplit)
{
  for (const Extent& whole : { Extent{ 0, 20, 0, 10, 0, 4 }, Extent{ 0, 127, 0, 63, 0, 95 } })
  {
    for (int pieces : { 2, 3, 4 })
    {
      const auto all = blocks(whole, pieces, { false, false, false });
      for (int p = 0; p < pieces; ++p)
      {
        EXPECT_EQ(all[std::size_t(p)], translated(whole, p, pieces)) << text(whole);
      }
    }
  }
}

TEST(PieceBlocks, EveryAxisPeriodicOrTooFewCellsFallsBackToTheWholeSplit)
{
  // Every axis periodic: nothing else to split, the block split of the whole
  // extent (every process then reads the whole field).
  const Extent cube{ 0, 20, 0, 10, 0, 4 };
  for (int pieces : { 2, 4 })
  {
    const auto all = blocks(cube, pieces, { true, true, true });
    for (int p = 0; p < pieces; ++p)
    {
      EXPECT_EQ(all[std::size_t(p)], translated(cube, p, pieces));
    }
  }
  // One cell along z, the one axis not periodic: too few for 4 pieces.
  const Extent thin{ 0, 20, 0, 10, 0, 1 };
  const auto all = blocks(thin, 4, { true, true, false });
  for (int p = 0; p < 4; ++p)
  {
    EXPECT_EQ(all[std::size_t(p)], translated(thin, p, 4));
  }
  // A flat 2-D field periodic in x and y: the same.
  const Extent flat{ 0, 20, 0, 10, 0, 0 };
  const auto two = blocks(flat, 2, { true, true, false });
  for (int p = 0; p < 2; ++p)
  {
    EXPECT_EQ(two[std::size_t(p)], translated(flat, p, 2));
  }
}

TEST(PieceBlocks, OwnedBlocksAndRequestedExtentsAgree)
{
  // What each process owns (setWholeExtent, the partition's box) lies inside
  // what it asks for (blockWithGhosts) by GhostCells layers, the whole axis
  // along a periodic one; each is the same on every process.
  vtkNew<vtkDummyController> controller;
  const Extent whole{ 0, 20, 0, 10, 0, 16 }; // z long enough for blocks with ghosts
  for (int pieces : { 2, 4 })
  {
    for (int p = 0; p < pieces; ++p)
    {
      bpvtk::PieceLayout layout;
      layout.Controller = controller;
      layout.Pieces = pieces;
      layout.Piece = p;
      layout.Periodic = { true, true, false };
      layout.setWholeExtent(whole.data());
      Extent owned;
      std::copy(layout.OwnedExtent, layout.OwnedExtent + 6, owned.begin());
      Extent expected;
      ASSERT_TRUE(bpvtk::pieceBlock(p, pieces, whole.data(), layout.Periodic, expected.data()));
      EXPECT_EQ(owned, expected);
      Extent asked;
      ASSERT_TRUE(layout.blockWithGhosts(p, asked.data()));
      for (int a = 0; a < 3; ++a)
      {
        const bool periodic = layout.Periodic[std::size_t(a)];
        EXPECT_EQ(asked[2 * a],
          periodic ? whole[2 * a] : std::max(owned[2 * a] - layout.GhostCells, whole[2 * a]));
        EXPECT_EQ(asked[2 * a + 1],
          periodic ? whole[2 * a + 1]
                   : std::min(owned[2 * a + 1] + layout.GhostCells, whole[2 * a + 1]));
      }
      // A part of z, with its ghost layers, not the whole field.
      EXPECT_TRUE(asked[4] > whole[4] || asked[5] < whole[5])
        << "piece " << p << " of " << pieces << " asks for " << text(asked);
      layout.Controller = nullptr; // not owned
    }
  }
}
