// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file RendererKind.h
 * @brief Which kind of OpenGL renderer a GL_RENDERER string names.
 */
#ifndef BoundParticles_RendererKind_h
#define BoundParticles_RendererKind_h

#include <string>

namespace bp
{

/// The kind of OpenGL renderer a display draws with.
enum class RendererKind
{
  Unknown,
  Hardware,
  Software
};

/// The kind of renderer a GL_RENDERER string names: Software for Mesa's
/// llvmpipe, softpipe and swrast, and other CPU rasterizers.
RendererKind rendererKind(const std::string& glRenderer);

} // namespace bp

#endif
