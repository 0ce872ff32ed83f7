// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticlePlayUpdates.h"

#include "pqBoundParticleActiveScene.h"
#include "pqBoundParticleIsTracer.h"

#include "pqAnimationScene.h"
#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqOutputPort.h"
#include "pqPipelineFilter.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "vtkCommand.h"
#include "vtkObject.h"
#include "vtkSMProxy.h"

#include <algorithm>

namespace
{
/// Appends `source`'s proxy and its displays' to `proxies`, after those of
/// every source upstream of it, each once.
void collectPipeline(pqPipelineSource* source, std::vector<vtkSMProxy*>& proxies)
{
  if (!source || !source->getProxy() ||
    std::find(proxies.begin(), proxies.end(), source->getProxy()) != proxies.end())
  {
    return;
  }
  if (auto* filter = qobject_cast<pqPipelineFilter*>(source))
  {
    for (pqOutputPort* input : filter->getAllInputs())
    {
      collectPipeline(input ? input->getSource() : nullptr, proxies);
    }
  }
  proxies.push_back(source->getProxy());
  for (pqDataRepresentation* display : source->getRepresentations(nullptr))
  {
    if (display && display->getProxy())
    {
      proxies.push_back(display->getProxy());
    }
  }
}
} // namespace

pqBoundParticlePlayUpdates::pqBoundParticlePlayUpdates(QObject* parent)
  : QObject(parent)
{
  pqBoundParticleFollowActiveScene(this, [this](pqAnimationScene* scene) { this->watch(scene); });
}

pqBoundParticlePlayUpdates::~pqBoundParticlePlayUpdates()
{
  this->watch(nullptr);
}

void pqBoundParticlePlayUpdates::watch(pqAnimationScene* scene)
{
  // A scene that goes away while it plays must not leave the panels stale.
  this->stopPlaying();
  if (this->Scene)
  {
    for (unsigned long tag : this->SceneTags)
    {
      this->Scene->RemoveObserver(tag);
    }
  }
  this->SceneTags.clear();
  this->Scene = vtkObject::SafeDownCast(
    scene && scene->getProxy() ? scene->getProxy()->GetClientSideObject() : nullptr);
  if (!this->Scene)
  {
    return;
  }
  // vtkSMAnimationScene forwards its player's start and end of playback; a
  // single step fires neither.
  vtkObject* s = this->Scene;
  this->SceneTags = { s->AddObserver(
                        vtkCommand::StartEvent, this, &pqBoundParticlePlayUpdates::startPlaying),
    s->AddObserver(vtkCommand::EndEvent, this, &pqBoundParticlePlayUpdates::stopPlaying) };
}

void pqBoundParticlePlayUpdates::startPlaying()
{
  if (this->Playing)
  {
    return;
  }
  this->Playing = true;
  std::vector<vtkSMProxy*> proxies;
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    if (pqBoundParticleIsTracer(source->getProxy()))
    {
      // Its input too: the GUI answers an input's new data as well (the
      // tracer's Information panel was gathered again for it every frame).
      collectPipeline(source, proxies);
    }
  }
  for (vtkSMProxy* proxy : proxies)
  {
    // Ahead of the GUI's observers (pqPipelineSource's, pqDataRepresentation's
    // and the colour array domain's, all at priority 0), so that aborting the
    // event keeps it from them.
    Held held;
    held.Proxy = proxy;
    held.Tag = proxy->AddObserver(
      vtkCommand::UpdateDataEvent, this, &pqBoundParticlePlayUpdates::holdBack, 1000.0f);
    this->Proxies.push_back(held);
  }
}

void pqBoundParticlePlayUpdates::stopPlaying()
{
  if (!this->Playing)
  {
    return;
  }
  this->Playing = false;
  std::vector<Held> proxies;
  proxies.swap(this->Proxies);
  for (const Held& held : proxies)
  {
    if (held.Proxy)
    {
      held.Proxy->RemoveObserver(held.Tag);
    }
  }
  // What the GUI would have heard at the last frame, upstream first, as the
  // pipeline fires it: the panels show the data of the frame now shown.
  for (const Held& held : proxies)
  {
    if (held.Proxy && held.Missed)
    {
      held.Proxy->InvokeEvent(vtkCommand::UpdateDataEvent, nullptr);
    }
  }
}

bool pqBoundParticlePlayUpdates::holdBack(vtkObject* caller, unsigned long, void*)
{
  for (Held& held : this->Proxies)
  {
    if (held.Proxy == caller)
    {
      held.Missed = true;
      return true;
    }
  }
  return false;
}
