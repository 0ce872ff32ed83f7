// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleTrailsDisplay.h"

#include "pqBoundParticleIsTracer.h"

#include <QTimer>

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkOutputWindow.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <string>

pqBoundParticleTrailsDisplay::pqBoundParticleTrailsDisplay(QObject* parent)
  : Superclass(parent)
{
}

void pqBoundParticleTrailsDisplay::onStartup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::sourceAdded, this,
    [this](pqPipelineSource* source) { this->watch(source); });
  QObject::connect(model, &pqServerManagerModel::representationRemoved, this,
    [this](pqRepresentation* r) { this->Seen.remove(qobject_cast<pqDataRepresentation*>(r)); });
}

void pqBoundParticleTrailsDisplay::watch(pqPipelineSource* source)
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
        }
      });
  };
  QObject::connect(source,
    static_cast<void (pqPipelineSource::*)(pqPipelineSource*)>(&pqPipelineSource::dataUpdated),
    this, later);
  QObject::connect(source, &pqPipelineSource::representationAdded, this, later);
}

void pqBoundParticleTrailsDisplay::check(pqPipelineSource* source)
{
  const bool trails = vtkSMPropertyHelper(source->getProxy(), "Trails").GetAsInt() != 0;
  for (pqDataRepresentation* display : source->getRepresentations(nullptr))
  {
    if (!trails)
    {
      this->Seen.remove(display);
      continue;
    }
    if (this->Seen.contains(display))
    {
      continue;
    }
    this->Seen.insert(display);
    vtkSMProxy* proxy = display->getProxy();
    if (!proxy->GetProperty("Representation") ||
      std::string(vtkSMPropertyHelper(proxy, "Representation").GetAsString()) != "Surface" ||
      !vtkSMPVRepresentationProxy::SafeDownCast(proxy) ||
      !vtkSMPVRepresentationProxy::SafeDownCast(proxy)->SetRepresentationType("Bound Particles"))
    {
      continue;
    }
    vtkOutputWindowDisplayText("Bound Particle Tracer: its trails fade with age on the Bound "
                               "Particles display, which now shows it. The Surface display draws "
                               "every past pose opaque (colour by Age and enable opacity mapping "
                               "to fade them there).\n");
    display->renderViewEventually();
  }
}
