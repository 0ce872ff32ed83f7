// SPDX-License-Identifier: BSD-3-Clause
// The field sampled at the particles, for the output arrays (SampleAtPositions.h).
#include "SampleAtPositions.h"

namespace bp
{

void sampleAtPositions(const VectorField& field, double t, const float* positions,
  std::size_t count, float* velocity, float* vorticity, const RangeRunner& run)
{
  const float weight = field.timeWeight(t);
  run(count,
    [&](std::size_t begin, std::size_t end)
    {
      // Elements lie in memory in no spatial order, so each new one's cells
      // are likely out of cache: ask for them a few particles ahead.
      constexpr std::size_t Ahead = 24;
      for (std::size_t i = begin; i < end; ++i)
      {
        if (i + Ahead < end)
        {
          field.prefetch(positions + 3 * (i + Ahead));
        }
        if (vorticity)
        {
          vorticity[i] = field.sampleWithVorticity(positions + 3 * i, weight, velocity + 3 * i);
        }
        else
        {
          field.sampleWeighted(positions + 3 * i, weight, velocity + 3 * i);
        }
      }
    });
}

} // namespace bp
