// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleDisplays.h"

#include "pqBoundParticleDefaults.h"
#include "pqBoundParticleIsTracer.h"
#include "vtkBoundParticleTracer.h"

#include <QTimer>

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqPipelineRepresentation.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkOutputWindow.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <string>

pqBoundParticleDisplays::pqBoundParticleDisplays(QObject* parent)
  : Superclass(parent)
{
}

void pqBoundParticleDisplays::onStartup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::sourceAdded, this,
    [this](pqPipelineSource* source) { this->watch(source); });
  QObject::connect(model, &pqServerManagerModel::sourceRemoved, this,
    [this](pqPipelineSource* source)
    {
      if (this->Vectors.remove(source) > 0)
      {
        // A tracer went: once ParaView has let go of it and of its displays
        // (their copies of its output go after it), the memory goes back.
        QTimer::singleShot(0, [] { vtkBoundParticleTracer::ReturnFreedMemory(); });
      }
    });
  // Reset Session and a disconnect remove the whole session at once (not
  // always through sourceRemoved): once it is gone, so is its memory.
  QObject::connect(model, &pqServerManagerModel::finishedRemovingServer, this,
    [this]()
    {
      this->Vectors.clear();
      this->SeenTrails.clear();
      this->SeenGpu.clear();
      QTimer::singleShot(0, [] { vtkBoundParticleTracer::ReturnFreedMemory(); });
    });
  QObject::connect(model, &pqServerManagerModel::representationRemoved, this,
    [this](pqRepresentation* r)
    {
      this->SeenTrails.remove(qobject_cast<pqDataRepresentation*>(r));
      this->SeenGpu.remove(qobject_cast<pqDataRepresentation*>(r));
    });
}

void pqBoundParticleDisplays::watch(pqPipelineSource* source)
{
  if (!source || !pqBoundParticleIsTracer(source->getProxy()))
  {
    return;
  }
  // Deferred: a new display gets its type after it is announced, and an
  // update is announced before Apply shows the output.
  QPointer<pqPipelineSource> guarded(source);
  auto later = [this, guarded]()
  {
    QTimer::singleShot(0, this,
      [this, guarded]()
      {
        if (guarded)
        {
          this->check(guarded);
          this->rescaleIfVectorsChanged(guarded);
        }
      });
  };
  QObject::connect(source,
    static_cast<void (pqPipelineSource::*)(pqPipelineSource*)>(&pqPipelineSource::dataUpdated),
    this, later);
  QObject::connect(source, &pqPipelineSource::representationAdded, this, later);
}

namespace
{
/// The tracer's Engine property's value for GPU (Plugin/BoundParticles.xml).
constexpr int GpuEngine = 1;

/// Turns `display` from Surface to Bound Particles; false where it is not a
/// Surface display (the user's own choice stays).
bool moveToBoundParticles(pqDataRepresentation* display)
{
  vtkSMProxy* proxy = display->getProxy();
  auto* representation = vtkSMPVRepresentationProxy::SafeDownCast(proxy);
  return proxy->GetProperty("Representation") && representation &&
    std::string(vtkSMPropertyHelper(proxy, "Representation").GetAsString()) == "Surface" &&
    representation->SetRepresentationType("Bound Particles");
}
} // namespace

void pqBoundParticleDisplays::check(pqPipelineSource* source)
{
  vtkSMProxy* tracer = source->getProxy();
  const bool trails = vtkSMPropertyHelper(tracer, "Trails").GetAsInt() != 0;
  const bool gpu = vtkSMPropertyHelper(tracer, "Engine").GetAsInt() == GpuEngine;
  for (pqDataRepresentation* display : source->getRepresentations(nullptr))
  {
    // Each reason once per display, while it holds.
    const bool newTrails = trails && !this->SeenTrails.contains(display);
    const bool newGpu = gpu && !this->SeenGpu.contains(display);
    trails ? (void)this->SeenTrails.insert(display) : (void)this->SeenTrails.remove(display);
    gpu ? (void)this->SeenGpu.insert(display) : (void)this->SeenGpu.remove(display);
    if ((!newTrails && !newGpu) || !moveToBoundParticles(display))
    {
      continue;
    }
    if (newGpu)
    {
      vtkOutputWindowDisplayText("Bound Particle Tracer: Engine is GPU, which runs in the Bound "
                                 "Particles display, which now shows it. A Surface display shows "
                                 "the CPU engine's trace.\n");
    }
    if (newTrails)
    {
      vtkOutputWindowDisplayText("Bound Particle Tracer: its trails fade with age on the Bound "
                                 "Particles display, which now shows it. The Surface display "
                                 "draws every past pose opaque (colour by Age and enable opacity "
                                 "mapping to fade them there).\n");
    }
    display->renderViewEventually();
  }
}

void pqBoundParticleDisplays::rescaleIfVectorsChanged(pqPipelineSource* source)
{
  const char* name = vtkSMPropertyHelper(source->getProxy(), "Vectors").GetAsString(4);
  const QString now = name ? QString(name) : QString();
  const auto last = this->Vectors.find(source);
  const bool changed = last != this->Vectors.end() && last.value() != now;
  this->Vectors.insert(source, now);
  if (!changed)
  {
    return;
  }
  for (pqDataRepresentation* display : source->getRepresentations(nullptr))
  {
    // A colour map whose range the first Apply set to the middle of the
    // values (and nobody changed since) gets the new trace's; any other, what
    // the GUI's "Rescale to Data Range" does (nothing for a solid colour, nor
    // where the user locked the range); that reaction's header is not
    // installed by Debian's ParaView 5.13 and 6.1.
    auto* shown = qobject_cast<pqPipelineRepresentation*>(display);
    auto* proxy = shown ? vtkSMPVRepresentationProxy::SafeDownCast(shown->getProxy()) : nullptr;
    if (proxy && shown->isVisible() &&
      (pqBoundParticleDefaults::readableColours(shown, /*onlyHeld=*/true) ||
        proxy->RescaleTransferFunctionToDataRange(/*extend=*/false, /*force=*/false)))
    {
      shown->renderViewEventually();
    }
  }
}
