// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleTickProbe
 * @brief Test only: a click on Play queued during a frame that is not
 * playback, delivered inside that frame's animation tick.
 *
 * A user's click made while a slow frame is computed waits in the window
 * system's queue; ParaView's VCR controller processes events inside the
 * tick, so the click starts Play there and ParaView aborts (`!InTick`),
 * unless pqBoundParticleTickGuard drops it. This probe makes that happen
 * on the first such tick, without timing: it posts the press and release
 * from inside the tick, before the controller processes events.
 */
#ifndef pqBoundParticleTickProbe_h
#define pqBoundParticleTickProbe_h

#include <QObject>

#include "vtkWeakPointer.h"

class vtkObject;

class pqBoundParticleTickProbe : public QObject
{
public:
  explicit pqBoundParticleTickProbe(QObject* parent = nullptr);
  ~pqBoundParticleTickProbe() override = default;

  void onStartup();
  void onShutdown() {}

private:
  void watchScene();
  void onTick();
  void startPlaying() { this->Playing = true; }
  void stopPlaying() { this->Playing = false; }

  vtkWeakPointer<vtkObject> Scene;
  bool Armed = true;
  bool Playing = false;
};

#endif
