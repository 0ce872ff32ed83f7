// SPDX-License-Identifier: BSD-3-Clause
#include "Checkpoints.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bp
{

CheckpointSpacing checkpointSpacing(double budgetBytes, double stateBytes, long long stepsToEnd)
{
  CheckpointSpacing s;
  if (!(budgetBytes > 0.0) || !(stateBytes > 0.0) || stepsToEnd < 2)
  {
    return s;
  }
  const double fit = std::floor(budgetBytes / stateBytes);
  if (fit < 1.0)
  {
    return s;
  }
  // Copies at every, 2 every, ... below the end: at most `fit` of them, and
  // none closer than one step.
  const long long copies = std::min<long long>(
    std::min(fit, double(std::numeric_limits<int>::max())), stepsToEnd - 1);
  s.every = std::max<long long>(1, (stepsToEnd + copies) / (copies + 1));
  while ((stepsToEnd - 1) / s.every > copies)
  {
    ++s.every;
  }
  s.most = int((stepsToEnd - 1) / s.every);
  return s;
}

CheckpointIndex::Entry CheckpointIndex::latestAtOrBefore(double time, double epsilon) const
{
  Entry best;
  for (const auto& [steps, t] : this->Times)
  {
    if (t <= time + epsilon && (best.steps < 0 || t > best.time))
    {
      best.steps = steps;
      best.time = t;
    }
  }
  return best;
}

} // namespace bp
