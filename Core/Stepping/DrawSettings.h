// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DrawSettings.h
 * @brief What a renderer needs to draw the state a WorkQueue leads to: the
 * tracer sets it (WorkQueue::setDraw), the renderer reads it.
 */
#ifndef BoundParticles_DrawSettings_h
#define BoundParticles_DrawSettings_h

#include <array>
#include <cstdint>

namespace bp
{

/// What a renderer needs to draw the state the queue leads to.
struct DrawSettings
{
  double time = 0.0;                          ///< the simulation time shown
  std::array<double, 3> offset = { 0, 0, 0 }; ///< world position of the grid-local origin
  std::array<double, 6> bounds = { 0, -1, 0, -1, 0, -1 }; ///< the field's world bounds
  int coloringAxis = 2;                                   ///< for Layer and Radius
  std::array<double, 2> radialCenter = { 0, 0 };          ///< grid-local, the other two axes
  std::uint64_t serial = 0; ///< changes with every update of the filter
  /// A backward trace: `time` and the engine's state are the trace's own
  /// (TimeDirection.h); Velocity and ElementSpin are drawn per the data's
  /// time (negated back), as the CPU output writes them.
  bool backward = false;
};

} // namespace bp

#endif
