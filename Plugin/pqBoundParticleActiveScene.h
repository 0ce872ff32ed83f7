// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pqBoundParticleActiveScene.h
 * @brief Follows the GUI's active animation scene (for the tick guard and
 * the Play updates, which both watch the scene that plays).
 */
#ifndef pqBoundParticleActiveScene_h
#define pqBoundParticleActiveScene_h

#include "pqAnimationManager.h"
#include "pqAnimationScene.h"
#include "pqPVApplicationCore.h"

#include <QObject>

/// Calls `watch(scene)` with the active scene now and whenever another
/// becomes active, for as long as `receiver` lives; false (and no call)
/// where the application has no animation manager yet.
template <typename Watch>
bool pqBoundParticleFollowActiveScene(QObject* receiver, Watch watch)
{
  pqPVApplicationCore* core = pqPVApplicationCore::instance();
  pqAnimationManager* manager = core ? core->animationManager() : nullptr;
  if (!manager)
  {
    return false;
  }
  QObject::connect(manager, &pqAnimationManager::activeSceneChanged, receiver, watch);
  watch(manager->getActiveScene());
  return true;
}

#endif
