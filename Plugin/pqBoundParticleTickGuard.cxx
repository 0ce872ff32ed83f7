// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleTickGuard.h"

#include "pqBoundParticleActiveScene.h"

#include "pqAnimationScene.h"
#include "vtkCommand.h"
#include "vtkObject.h"
#include "vtkSMProxy.h"

#include <QCoreApplication>
#include <QEvent>

pqBoundParticleTickGuard::pqBoundParticleTickGuard(QObject* parent)
  : QObject(parent)
{
  if (pqBoundParticleFollowActiveScene(
        this, [this](pqAnimationScene* scene) { this->watch(scene); }))
  {
    QCoreApplication::instance()->installEventFilter(this);
  }
}

pqBoundParticleTickGuard::~pqBoundParticleTickGuard()
{
  if (QCoreApplication::instance())
  {
    QCoreApplication::instance()->removeEventFilter(this);
  }
  this->watch(nullptr);
}

void pqBoundParticleTickGuard::watch(pqAnimationScene* scene)
{
  if (this->Scene)
  {
    for (unsigned long tag : this->Tags)
    {
      this->Scene->RemoveObserver(tag);
    }
  }
  this->Tags.clear();
  this->TickDepth = 0;
  this->Playing = false;
  this->Scene = vtkObject::SafeDownCast(
    scene && scene->getProxy() ? scene->getProxy()->GetClientSideObject() : nullptr);
  if (!this->Scene)
  {
    return;
  }
  // Around pqAnimationScene's own observer (priority 0), whose tick signal
  // reaches pqVCRController::onTick and its processEvents().
  vtkObject* s = this->Scene;
  this->Tags = { s->AddObserver(vtkCommand::AnimationCueTickEvent, this,
                   &pqBoundParticleTickGuard::enterTick, 1000.0f),
    s->AddObserver(
      vtkCommand::AnimationCueTickEvent, this, &pqBoundParticleTickGuard::leaveTick, -1000.0f),
    // The scene forwards its player's start and end of playback.
    s->AddObserver(vtkCommand::StartEvent, this, &pqBoundParticleTickGuard::startPlaying),
    s->AddObserver(vtkCommand::EndEvent, this, &pqBoundParticleTickGuard::stopPlaying) };
}

bool pqBoundParticleTickGuard::eventFilter(QObject* watched, QEvent* event)
{
  if (this->TickDepth > 0 && !this->Playing)
  {
    switch (event->type())
    {
      case QEvent::MouseButtonPress:
      case QEvent::MouseButtonRelease:
      case QEvent::MouseButtonDblClick:
      case QEvent::KeyPress:
      case QEvent::KeyRelease:
      case QEvent::Shortcut:
      case QEvent::ShortcutOverride:
      case QEvent::Wheel:
      case QEvent::ContextMenu:
      case QEvent::TouchBegin:
      case QEvent::TouchUpdate:
      case QEvent::TouchEnd:
        return true;
      default:
        break;
    }
  }
  return QObject::eventFilter(watched, event);
}
