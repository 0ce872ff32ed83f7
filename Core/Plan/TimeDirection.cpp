// SPDX-License-Identifier: BSD-3-Clause
#include "TimeDirection.h"

#include <memory>

namespace bp
{

std::vector<double> traceTimes(TimeDirection direction, const std::vector<double>& times)
{
  if (direction != TimeDirection::Backward)
  {
    return times;
  }
  std::vector<double> mirrored(times.rbegin(), times.rend());
  for (double& t : mirrored)
  {
    t = -t;
  }
  return mirrored;
}

FieldSlice traceSlice(TimeDirection direction, const FieldSlice& slice)
{
  if (direction != TimeDirection::Backward)
  {
    return slice;
  }
  FieldSlice reversed = slice;
  reversed.time = -slice.time;
  if (slice.velocity)
  {
    auto negated = std::make_shared<std::vector<float>>(*slice.velocity);
    for (float& v : *negated)
    {
      v = -v;
    }
    reversed.velocity = negated;
  }
  return reversed;
}

std::array<double, 2> traceWindow(TimeDirection direction, double start, double stop)
{
  if (direction != TimeDirection::Backward)
  {
    return { start, stop };
  }
  return { -stop, -start };
}

std::string checkTimeDirection(TimeDirection direction, const Parameters& engine)
{
  if (direction == TimeDirection::Backward && engine.inertia != Inertia::None)
  {
    return "Time Direction = Backward traces massless elements only: heavy particles "
           "(Inertia = Maxey-Riley) lag the flow by a drag that damps their slip forward in "
           "time and amplifies it backward, so their earlier positions are not defined by the "
           "later ones. Set Inertia to None, or Time Direction to Forward.";
  }
  return std::string();
}

} // namespace bp
