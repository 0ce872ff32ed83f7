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
 * continents or features stay behind the elements. (Its reader, for a time
 * series, reads a step again in frames of Play where the slice and the
 * tracer ask for different times.)
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

private:
  /// `field`, the display of `input` in `view`: a 3D field's outline, a 2D
  /// field's display moved behind the elements' plane.
  static void keepAsContext(pqOutputPort* input, pqDataRepresentation* field, pqView* view);
};

#endif
