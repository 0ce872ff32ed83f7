// SPDX-License-Identifier: BSD-3-Clause
#include "ReplayHooks.h"

#include "vtkAlgorithm.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOutputWindow.h"
#include "vtkPVVersion.h"
// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <utility>

namespace bpvtk
{

bool replayReportsProgress()
{
#if PARAVIEW_VERSION_NUMBER >= PARAVIEW_VERSION_CHECK(6, 1, 0)
  return false;
#else
  return true;
#endif
}

bp::ReplayProgress::Hooks replayHooks(
  vtkAlgorithm* owner, vtkOpenGLRenderWindow* window, std::function<bool()> stop)
{
  bp::ReplayProgress::Hooks hooks;
  // Finished before an abort is asked too, so a stop comes when the work does.
  hooks.settle = [] { glFinish(); };
  hooks.stop = std::move(stop);
  if (replayReportsProgress())
  {
    hooks.report = [owner](double share)
    {
      owner->SetProgressText("Bound Particles: GPU engine");
      owner->UpdateProgress(share);
    };
    hooks.resume = [window] { window->MakeCurrent(); };
  }
  return hooks;
}

void sayInOutputWindow(const std::string& text, bool warning)
{
  const std::string line = text + "\n";
  if (warning)
  {
    vtkOutputWindowDisplayWarningText(line.c_str());
  }
  else
  {
    vtkOutputWindowDisplayText(line.c_str());
  }
}

} // namespace bpvtk
