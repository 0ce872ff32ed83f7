// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file HeadlessContext.h
 * @brief An OpenGL core context with no window and no X: EGL on Mesa's
 * surfaceless platform, or on an EGL device (NVIDIA), for tests and benchmarks
 * of the GPU engine. It asks for 4.3 (the engine's compute path), then 3.3
 * (its fragment path); a driver may give a later version (Mesa's llvmpipe
 * gives 4.5 to either).
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

private:
  void* Display = nullptr;
  void* Context = nullptr;
};

} // namespace bp

#endif
