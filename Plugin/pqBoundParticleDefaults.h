// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleDefaults
 * @brief Completes the defaults of a Bound Particle Tracer made before its
 * input had data (from the Python shell).
 *
 * ParaView picks a filter's data-dependent defaults (the Vectors array, the
 * emitter box from the input's bounds) when the filter is made. From the
 * Python shell that is usually before the input has run, so the panel showed
 * no Vectors and an Emitter Size of -2 -2 -2 (the extents of bounds never
 * set) for good, and so did the Seed Types' Point Cloud and Line (a radius
 * of -0.2, a line from (1, 1, 1) to (-1, -1, -1)). This autostart watches
 * the tracers that get registered; one that holds those placeholders has its
 * input updated and those properties set from its data, as if it had been
 * made after the update.
 *
 * On the Apply that first shows a tracer made in the GUI, it also hides the
 * field input's display in that view when it is a slice (a 2D image's
 * default), which lies in the elements' plane and covers them, as the
 * tracer's replace_input="2" hides an opaque surface; an outline stays.
 * At startup it installs the pqBoundParticleTickGuard and the
 * pqBoundParticlePlayUpdates.
 */
#ifndef pqBoundParticleDefaults_h
#define pqBoundParticleDefaults_h

#include <QObject>

class pqDataRepresentation;
class pqPipelineSource;

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
  /// Apply: hides the field input's display in that view if it shows a slice.
  static void shown(pqDataRepresentation* representation);
};

#endif
