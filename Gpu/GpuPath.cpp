// SPDX-License-Identifier: BSD-3-Clause
#include "GpuPath.h"

#include "WorkQueue.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>

namespace bp
{
namespace
{
void toStandardError(const std::string& text, bool warning)
{
  std::fprintf(stderr, "%s%s\n", warning ? "Warning: " : "", text.c_str());
}

std::mutex Said;
GpuMessageSink Sink = toStandardError;
std::set<std::string> SaidAlready;

/// "4.5" from a version number.
std::string versionText(int version)
{
  return std::to_string(version / 10) + "." + std::to_string(version % 10);
}
} // namespace

const char* gpuPathName(GpuPath path)
{
  return path == GpuPath::Compute ? "compute" : "fragment";
}

GpuPathChoice chooseGpuPath(int version, const std::string& context, const char* requested)
{
  const std::string asked = requested ? requested : "";
  const bool computeAvailable = version >= ComputePathVersion;
  GpuPathChoice choice;
  std::string why = "chosen automatically";
  if (asked == "fragment")
  {
    why = std::string("as ") + GpuPathVariable + " asks";
  }
  else if (asked == "compute" && computeAvailable)
  {
    why = std::string("as ") + GpuPathVariable + " asks";
    choice.path = GpuPath::Compute;
  }
  else
  {
    if (asked == "compute")
    {
      choice.warning = std::string(GpuPathVariable) +
        "=compute asks for the GPU engine's compute path, but this OpenGL context is version " +
        versionText(version) + " and compute shaders need 4.3: the engine runs its fragment path.";
    }
    else if (!asked.empty() && asked != "automatic")
    {
      choice.warning = std::string(GpuPathVariable) + "=" + asked +
        " is not one of compute, fragment or automatic: the GPU engine chooses its path itself.";
    }
    choice.path = computeAvailable ? GpuPath::Compute : GpuPath::Fragment;
    if (!computeAvailable)
    {
      why += " (compute shaders need OpenGL 4.3)";
    }
  }
  choice.note = std::string("BoundParticles GPU engine: the ") + gpuPathName(choice.path) +
    " path, " + why + ", on OpenGL " + context + ".";
  return choice;
}

bool fusesSteps(FusedSteps choice, const std::string& renderer, const char* requested)
{
  const std::string asked = requested ? requested : "";
  if (choice == FusedSteps::Automatic && (asked == "on" || asked == "off"))
  {
    return asked == "on";
  }
  return choice == FusedSteps::Always ||
    (choice == FusedSteps::Automatic && rendererKind(renderer) != RendererKind::Software);
}

GpuPathChoice currentGpuPath()
{
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return chooseGpuPath(epoxy_gl_version(), version ? version : "?", std::getenv(GpuPathVariable));
}

void setGpuMessageSink(GpuMessageSink sink)
{
  const std::lock_guard<std::mutex> lock(Said);
  Sink = sink ? sink : toStandardError;
}

void sayGpuPathOnce(const GpuPathChoice& choice)
{
  const std::lock_guard<std::mutex> lock(Said);
  if (!SaidAlready.insert(choice.warning + "\n" + choice.note).second)
  {
    return;
  }
  if (!choice.warning.empty())
  {
    Sink(choice.warning, true);
  }
  Sink(choice.note, false);
}

} // namespace bp
