// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticlePeriodicWidget
 * @brief The tracer's Periodic property in its panel: three check boxes,
 * X, Y and Z, in one row.
 *
 * Periodic is an IntVectorProperty of three flags (0 or 1), one per axis;
 * ParaView shows such a property as three number fields. Each box here is
 * linked to its element of the property (checked is 1), so the panel's
 * Apply and Reset, undo, and a loaded state move the boxes as they move
 * ParaView's own widgets. XML: `panel_widget="BoundParticlePeriodic"` on the
 * property. The boxes' object names are X, Y and Z (recorded GUI tests).
 */
#ifndef pqBoundParticlePeriodicWidget_h
#define pqBoundParticlePeriodicWidget_h

#include "pqPropertyWidget.h"

class pqBoundParticlePeriodicWidget : public pqPropertyWidget
{
  typedef pqPropertyWidget Superclass;

public:
  pqBoundParticlePeriodicWidget(
    vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqBoundParticlePeriodicWidget() override = default;

private:
  Q_DISABLE_COPY(pqBoundParticlePeriodicWidget)
};

#endif
