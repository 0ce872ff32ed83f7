// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleTickGuard
 * @brief Keeps clicks queued during a slow animation frame from starting
 * Play inside that frame, which aborts ParaView.
 *
 * ParaView's VCR controller answers every animation tick with a nested
 * QApplication::processEvents() (pqVCRController::onTick), run while
 * vtkSMAnimationScene is still inside its Tick. A Play (or Reverse) clicked
 * while the frame was being computed is then delivered there, ticks again,
 * and fails ParaView's assertion `!this->InTick`: the session is lost. A slow
 * trace makes such clicks likely (issue 29: First Frame, then Play, while an
 * update ran). ParaView's own Particle Tracer hits it the same way.
 *
 * This guard drops user input (mouse, keys, shortcuts, wheel, touch) that
 * arrives inside a tick of the active scene that is not part of playback,
 * as ParaView itself drops input while it shows progress. Ticks during
 * Play are left alone: Pause must still reach the player, and a second Play
 * there is refused by the player itself. Created by the plugin's autostart.
 */
#ifndef pqBoundParticleTickGuard_h
#define pqBoundParticleTickGuard_h

#include <QObject>
#include <QPointer>

#include "vtkWeakPointer.h"

#include <vector>

class pqAnimationScene;
class vtkObject;

class pqBoundParticleTickGuard : public QObject
{
public:
  explicit pqBoundParticleTickGuard(QObject* parent);
  ~pqBoundParticleTickGuard() override;

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  /// Observes `scene`'s ticks (and no other scene's).
  void watch(pqAnimationScene* scene);
  void enterTick() { ++this->TickDepth; }
  void leaveTick() { this->TickDepth = this->TickDepth > 0 ? this->TickDepth - 1 : 0; }
  void startPlaying() { this->Playing = true; }
  void stopPlaying() { this->Playing = false; }

  vtkWeakPointer<vtkObject> Scene;
  std::vector<unsigned long> Tags;
  int TickDepth = 0;
  bool Playing = false;
};

#endif
