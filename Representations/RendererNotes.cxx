// SPDX-License-Identifier: BSD-3-Clause
#include "RendererNotes.h"

#include "EngineChoice.h"
#include "WorkQueue.h"

#include "vtkOutputWindow.h"
#include "vtkPVRenderView.h"
#include "vtkRenderWindow.h"

#include <string>

namespace bpvtk
{

void recordRenderer(vtkPVRenderView* view, bp::RendererReportWriter& writer)
{
  vtkRenderWindow* window = view ? view->GetRenderWindow() : nullptr;
  bp::RendererReport& report = writer.report();
  if (report.renderer != bp::RendererKind::Unknown || !window || window->GetNeverRendered())
  {
    return;
  }
  const char* capabilities = window->ReportCapabilities();
  const std::string text = capabilities ? capabilities : "";
  const std::string key = "OpenGL renderer string:";
  const std::size_t at = text.find(key);
  if (at == std::string::npos)
  {
    return;
  }
  const std::size_t first = text.find_first_not_of(" \t", at + key.size());
  const std::size_t end = text.find('\n', at);
  report.rendererName = first < end ? text.substr(first, end - first) : std::string();
  report.renderer = bp::rendererKind(report.rendererName);
}

void sayAutomaticOnCpu(bool automaticOnCpu, const bp::WorkQueue& queue, bool& said)
{
  const bp::RendererReport& report = queue.report();
  if (!automaticOnCpu || said || report.renderer != bp::RendererKind::Software)
  {
    return;
  }
  said = true;
  const std::string text = bp::automaticOnCpuNote(report.rendererName) + "\n";
  vtkOutputWindowDisplayText(text.c_str());
}

} // namespace bpvtk
