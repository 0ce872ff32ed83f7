// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleEmitterWidget.h"

#include "vtkBoundingBox.h"
#include "vtkPVDataInformation.h"
#include "vtkSMNewWidgetRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSourceProxy.h"

#include <QAbstractButton>

pqBoundParticleEmitterWidget::pqBoundParticleEmitterWidget(
  vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent)
  : Superclass(proxy, group, parent, /*hideReferenceBounds=*/true)
{
  if (auto* reset = this->findChild<QAbstractButton*>("resetBounds"))
  {
    // Replaces the base widget's handler (see the class comment).
    QObject::disconnect(reset, &QAbstractButton::clicked, nullptr, nullptr);
    QObject::connect(
      reset, &QAbstractButton::clicked, this, [this](bool) { this->resetToInputBounds(); });
  }
}

void pqBoundParticleEmitterWidget::resetToInputBounds()
{
  // The tracer's input, read when clicked (it may have changed): the base
  // widget looks for an "Input" in the property group, which this one has not.
  vtkSMPropertyHelper input(this->proxy(), "Input");
  auto* source = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy());
  if (!source)
  {
    return;
  }
  const vtkBoundingBox bounds(source->GetDataInformation(input.GetOutputPort())->GetBounds());
  if (!bounds.IsValid())
  {
    return;
  }
  double center[3], lengths[3];
  bounds.GetCenter(center);
  bounds.GetLengths(lengths);
  const double reference[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  const double none[3] = { 0, 0, 0 };
  vtkSMNewWidgetRepresentationProxy* box = this->widgetProxy();
  vtkSMPropertyHelper(box, "Position").Set(center, 3);
  vtkSMPropertyHelper(box, "Scale").Set(lengths, 3);
  vtkSMPropertyHelper(box, "ReferenceBounds").Set(reference, 6);
  vtkSMPropertyHelper(box, "Rotation").Set(none, 3);
  box->UpdateVTKObjects();
  Q_EMIT this->changeAvailable();
  this->render();
}

void pqBoundParticleEmitterWidget::hideEvent(QHideEvent* event)
{
  // Taken before the base class hides the box (and records it as hidden).
  this->ShowBox = this->isWidgetVisible();
  this->Superclass::hideEvent(event);
}

void pqBoundParticleEmitterWidget::showEvent(QShowEvent* event)
{
  this->Superclass::showEvent(event);
  this->setWidgetVisible(this->ShowBox);
}
