// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleTickProbe.h"

#include "pqAnimationManager.h"
#include "pqAnimationScene.h"
#include "pqCoreUtilities.h"
#include "pqPVApplicationCore.h"
#include "vtkCommand.h"
#include "vtkObject.h"
#include "vtkSMProxy.h"

#include <QAction>
#include <QCoreApplication>
#include <QMainWindow>
#include <QMouseEvent>
#include <QTimer>
#include <QToolBar>

#include <iostream>

pqBoundParticleTickProbe::pqBoundParticleTickProbe(QObject* parent)
  : QObject(parent)
{
}

void pqBoundParticleTickProbe::onStartup()
{
  // Once the application core is complete (as the guard does).
  QTimer::singleShot(0, this, [this]() { this->watchScene(); });
}

void pqBoundParticleTickProbe::watchScene()
{
  pqPVApplicationCore* core = pqPVApplicationCore::instance();
  pqAnimationScene* scene =
    core && core->animationManager() ? core->animationManager()->getActiveScene() : nullptr;
  this->Scene = vtkObject::SafeDownCast(
    scene && scene->getProxy() ? scene->getProxy()->GetClientSideObject() : nullptr);
  if (!this->Scene)
  {
    std::cerr << "TickProbe: no animation scene" << std::endl;
    return;
  }
  // After the guard's entry (1000), before pqAnimationScene's tick signal (0).
  this->Scene->AddObserver(
    vtkCommand::AnimationCueTickEvent, this, &pqBoundParticleTickProbe::onTick, 500.0f);
  this->Scene->AddObserver(vtkCommand::StartEvent, this, &pqBoundParticleTickProbe::startPlaying);
  this->Scene->AddObserver(vtkCommand::EndEvent, this, &pqBoundParticleTickProbe::stopPlaying);
}

void pqBoundParticleTickProbe::onTick()
{
  if (!this->Armed || this->Playing)
  {
    return;
  }
  auto* window = qobject_cast<QMainWindow*>(pqCoreUtilities::mainWidget());
  auto* bar = window ? window->findChild<QToolBar*>("VCRToolbar") : nullptr;
  auto* play = bar ? bar->findChild<QAction*>("actionVCRPlay") : nullptr;
  QWidget* button = play ? bar->widgetForAction(play) : nullptr;
  if (!button)
  {
    std::cerr << "TickProbe: no Play button" << std::endl;
    return;
  }
  this->Armed = false;
  const QPointF centre = QRectF(button->rect()).center();
  QCoreApplication::postEvent(button, new QMouseEvent(QEvent::MouseButtonPress, centre,
                                        Qt::LeftButton, Qt::LeftButton, Qt::NoModifier));
  QCoreApplication::postEvent(button, new QMouseEvent(QEvent::MouseButtonRelease, centre,
                                        Qt::LeftButton, Qt::NoButton, Qt::NoModifier));
  std::cerr << "TickProbe: clicked Play inside a tick" << std::endl;
}
