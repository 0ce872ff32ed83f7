// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleDisplays
 * @brief Keeps a tracer's displays in step with its settings: the display
 * that draws its trails or its GPU engine, and colour ranges that follow a
 * change of Vectors.
 *
 * Two settings of the tracer are drawn by the Bound Particles display only:
 *  - Trails: ParaView's Surface display draws every trail pose opaque (in
 *    ParaView 5.11 a surface's colours take their opacity only from the
 *    colour map of the array they show, so a pose cannot fade by its age
 *    while the elements are coloured by Speed); the Bound Particles display
 *    fades them, on both engines;
 *  - Engine = GPU: the GPU engine runs in the Bound Particles display's
 *    render; a Surface display asks for the elements as data, which the CPU
 *    engine steps (the user saw the CPU picture, and nothing said why).
 * When either is applied, each of the tracer's Surface displays becomes a
 * Bound Particles display, once, with a line in Output Messages saying so;
 * a display the user turns back to Surface meanwhile is left as it is.
 *
 * When the tracer's Vectors change (at Apply: ACCL to VEL on an Exodus
 * result, say), every array it outputs changes its scale, while ParaView's
 * colour maps only grow on Apply (the elements stayed one blue under ACCL's
 * range up to 1.8e7): each of its coloured displays' colour maps is rescaled
 * to the data's range once the new trace is shown.
 */
#ifndef pqBoundParticleDisplays_h
#define pqBoundParticleDisplays_h

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QString>

class pqDataRepresentation;
class pqPipelineSource;

class pqBoundParticleDisplays : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqBoundParticleDisplays(QObject* parent = nullptr);
  ~pqBoundParticleDisplays() override = default;

  void onStartup();
  void onShutdown() {}

private:
  /// Follows a new source's updates and displays if it is a tracer.
  void watch(pqPipelineSource* source);
  /// After an update or a new display (once ParaView has set it up).
  void check(pqPipelineSource* source);
  /// After an update: the colour maps rescaled when the Vectors changed.
  void rescaleIfVectorsChanged(pqPipelineSource* source);

  /// The displays already seen with the trails on, or with Engine = GPU
  /// (cleared when that setting goes off).
  QSet<pqDataRepresentation*> SeenTrails;
  QSet<pqDataRepresentation*> SeenGpu;
  /// Each tracer's Vectors as last seen (array name), to tell a change.
  QHash<pqPipelineSource*, QString> Vectors;

  Q_DISABLE_COPY(pqBoundParticleDisplays)
};

#endif
