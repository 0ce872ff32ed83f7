// SPDX-License-Identifier: BSD-3-Clause
#include "GpuPath.h"

#include "RendererKind.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <atomic>
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

std::string acceptedValue(const char* variable, const char* value,
  const std::vector<std::string>& accepted, const std::string& otherwise, std::string& warning)
{
  const std::string given = value ? value : "";
  if (given.empty() || std::find(accepted.begin(), accepted.end(), given) != accepted.end())
  {
    return given;
  }
  std::string names;
  for (std::size_t k = 0; k < accepted.size(); ++k)
  {
    names += (k == 0 ? "" : k + 1 == accepted.size() ? " or " : ", ") + accepted[k];
  }
  warning = std::string(variable) + "=" + given + " is not one of " + names + ": " + otherwise;
  return std::string();
}

const char* gpuPathName(GpuPath path)
{
  return path == GpuPath::Compute ? "compute" : "fragment";
}

GpuPathChoice chooseGpuPath(int version, const std::string& context, const char* requested)
{
  GpuPathChoice choice;
  const std::string asked =
    acceptedValue(GpuPathVariable, requested, { "compute", "fragment", "automatic" },
      "the GPU engine chooses its path itself.", choice.warning);
  const bool computeAvailable = version >= ComputePathVersion;
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

bool fusesSteps(
  FusedSteps choice, const std::string& renderer, const char* requested, std::string* warning)
{
  std::string unknown;
  const std::string asked =
    acceptedValue(FusedStepVariable, requested, { "on", "off", "automatic" },
      "the compute path fuses a system's step on a GPU and runs a dispatch per kernel on a "
      "software renderer.",
      unknown);
  if (warning)
  {
    *warning = unknown;
  }
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

int fusedGroupValue(const char* value)
{
  if (!value || !*value)
    return 0;
  char* end = nullptr;
  const long n = std::strtol(value, &end, 10);
  return *end == '\0' && n >= 1 && n <= 1024 ? int(n) : 0;
}

namespace
{
std::atomic<bool> ComputeFails{ false };
}

void setComputeCompileFailureForTesting(bool on)
{
  ComputeFails = on;
}

bool computeCompileFailureForTesting()
{
  return ComputeFails;
}

void fallBackToFragmentPath(
  GpuPathChoice& choice, const std::string& error, const std::string& context)
{
  // One line: the program and the compiler's first messages.
  std::string why;
  for (char c : error)
    why += c == '\n' ? ' ' : c;
  while (why.find("  ") != std::string::npos)
    why.replace(why.find("  "), 2, " ");
  if (why.size() > 400)
    why = why.substr(0, 400) + "...";
  choice.path = GpuPath::Fragment;
  choice.warning += (choice.warning.empty() ? "" : "\n") +
    std::string("The GPU engine's compute path could not be built on this driver (") + why +
    "): the engine runs its fragment path, which runs the same kernels.";
  choice.note = "BoundParticles GPU engine: the fragment path, since the compute path's "
                "programs did not build, on OpenGL " +
    context + ".";
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
  std::size_t from = 0;
  while (from < choice.warning.size())
  {
    const std::size_t end = std::min(choice.warning.find('\n', from), choice.warning.size());
    Sink(choice.warning.substr(from, end - from), true);
    from = end + 1;
  }
  Sink(choice.note, false);
}

} // namespace bp
