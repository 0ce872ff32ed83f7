// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file PassTime.h
 * @brief One pass's GPU time (PassTimer.h), with no GL header.
 */
#ifndef BoundParticles_PassTime_h
#define BoundParticles_PassTime_h

#include <string>

namespace bp
{

/// One pass's GPU time over the runs timed.
struct PassTime
{
  std::string pass; ///< the pass's name (its kernel, "step (fused)" or "copy")
  long runs = 0;
  double seconds = 0.0;
};

} // namespace bp

#endif
