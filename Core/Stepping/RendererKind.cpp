// SPDX-License-Identifier: BSD-3-Clause
#include "RendererKind.h"

#include <algorithm>
#include <cctype>

namespace bp
{

RendererKind rendererKind(const std::string& glRenderer)
{
  std::string name(glRenderer.size(), ' ');
  std::transform(glRenderer.begin(), glRenderer.end(), name.begin(),
    [](unsigned char c) { return char(std::tolower(c)); });
  if (name.empty())
  {
    return RendererKind::Unknown;
  }
  for (const char* software :
    { "llvmpipe", "softpipe", "swrast", "software rasterizer", "swiftshader", "lavapipe" })
  {
    if (name.find(software) != std::string::npos)
    {
      return RendererKind::Software;
    }
  }
  return RendererKind::Hardware;
}

} // namespace bp
