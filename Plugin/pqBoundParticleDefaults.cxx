// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleDefaults.h"

#include "ColourRange.h"
#include "pqBoundParticleIsTracer.h"
#include "pqBoundParticlePlayUpdates.h"
#include "pqBoundParticleTickGuard.h"

#include <QPointer>
#include <QTimer>

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqOutputPort.h"
#include "pqPipelineFilter.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMParaViewPipelineControllerWithRendering.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyListDomain.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMTransferFunctionManager.h"
#include "vtkSMTransferFunctionProxy.h"
#include "vtkSMViewProxy.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
/// How far a 2D input's display moves behind the elements' plane, as a share
/// of its size: far enough for the depth buffer, too little to see.
constexpr double ContextBehind = 0.01;

/// A colour map's AutomaticRescaleRangeMode values: ParaView's default
/// ("Grow and update on 'Apply'") and Never (what the colour map editor's
/// "Rescale and disable automatic rescaling" sets).
constexpr int GrowOnApply = 0;
constexpr int NeverRescale = -1;

/// Bins of the histogram a colour range is read from.
constexpr int ColourBins = 4096;

/// The greys, low to high, of a 2D context's own colour map: dimmer than
/// the elements' colours, lighter than a dark background.
constexpr double ContextGreys[2] = { 0.2, 0.6 };

/// The colour maps whose range readableColours() set.
std::vector<vtkWeakPointer<vtkSMProxy>>& heldRanges()
{
  static std::vector<vtkWeakPointer<vtkSMProxy>> held;
  return held;
}

bool holdsRange(vtkSMProxy* lut)
{
  auto& held = heldRanges();
  held.erase(std::remove_if(held.begin(), held.end(),
               [](const vtkWeakPointer<vtkSMProxy>& p) { return p == nullptr; }),
    held.end());
  return std::find(held.begin(), held.end(), lut) != held.end();
}

/// A histogram of the single-component `array` of `source`'s output `port`
/// at `time`: `ColourBins` equal bins over `range`, counted where the data is
/// (ParaView's Histogram filter, its tables merged over the ranks and moved
/// to the client, as the colour map editor's histogram). Empty on failure.
std::vector<double> histogramOf(vtkSMSourceProxy* source, unsigned int port, int association,
  const char* array, const double range[2], double time)
{
  vtkSMSessionProxyManager* pxm = source->GetSessionProxyManager();
  auto make = [pxm](const char* name)
  {
    vtkSmartPointer<vtkSMSourceProxy> proxy;
    proxy.TakeReference(vtkSMSourceProxy::SafeDownCast(pxm->NewProxy("filters", name)));
    return proxy;
  };
  vtkSmartPointer<vtkSMSourceProxy> histogram = make("ExtractHistogram");
  vtkSmartPointer<vtkSMSourceProxy> reducer = make("ReductionFilter");
  vtkSmartPointer<vtkSMSourceProxy> mover = make("ClientServerMoveData");
  if (!histogram || !reducer || !mover)
  {
    return {};
  }
  vtkSMPropertyHelper(histogram, "Input").Set(source, port);
  vtkSMPropertyHelper(histogram, "SelectInputArray").SetInputArrayToProcess(association, array);
  vtkSMPropertyHelper(histogram, "Component").Set(0);
  vtkSMPropertyHelper(histogram, "BinCount").Set(ColourBins);
  vtkSMPropertyHelper(histogram, "UseCustomBinRanges").Set(1);
  vtkSMPropertyHelper(histogram, "CustomBinRanges").Set(range, 2);
  histogram->UpdateVTKObjects();
  vtkSMPropertyHelper(reducer, "Input").Set(histogram);
  vtkSMPropertyHelper(reducer, "PostGatherHelperName").Set("vtkPVMergeTables");
  reducer->UpdateVTKObjects();
  vtkSMPropertyHelper(mover, "Input").Set(reducer);
  vtkSMPropertyHelper(mover, "OutputDataType").Set(VTK_TABLE);
  mover->UpdateVTKObjects();
  mover->UpdatePipeline(time);
  auto* algorithm = vtkAlgorithm::SafeDownCast(mover->GetClientSideObject());
  vtkTable* table = algorithm ? vtkTable::SafeDownCast(algorithm->GetOutputDataObject(0)) : nullptr;
  vtkDataArray* values =
    table ? vtkDataArray::SafeDownCast(table->GetColumnByName("bin_values")) : nullptr;
  // One table of ColourBins rows, or one a rank, merged one after another.
  std::vector<double> counts(ColourBins, 0.0);
  const vtkIdType rows = values ? values->GetNumberOfTuples() : 0;
  if (rows == 0 || rows % ColourBins != 0)
  {
    return {};
  }
  for (vtkIdType row = 0; row < rows; ++row)
  {
    counts[static_cast<std::size_t>(row % ColourBins)] += values->GetTuple1(row);
  }
  return counts;
}

/// Gives a scalar-coloured 2D context `display` a colour map of its own in
/// greys (its own values still shown), so the elements' colours stand out;
/// where the colour map it used had its legend shown in `view`, the legend
/// shows the greys instead (the other goes when nothing else uses it).
void showAsContext(vtkSMProxy* display, vtkSMProxy* view)
{
  auto* pv = vtkSMPVRepresentationProxy::SafeDownCast(display);
  if (!pv || !pv->GetUsingScalarColoring() || !display->GetProperty("UseSeparateColorMap"))
  {
    return; // a solid colour (or none) takes no colour map from the elements
  }
  vtkSMPropertyHelper colour(display, "ColorArrayName");
  const int association = colour.GetInputArrayAssociation();
  const std::string name = colour.GetInputArrayNameToProcess();
  vtkSMProxy* shared = vtkSMPropertyHelper(display, "LookupTable", true).GetAsProxy();
  const bool legend =
    view && shared && vtkSMTransferFunctionProxy::IsScalarBarVisible(shared, view);
  // What the display's "Use Separate Color Map" button does.
  vtkSMPropertyHelper(display, "UseSeparateColorMap").Set(1);
  display->UpdateVTKObjects();
  pv->SetScalarColoring(name.c_str(), association);
  pv->RescaleTransferFunctionToDataRange(/*extend=*/false, /*force=*/true);
  vtkSMProxy* lut = vtkSMPropertyHelper(display, "LookupTable", true).GetAsProxy();
  vtkSMProperty* points = lut ? lut->GetProperty("RGBPoints") : nullptr;
  if (!points)
  {
    return;
  }
  vtkSMPropertyHelper helper(points);
  const unsigned int count = helper.GetNumberOfElements();
  if (count < 8)
  {
    return;
  }
  const double low = helper.GetAsDouble(0), high = helper.GetAsDouble(count - 4);
  const double g0 = ContextGreys[0], g1 = ContextGreys[1];
  const double greys[8] = { low, g0, g0, g0, high, g1, g1, g1 };
  helper.Set(greys, 8);
  vtkSMPropertyHelper(lut, "ColorSpace").Set("RGB");
  lut->UpdateVTKObjects();
  display->UpdateVTKObjects();
  if (legend)
  {
    vtkNew<vtkSMTransferFunctionManager> manager;
    manager->UpdateScalarBars(view, vtkSMTransferFunctionManager::HIDE_UNUSED_SCALAR_BARS);
    pv->SetScalarBarVisibility(view, true);
  }
}

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
  // Once Apply is done (it sets the display's colouring and grows its colour
  // map to the data range after announcing the display).
  QPointer<pqDataRepresentation> guarded(representation);
  QTimer::singleShot(0, [guarded]() { pqBoundParticleDefaults::readableColours(guarded, false); });
}

bool pqBoundParticleDefaults::readableColours(pqDataRepresentation* display, bool onlyHeld)
{
  auto* pv = display ? vtkSMPVRepresentationProxy::SafeDownCast(display->getProxy()) : nullptr;
  vtkSMProxy* lut = pv && display->isVisible() && pv->GetUsingScalarColoring()
    ? vtkSMPropertyHelper(pv, "LookupTable", true).GetAsProxy()
    : nullptr;
  vtkSMProperty* mode = lut ? lut->GetProperty("AutomaticRescaleRangeMode") : nullptr;
  auto* input =
    pv ? vtkSMSourceProxy::SafeDownCast(vtkSMPropertyHelper(pv, "Input").GetAsProxy()) : nullptr;
  if (!mode || !input)
  {
    return false;
  }
  // ParaView's default mode, or a range set here before and not changed
  // since: the user's own colour map settings stay.
  const int rescale = vtkSMPropertyHelper(mode).GetAsInt();
  const bool held = holdsRange(lut);
  if (onlyHeld ? !(held && rescale == NeverRescale)
               : !(rescale == GrowOnApply || (held && rescale == NeverRescale)))
  {
    return false;
  }
  vtkPVArrayInformation* info = pv->GetArrayInformationForColorArray(false);
  double full[2] = { 0.0, 0.0 };
  if (info && info->GetNumberOfComponents() == 1)
  {
    info->GetComponentRange(0, full);
  }
  if (!(full[1] > full[0]))
  {
    return false; // a vector's colours, or one value: nothing to spread
  }
  vtkSMPropertyHelper colour(pv, "ColorArrayName");
  const std::string array = colour.GetInputArrayNameToProcess();
  pqView* view = display->getView();
  vtkSMProxy* viewProxy = view ? view->getViewProxy() : nullptr;
  const double time = viewProxy && viewProxy->GetProperty("ViewTime")
    ? vtkSMPropertyHelper(viewProxy, "ViewTime").GetAsDouble()
    : 0.0;
  const std::vector<double> counts =
    histogramOf(input, vtkSMPropertyHelper(pv, "Input").GetOutputPort(),
      colour.GetInputArrayAssociation(), array.c_str(), full, time);
  const bp::ColourScale scale = bp::colourScale(counts, { full[0], full[1] });
  const bp::Range& range = scale.range;
  if (!(range[0] > full[0] || range[1] < full[1]))
  {
    return false;
  }
  // As the colour map editor's log scale check box: control points spread
  // over the logarithm, then the range.
  vtkSMProperty* logScale = lut->GetProperty("UseLogScale");
  const bool wasLog = logScale && vtkSMPropertyHelper(logScale).GetAsInt() != 0;
  if (logScale && wasLog != scale.logarithmic)
  {
    vtkSMTransferFunctionProxy::RescaleTransferFunction(lut, range[0], range[1], false);
    auto* function = vtkSMTransferFunctionProxy::SafeDownCast(lut);
    if (function)
    {
      function->MapControlPointsToLogSpace(/*inverse=*/!scale.logarithmic);
    }
    vtkSMPropertyHelper(logScale).Set(scale.logarithmic ? 1 : 0);
    lut->UpdateVTKObjects();
  }
  vtkSMTransferFunctionProxy::RescaleTransferFunction(lut, range[0], range[1], false);
  if (vtkSMProxy* opacity = vtkSMPropertyHelper(lut, "ScalarOpacityFunction", true).GetAsProxy())
  {
    vtkSMTransferFunctionProxy::RescaleTransferFunction(opacity, range[0], range[1], false);
  }
  vtkSMPropertyHelper(mode).Set(NeverRescale);
  lut->UpdateVTKObjects();
  if (!held)
  {
    heldRanges().emplace_back(lut);
  }
  char text[512];
  std::snprintf(text, sizeof(text),
    "Bound Particle Tracer: the colours of '%s' span the middle %g%% of its values, %g to %g "
    "(all: %g to %g)%s, so that a few fast elements do not leave the others one colour; "
    "automatic rescaling is off for it (Rescale to Data Range shows the extremes).\n",
    array.c_str(), 100.0 * (1.0 - 2.0 * bp::ColourRangeTail), range[0], range[1], full[0], full[1],
    scale.logarithmic ? ", on a log scale (half the values lie in its lowest quarter)" : "");
  vtkOutputWindowDisplayText(text);
  display->renderViewEventually();
  return true;
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
  // along its normal, so the elements draw in front of it, and coloured by
  // its array in greys, so the elements' colours stand out on it.
  showAsContext(display, view->getViewProxy());
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
