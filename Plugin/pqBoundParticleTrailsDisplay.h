// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleTrailsDisplay
 * @brief Shows a tracer's trails on the display that fades them.
 *
 * ParaView's Surface display draws every trail pose opaque: in ParaView 5.11
 * a surface's colours take their opacity only from the colour map of the
 * array they show, so a pose cannot fade by its age while the elements are
 * coloured by Speed. The Bound Particles display fades them, on both
 * engines. When a tracer's Trails are switched on (at Apply), each of its
 * Surface displays becomes a Bound Particles display, once, with a line in
 * Output Messages saying so; a display the user turns back to Surface while
 * the trails stay on is left as it is.
 */
#ifndef pqBoundParticleTrailsDisplay_h
#define pqBoundParticleTrailsDisplay_h

#include <QObject>
#include <QPointer>
#include <QSet>

class pqDataRepresentation;
class pqPipelineSource;

class pqBoundParticleTrailsDisplay : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqBoundParticleTrailsDisplay(QObject* parent = nullptr);
  ~pqBoundParticleTrailsDisplay() override = default;

  void onStartup();
  void onShutdown() {}

private:
  /// Follows a new source's updates and displays if it is a tracer.
  void watch(pqPipelineSource* source);
  /// After an update or a new display (once ParaView has set it up).
  void check(pqPipelineSource* source);

  /// The displays already seen with the trails on (cleared when they go off).
  QSet<pqDataRepresentation*> Seen;

  Q_DISABLE_COPY(pqBoundParticleTrailsDisplay)
};

#endif
