// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleDefaults.h"

#include "pqBoundParticleIsTracer.h"
#include "pqBoundParticlePlayUpdates.h"
#include "pqBoundParticleTickGuard.h"

#include <QTimer>

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqOutputPort.h"
#include "pqPipelineFilter.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMParaViewPipelineControllerWithRendering.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyListDomain.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMViewProxy.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace
{
/// How far a 2D input's display moves behind the elements' plane, as a share
/// of its size: far enough for the depth buffer, too little to see.
constexpr double ContextBehind = 0.01;

/// No array named in Vectors: its default found no input arrays.
bool lacksVectors(vtkSMProxy* tracer)
{
  const char* name = vtkSMPropertyHelper(tracer, "Vectors").GetAsString(4);
  return !name || !*name;
}

/// Whether every element of `name` on `proxy` is still its XML default: what
/// the bounds domains (BoundParticleBoundsDomain) leave while the input has
/// no bounds.
bool atXmlDefault(vtkSMProxy* proxy, const char* name)
{
  vtkSMProperty* property = proxy->GetProperty(name);
  return property && property->IsValueDefault();
}

/// The emitter box as made before the input had bounds (Emitter Size -1: the
/// field, whenever the trace runs; the panel shows the bounds once known).
bool placeholderBox(vtkSMProxy* tracer)
{
  return atXmlDefault(tracer, "EmitterSize") && atXmlDefault(tracer, "EmitterCenter");
}

/// The Seed Type proxies (the SeedType property's list) whose bounds-based
/// properties are as made before the input had bounds.
std::vector<vtkSMProxy*> placeholderSeeds(vtkSMProxy* tracer)
{
  std::vector<vtkSMProxy*> placeholders;
  vtkSMProperty* seedType = tracer->GetProperty("SeedType");
  auto* list = seedType ? seedType->FindDomain<vtkSMProxyListDomain>() : nullptr;
  for (unsigned int i = 0; list && i < list->GetNumberOfProxies(); ++i)
  {
    vtkSMProxy* seeds = list->GetProxy(i);
    const char* name = seeds ? seeds->GetXMLName() : nullptr;
    const bool cloud = name && std::strcmp(name, "PointCloud") == 0 &&
      atXmlDefault(seeds, "Center") && atXmlDefault(seeds, "Radius");
    const bool line = name && std::strcmp(name, "Line") == 0 && atXmlDefault(seeds, "Point1") &&
      atXmlDefault(seeds, "Point2");
    if (cloud || line)
    {
      placeholders.push_back(seeds);
    }
  }
  return placeholders;
}

/// Whether `input` (the tracer's Input proxy) has no points yet: made before
/// it ran, the tracer's data-dependent properties hold placeholders.
bool hasNoDataYet(vtkSMProxy* tracer, vtkSMSourceProxy* input)
{
  const unsigned int port = vtkSMPropertyHelper(tracer, "Input").GetOutputPort();
  vtkPVDataInformation* info = input->GetDataInformation(port);
  return !info || info->GetNumberOfPoints() == 0;
}
} // namespace

pqBoundParticleDefaults::pqBoundParticleDefaults(QObject* parent)
  : QObject(parent)
{
}

void pqBoundParticleDefaults::onStartup()
{
  // Clicks queued during a slow frame must not start Play inside it. Once the
  // event loop runs: a plugin on PV_PLUGIN_PATH starts while the application
  // core is still being built, before it has its animation manager.
  // Play shows the frames, not panels that change 20 times a second: the
  // GUI's reaction to each frame's new data waits for the end of Play.
  QTimer::singleShot(0, this,
    [this]()
    {
      new pqBoundParticleTickGuard(this);
      new pqBoundParticlePlayUpdates(this);
    });
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::sourceAdded, this,
    [](pqPipelineSource* source) { pqBoundParticleDefaults::complete(source); });
  auto watchView = [this](pqView* view)
  {
    QObject::connect(view, &pqView::representationAdded, this,
      [](pqRepresentation* representation)
      { pqBoundParticleDefaults::shown(qobject_cast<pqDataRepresentation*>(representation)); });
  };
  for (pqView* view : model->findItems<pqView*>())
  {
    watchView(view);
  }
  QObject::connect(model, &pqServerManagerModel::viewAdded, this, watchView);
}

void pqBoundParticleDefaults::shown(pqDataRepresentation* representation)
{
  pqPipelineFilter* tracer =
    representation ? qobject_cast<pqPipelineFilter*>(representation->getInput()) : nullptr;
  pqView* view = representation ? representation->getView() : nullptr;
  // Only the Apply that first shows a tracer made in the GUI: a loaded state,
  // a Python script and a later Show keep the input's display as they set it.
  if (!tracer || !view || !pqBoundParticleIsTracer(tracer->getProxy()) ||
    tracer->modifiedState() != pqProxy::UNINITIALIZED)
  {
    return;
  }
  for (pqOutputPort* input : tracer->getInputs("Input"))
  {
    pqDataRepresentation* field = input ? input->getRepresentation(view) : nullptr;
    if (field && field->isVisible() && field->getProxy()->GetProperty("Representation"))
    {
      keepAsContext(input, field, view);
    }
  }
}

void pqBoundParticleDefaults::keepAsContext(
  pqOutputPort* input, pqDataRepresentation* field, pqView* view)
{
  vtkSMProxy* display = field->getProxy();
  vtkPVDataInformation* info = input->getDataInformation();
  double bounds[6];
  info->GetBounds(bounds);
  int flat = -1;
  double extent = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    const double span = bounds[2 * a + 1] - bounds[2 * a];
    flat = span == 0.0 ? a : flat;
    extent = std::max(extent, span);
  }
  if (flat < 0 || !(extent > 0.0))
  {
    // A 3D field: a display that would cover the elements (a surface, a
    // volume, a mesh's points) becomes its outline; an outline stays.
    const std::string type = vtkSMPropertyHelper(display, "Representation").GetAsString();
    auto* pv = vtkSMPVRepresentationProxy::SafeDownCast(display);
    if (type != "Outline" && type != "Feature Edges" && pv)
    {
      pv->SetRepresentationType("Outline");
      display->UpdateVTKObjects();
    }
    return;
  }
  // A 2D field (a slice, a flat surface: a map, say) lies in the elements'
  // plane: it stays, moved a hundredth of its size away from the camera
  // along its normal, so the elements draw in front of it.
  auto* renderView = vtkSMRenderViewProxy::SafeDownCast(view->getViewProxy());
  vtkCamera* camera = renderView ? renderView->GetActiveCamera() : nullptr;
  double direction[3] = { 0.0, 0.0, -1.0 };
  if (camera)
  {
    camera->GetDirectionOfProjection(direction);
  }
  // The display's offset: "Translation" from ParaView 5.13 on, "Position" before.
  vtkSMProperty* position = display->GetProperty("Translation");
  position = position ? position : display->GetProperty("Position");
  if (position)
  {
    vtkSMPropertyHelper helper(position);
    double moved[3] = { helper.GetAsDouble(0), helper.GetAsDouble(1), helper.GetAsDouble(2) };
    moved[flat] += (direction[flat] < 0.0 ? -1.0 : 1.0) * ContextBehind * extent;
    helper.Set(moved, 3);
    display->UpdateVTKObjects();
  }
}

void pqBoundParticleDefaults::complete(pqPipelineSource* source)
{
  vtkSMProxy* tracer = source ? source->getProxy() : nullptr;
  if (!pqBoundParticleIsTracer(tracer))
  {
    return;
  }
  auto* input = vtkSMSourceProxy::SafeDownCast(vtkSMPropertyHelper(tracer, "Input").GetAsProxy());
  if (!input || !hasNoDataYet(tracer, input))
  {
    return; // made after its input ran: its defaults came from the data
  }
  const bool vectors = lacksVectors(tracer), box = placeholderBox(tracer);
  const std::vector<vtkSMProxy*> seeds = placeholderSeeds(tracer);
  if (!vectors && !box && seeds.empty())
  {
    return;
  }
  // What making the tracer after an update would have seen.
  input->UpdatePipeline();
  // The domains that depend on the input (arrays, bounds) look at its data
  // again when the input property says it changed.
  tracer->GetProperty("Input")->InvokeEvent(vtkCommand::UncheckedPropertyModifiedEvent);
  if (vectors)
  {
    tracer->GetProperty("Vectors")->ResetToDomainDefaults();
  }
  // The Seed Types' Input is the tracer's (a proxy-list link); their bounds
  // domains look at its data again on the same event.
  for (vtkSMProxy* placeholder : seeds)
  {
    if (vtkSMProperty* seedInput = placeholder->GetProperty("Input"))
    {
      seedInput->InvokeEvent(vtkCommand::UncheckedPropertyModifiedEvent);
    }
    for (const char* name : { "Center", "Radius", "Point1", "Point2" })
    {
      if (vtkSMProperty* property = placeholder->GetProperty(name))
      {
        property->ResetToDomainDefaults();
      }
    }
    placeholder->UpdateVTKObjects();
  }
  if (box && !placeholderBox(tracer))
  {
    return; // someone set the box meanwhile
  }
  if (box)
  {
    tracer->GetProperty("EmitterCenter")->ResetToDomainDefaults();
    tracer->GetProperty("EmitterSize")->ResetToDomainDefaults();
  }
  tracer->UpdateVTKObjects();
}
