// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleDefaults
 * @brief Completes the defaults of a Bound Particle Tracer made before its
 * input had data (from the Python shell).
 *
 * ParaView picks a filter's data-dependent defaults (the Vectors array, the
 * emitter box from the input's bounds) when the filter is made. From the
 * Python shell that is usually before the input has run: the bounds domains
 * (BoundParticleBoundsDomain) then leave the XML's defaults (an Emitter Size
 * of -1 -1 -1, which spans the field when the trace runs; the Point Cloud's
 * and Line's placeholders), and Vectors finds no array. This autostart
 * watches the tracers that get registered; one made before its input had
 * data and still holding those defaults has its input updated and those
 * properties set from its data, as if it had been made after the update.
 *
 * On the Apply that first shows a tracer made in the GUI, it also keeps the
 * field input's display in that view as context that does not cover the
 * elements: a 3D input's surface (an Exodus disk, a mesh) becomes its
 * outline, an outline stays; a 2D input (a slice, a map) stays as it is,
 * moved just behind the elements' plane, away from the camera, so its
 * continents or features stay behind the elements (its reader, for a time
 * series, reads a step again in frames of Play where the slice and the
 * tracer ask for different times); a 2D input coloured by an array gets a
 * colour map of its own in greys, so the elements' colours (often of the
 * same quantity: velocity magnitude and Speed) stand out on it. Once that
 * Apply is done, the tracer's display (coloured by Speed) is coloured over
 * the range of the middle 90% of the speeds, not their extremes
 * (readableColours()).
 * At startup it installs the pqBoundParticleTickGuard and the
 * pqBoundParticlePlayUpdates.
 */
#ifndef pqBoundParticleDefaults_h
#define pqBoundParticleDefaults_h

#include <QObject>

class pqDataRepresentation;
class pqOutputPort;
class pqPipelineSource;
class pqView;

class pqBoundParticleDefaults : public QObject
{
public:
  explicit pqBoundParticleDefaults(QObject* parent = nullptr);
  ~pqBoundParticleDefaults() override = default;

  void onStartup();
  void onShutdown() {}

  /// Sets the data-dependent defaults of `source` if it is a tracer that
  /// holds the placeholders of a proxy made before its input had data.
  static void complete(pqPipelineSource* source);

  /// When `representation` is a tracer's first display, made by the GUI's
  /// Apply: keeps the field input's displays in that view as context.
  static void shown(pqDataRepresentation* representation);

  /**
   * Colours `display` (a tracer's, coloured by a one-component array such as
   * Speed) over the range holding the middle 90% of its values, the range a
   * user would set by hand, rather than over its extremes (bp::colourScale:
   * on a log scale where most values crowd its bottom; left alone where that
   * range is nearly the full one), and turns its colour map's automatic
   * rescaling off (as the colour map editor's "Rescale and disable automatic
   * rescaling"): where its colour map is at ParaView's default mode, or, with
   * `onlyHeld`, only where this set its range and it is still unchanged. Says
   * so in Output Messages. True where it set the range.
   */
  static bool readableColours(pqDataRepresentation* display, bool onlyHeld);

private:
  /// `field`, the display of `input` in `view`: a 3D field's outline, a 2D
  /// field's display moved behind the elements' plane.
  static void keepAsContext(pqOutputPort* input, pqDataRepresentation* field, pqView* view);
};

#endif
