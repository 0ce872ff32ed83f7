// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file EngineChoice.h
 * @brief Which engine the tracer's Engine property (bp::EngineChoice, in
 * BoundParticlesChoices.h) comes to on a display's renderer.
 */
#ifndef BoundParticles_EngineChoice_h
#define BoundParticles_EngineChoice_h

#include "BoundParticlesChoices.h"
#include "RendererKind.h"

#include <string>

namespace bp
{

/// Whether a trace a display asked for runs on the GPU engine: always with
/// Gpu; with Automatic only on a hardware renderer (an unknown one, before
/// the display first drew, gets the CPU engine).
bool usesGpuEngine(EngineChoice choice, RendererKind renderer);

/// What a display says, once, when Engine Automatic traces on the CPU engine
/// because it draws with the software renderer `rendererName`.
std::string automaticOnCpuNote(const std::string& rendererName);

} // namespace bp

#endif
