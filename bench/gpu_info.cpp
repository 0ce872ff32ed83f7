// SPDX-License-Identifier: BSD-3-Clause
// The GPU a headless context gets: the EGL devices it could choose from, the
// one it took, OpenGL's vendor, renderer and version, and the limits the
// engine's paths depend on (issue 55). The bundle's real_gpu.sh runs it first
// and refuses a software renderer before any minute is spent.
//
//   BoundParticlesGpuInfo        exit 0 with a context, 1 without one
#include "HeadlessContext.h"

#include <cstdio>

int main()
{
  bp::HeadlessContext context;
  const std::string error = context.create();
  std::printf("%s", context.report().c_str());
  if (!error.empty())
  {
    std::printf("context: none: %s\n", error.c_str());
    return 1;
  }
  return 0;
}
