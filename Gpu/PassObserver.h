// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file PassObserver.h
 * @brief What the GPU engine tells about its passes while it runs them: a
 * call before and after every pass and copy, and the memory each moves, for
 * whoever wants to time or count them (the tests' and benchmarks' PassTimer,
 * Gpu/Support/PassTimer.h; the benchmarks' PassTraffic, Gpu/Support/PassTraffic.h).
 * No GL header: a renderer's code includes GpuEngine.h beside its own GL loader.
 */
#ifndef BoundParticles_PassObserver_h
#define BoundParticles_PassObserver_h

#include <cstddef>
#include <string>

namespace bp
{

/// Told about every pass and copy the engine runs (GpuEngine::setPassObserver),
/// with the GL context current: begin() before the pass's GL calls, end()
/// after them. Calls never nest.
struct PassObserver
{
  virtual ~PassObserver() = default;
  /// A pass begins: `name` is its kernel's, "step (fused)" or "copy".
  virtual void begin(const std::string& name) = 0;
  /// The pass begun last moves at least `bytesRead` and `bytesWritten`: the
  /// whole of every 2D texture it binds (the state, and small tables such as
  /// the seed points or a rectilinear grid's axes), read once, and of every
  /// target or image it stores into, written once (its compulsory traffic; a
  /// texel fetched again comes from cache). The field's samples (3D textures)
  /// are not counted. Told between begin() and end().
  virtual void traffic(std::size_t bytesRead, std::size_t bytesWritten)
  {
    (void)bytesRead;
    (void)bytesWritten;
  }
  /// The pass begun last has issued its GL calls.
  virtual void end() = 0;
};

} // namespace bp

#endif
