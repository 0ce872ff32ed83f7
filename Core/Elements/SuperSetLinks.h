// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SuperSetLinks.h
 * @brief The one order in which a super set's links are listed, each once.
 *
 * A LinkTable lists every link from both of its elements (+u and -u, +v and
 * -v). Whatever lists each link once — the table's link count, the CPU
 * output's link cells (Filters/TracerOutput.cxx) and the display's link draw
 * (Representations/DrawTables.cxx) — walks it here, so that the GPU draw's
 * instance k is the CPU output's link cell k: for each element e in
 * increasing order, its link along +u, then its link along +v.
 */
#ifndef BoundParticles_SuperSetLinks_h
#define BoundParticles_SuperSetLinks_h

#include "SuperSet.h"

#include <cstddef>
#include <cstdint>

namespace bp
{

/**
 * Calls `visit(e, f)` once per link of `table`, from element e to its
 * neighbour f along +u and then along +v, e increasing. A template so that
 * the CPU output's per-particle loop inside `visit` stays inlined.
 */
template <typename Visit>
void forEachLink(const LinkTable& table, Visit&& visit)
{
  const std::size_t elements = table.neighbours.size() / LinkDirections;
  for (std::size_t e = 0; e < elements; ++e)
  {
    for (int d : { 0, 2 }) // +u and +v: the -u and -v entries are the same links seen from f
    {
      const std::int32_t f = table.neighbours[LinkDirections * e + std::size_t(d)];
      if (f >= 0)
      {
        visit(e, std::size_t(f));
      }
    }
  }
}

} // namespace bp

#endif
