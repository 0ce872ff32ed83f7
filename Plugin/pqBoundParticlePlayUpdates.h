// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticlePlayUpdates
 * @brief Holds back the GUI's reaction to new data in a Bound Particle
 * Tracer's pipeline while the animation plays, and lets it happen once when
 * Play stops.
 *
 * Every frame of Play gives the tracer, its input and their displays new
 * data, and each of their proxies fires vtkCommand::UpdateDataEvent. The
 * ParaView GUI answers each one within the frame: the Information panel
 * gathers the data information again (even while its tab is hidden, and
 * for the tracer also when only its input fired), the Filters menu
 * re-evaluates every filter and reloads its icons, the properties panel and
 * the colour widgets refresh their array lists. With the tracer's defaults
 * that was about a third of a frame on this project's machine
 * (docs/performance.md, "GUI Play"), for panels nobody can read at 20
 * frames a second.
 *
 * While the active animation scene plays, this autostart object observes,
 * ahead of the GUI's own observers, the proxies of every tracer, of every
 * source upstream of one, and of their displays, and aborts the event, so
 * that the GUI does not see it. What the frame shows is unchanged: the data
 * information is still marked out of date (vtkSMSourceProxy does that before
 * firing the event) and the scene's tick still rescales the colour maps.
 * When Play stops, each proxy whose event was held back fires it once, so
 * the panels show the last frame's data. Single steps (Next Frame, First
 * Frame, a time typed in) are not playback and are left alone, and so is
 * pvpython, which has no GUI. Created by the plugin's autostart
 * (pqBoundParticleDefaults).
 */
#ifndef pqBoundParticlePlayUpdates_h
#define pqBoundParticlePlayUpdates_h

#include <QObject>

#include "vtkWeakPointer.h"

#include <vector>

class pqAnimationScene;
class vtkObject;
class vtkSMProxy;

class pqBoundParticlePlayUpdates : public QObject
{
public:
  explicit pqBoundParticlePlayUpdates(QObject* parent);
  ~pqBoundParticlePlayUpdates() override;

private:
  /// Observes `scene`'s start and end of playback (and no other scene's).
  void watch(pqAnimationScene* scene);
  /// Play started: observe the tracers' pipelines.
  void startPlaying();
  /// Play stopped: stop observing, and fire what was held back.
  void stopPlaying();
  /// The observer on a held proxy: true aborts the event.
  bool holdBack(vtkObject* caller, unsigned long event, void* data);

  struct Held
  {
    vtkWeakPointer<vtkSMProxy> Proxy;
    unsigned long Tag = 0;
    bool Missed = false; ///< an event was held back
  };

  vtkWeakPointer<vtkObject> Scene;
  std::vector<unsigned long> SceneTags;
  std::vector<Held> Proxies; ///< upstream before downstream
  bool Playing = false;
};

#endif
