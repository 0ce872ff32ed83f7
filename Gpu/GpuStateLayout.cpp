// SPDX-License-Identifier: BSD-3-Clause
// The kernels' declarations of the per-element state (GpuStateLayout.h).
#include "GpuStateLayout.h"

namespace bp
{

std::string elementStateDeclarations(bool images)
{
  std::string out;
  for (int row = 0; row < ElementTextureCount; ++row)
  {
    const std::string sampler = ElementTextureSamplers[row];
    out += "uniform sampler2D " + sampler + ";\n";
    if (images)
    {
      out += "layout(rgba32f, binding = " + std::to_string(1 + row) +
        ") uniform writeonly image2D " + sampler + "Out;\n";
    }
  }
  return out;
}

} // namespace bp
