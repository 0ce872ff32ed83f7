// SPDX-License-Identifier: BSD-3-Clause
#include "EngineChoice.h"

namespace bp
{

bool usesGpuEngine(EngineChoice choice, RendererKind renderer)
{
  return choice == EngineChoice::Gpu ||
    (choice == EngineChoice::Automatic && renderer == RendererKind::Hardware);
}

std::string automaticOnCpuNote(const std::string& rendererName)
{
  return "Bound Particle Tracer: Engine is Automatic and this render window draws with a "
         "software renderer (" +
    rendererName +
    "), on which the GPU engine is slower: the CPU engine traces. Set Engine to GPU to use the "
    "GPU engine anyway.";
}

} // namespace bp
