// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticlePeriodicWidget.h"

#include "pqPropertiesPanel.h"
#include "vtkSMIntVectorProperty.h"
#include "vtkSMProxy.h"
#include "vtkSetGet.h"

#include <QCheckBox>
#include <QHBoxLayout>

pqBoundParticlePeriodicWidget::pqBoundParticlePeriodicWidget(
  vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
{
  this->setProperty(property);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(pqPropertiesPanel::suggestedMargins());
  layout->setSpacing(pqPropertiesPanel::suggestedHorizontalSpacing());
  auto* flags = vtkSMIntVectorProperty::SafeDownCast(property);
  if (!flags || flags->GetNumberOfElements() != 3)
  {
    // A mistake in the XML, not the user's: the widget stays empty.
    vtkGenericWarningMacro("BoundParticlePeriodic: property '"
      << (property ? property->GetXMLName() : "(none)") << "' is not three integers");
    return;
  }
  const char* const axes[3] = { "X", "Y", "Z" };
  for (int axis = 0; axis < 3; ++axis)
  {
    auto* box = new QCheckBox(axes[axis], this);
    box->setObjectName(axes[axis]);
    // checked <-> element `axis` (0 or 1), as ParaView links a boolean's box.
    this->addPropertyLink(box, "checked", SIGNAL(toggled(bool)), flags, axis);
    layout->addWidget(box);
  }
  layout->addStretch();
  // A click is a whole change: the panel's Apply lights up at once.
  this->setChangeAvailableAsChangeFinished(true);
}
