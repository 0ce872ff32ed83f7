// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleEmitterWidget
 * @brief The emitter's box widget in the tracer's panel: ParaView's box
 * widget showing Emitter Center and Emitter Size only.
 *
 * The box widget draws Position + Scale x ReferenceBounds; the tracer fixes
 * the reference bounds to [-0.5, 0.5]^3 so that the box is centre +- size / 2.
 * Those two helper properties mean nothing to a user, so this widget hides
 * them, which ParaView 5.11's XML alone cannot do.
 */
#ifndef pqBoundParticleEmitterWidget_h
#define pqBoundParticleEmitterWidget_h

#include "pqBoxPropertyWidget.h"

class pqBoundParticleEmitterWidget : public pqBoxPropertyWidget
{
  typedef pqBoxPropertyWidget Superclass;

public:
  pqBoundParticleEmitterWidget(
    vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqBoundParticleEmitterWidget() override = default;

private:
  Q_DISABLE_COPY(pqBoundParticleEmitterWidget)
};

#endif
