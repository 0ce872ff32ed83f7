// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file HeadlessContext.h
 * @brief An OpenGL core context with no window and no X, for tests and
 * benchmarks of the GPU engine. It enumerates the EGL devices
 * (EGL_EXT_device_enumeration) and takes a hardware one first, then Mesa's
 * surfaceless platform, then a software device (Mesa's llvmpipe);
 * BOUNDPARTICLES_EGL_DEVICE=N takes device N (as report() numbers them) and no
 * other. It asks for 4.3 (the engine's compute path), then 3.3 (its fragment
 * path); a driver may give a later version (Mesa's llvmpipe gives 4.5 to either).
 */
#ifndef BoundParticles_HeadlessContext_h
#define BoundParticles_HeadlessContext_h

#include <string>

namespace bp
{

class HeadlessContext
{
public:
  HeadlessContext() = default;
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  /// Creates the context and makes it current; empty on success.
  std::string create();
  /// GL_RENDERER and GL_VERSION of the current context.
  std::string description() const;
  /// Lines for a person: the EGL devices found (hardware or software), the
  /// display taken, and with a context GL's vendor, renderer and version and the
  /// limits that matter (compute workgroup size, invocations and shared memory,
  /// image units per stage). After create(), successful or not.
  std::string report() const;

private:
  void* Display = nullptr;
  void* Context = nullptr;
  std::string Devices; // one line per EGL device, from create()
  std::string Taken;   // the display create() took, or why none
};

} // namespace bp

#endif
