// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleEmitterWidget
 * @brief The emitter's box widget in the tracer's panel: ParaView's box
 * widget showing Emitter Center and Emitter Size only.
 *
 * The box widget draws Position + Scale x ReferenceBounds; the tracer fixes
 * the reference bounds to [-0.5, 0.5]^3 so that the box is centre +- size / 2.
 * Those two helper properties mean nothing to a user, so this widget hides
 * them, which ParaView 5.11's XML alone cannot do. It also keeps two things
 * ParaView 5.11's box widget gets wrong for this convention:
 *  - Reset Bounds places the box on the input's bounds as centre and size
 *    (the base widget sets the reference bounds instead, which the tracer
 *    does not use, so the emitter stayed where it was);
 *  - Show Box keeps the user's choice when another pipeline item is
 *    selected and this one again (the base widget took the widget's
 *    visibility at the moment it was hidden, already off, and unticked it).
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

  void hideEvent(QHideEvent* event) override;
  void showEvent(QShowEvent* event) override;

private:
  /// Emitter Center and Size to the input's bounds.
  void resetToInputBounds();

  bool ShowBox = true; ///< the user's Show Box choice while the panel is hidden

  Q_DISABLE_COPY(pqBoundParticleEmitterWidget)
};

#endif
