// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleEmitterWidget.h"

pqBoundParticleEmitterWidget::pqBoundParticleEmitterWidget(
  vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent)
  : Superclass(proxy, group, parent, /*hideReferenceBounds=*/true)
{
}
