// SPDX-License-Identifier: BSD-3-Clause
// The order in which a super set's links are listed once (Core/Elements/SuperSetLinks.h):
// the CPU output's link cells and the display's link draw both follow it, so
// it must stay the order they had: element by element, +u before +v.
#include "SuperSet.h"
#include "SuperSetLinks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

Pairs listed(const bp::LinkTable& table)
{
  Pairs pairs;
  bp::forEachLink(table, [&](std::size_t e, std::size_t f) { pairs.emplace_back(e, f); });
  return pairs;
}

/// The order as each of the three places wrote it before it was shared.
Pairs expectedOrder(const bp::LinkTable& table)
{
  Pairs pairs;
  for (std::size_t e = 0; e < table.sites.size() / 3; ++e)
  {
    for (int d : { 0, 2 })
    {
      const std::int32_t f = table.neighbours[bp::LinkDirections * e + std::size_t(d)];
      if (f >= 0)
      {
        pairs.emplace_back(e, std::size_t(f));
      }
    }
  }
  return pairs;
}

/// Every link of the table, from both ends, as unordered pairs.
std::set<std::pair<std::size_t, std::size_t>> allLinks(const bp::LinkTable& table)
{
  std::set<std::pair<std::size_t, std::size_t>> links;
  for (std::size_t k = 0; k < table.neighbours.size(); ++k)
  {
    const std::int32_t f = table.neighbours[k];
    if (f >= 0)
    {
      const std::size_t e = k / bp::LinkDirections;
      links.emplace(std::min(e, std::size_t(f)), std::max(e, std::size_t(f)));
    }
  }
  return links;
}
} // namespace

TEST(SuperSetLinks, EachLinkOnceInElementOrderUBeforeV)
{
  const std::array<float, 3> lo = { 0, 0, 0 }, hi = { 4, 2, 1 };
  for (bp::Linking linking : { bp::Linking::Chain, bp::Linking::Ring, bp::Linking::Sheet,
         bp::Linking::Tube, bp::Linking::Torus })
  {
    for (std::size_t elements : { 1, 2, 3, 7, 12, 16, 30 })
    {
      const bp::LinkTable table = bp::makeLinkTable(linking, elements, 0, lo, hi);
      const Pairs pairs = listed(table);
      SCOPED_TRACE(std::string(bp::enumName(linking)) + " of " + std::to_string(elements));
      EXPECT_EQ(pairs, expectedOrder(table));
      EXPECT_EQ(pairs.size(), table.linkCount());
      std::set<std::pair<std::size_t, std::size_t>> once;
      for (const auto& p : pairs)
      {
        EXPECT_TRUE(once.emplace(std::min(p.first, p.second), std::max(p.first, p.second)).second)
          << p.first << "-" << p.second << " listed twice";
      }
      EXPECT_EQ(once, allLinks(table));
    }
  }
}

TEST(SuperSetLinks, ASheetListsItsRowLinkThenItsColumnLink)
{
  // A 2 x 2 sheet: 0-1 (+u of 0), 0-2 (+v of 0), 1-3 (+v of 1), 2-3 (+u of 2).
  const bp::LinkTable table = bp::makeLinkTable(bp::Linking::Sheet, 4, 2, { 0, 0, 0 }, { 1, 1, 1 });
  const Pairs expected = { { 0, 1 }, { 0, 2 }, { 1, 3 }, { 2, 3 } };
  EXPECT_EQ(listed(table), expected);
}

TEST(SuperSetLinks, NoneListsNothing)
{
  const bp::LinkTable table = bp::makeLinkTable(bp::Linking::None, 5, 0, { 0, 0, 0 }, { 1, 1, 1 });
  EXPECT_TRUE(listed(table).empty());
  EXPECT_EQ(table.linkCount(), 0u);
}
