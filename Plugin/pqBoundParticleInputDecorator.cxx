// SPDX-License-Identifier: BSD-3-Clause
#include "pqBoundParticleInputDecorator.h"

#include "pqActiveObjects.h"
#include "pqCoreUtilities.h"
#include "pqPropertyWidget.h"
#include "vtkCommand.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMProperty.h"
#include "vtkSMProxy.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMUncheckedPropertyHelper.h"
#include "vtkType.h"

#include <cstring>

pqBoundParticleInputDecorator::pqBoundParticleInputDecorator(
  vtkPVXMLElement* config, pqPropertyWidget* parent)
  : Superclass(config, parent)
{
  const char* name = config->GetAttributeOrDefault("input", "Input");
  vtkSMProxy* proxy = parent->proxy();
  this->Input = proxy ? proxy->GetProperty(name) : nullptr;
  this->observe(this->Input);
  if (std::strcmp(config->GetAttributeOrDefault("when", ""), "emitter_box") == 0 && proxy)
  {
    // Picking another Seed Type in the panel: look again before Apply.
    this->SeedType = proxy->GetProperty(config->GetAttributeOrDefault("seed_type", "SeedType"));
    this->observe(this->SeedType);
  }
  // An input's time steps are known once it has updated (after Apply).
  QObject::connect(&pqActiveObjects::instance(), &pqActiveObjects::dataUpdated, this,
    [this] { this->inputChanged(); });
}

pqBoundParticleInputDecorator::~pqBoundParticleInputDecorator()
{
  for (auto& observer : this->Observers)
  {
    if (observer.first)
    {
      observer.first->RemoveObserver(observer.second);
    }
  }
}

void pqBoundParticleInputDecorator::observe(vtkSMProperty* property)
{
  if (!property)
  {
    return;
  }
  // Connecting or changing it: look again (signal to signal).
  this->Observers.emplace_back(property,
    pqCoreUtilities::connect(
      property, vtkCommand::UncheckedPropertyModifiedEvent, this, SIGNAL(visibilityChanged())));
  this->Observers.emplace_back(property,
    pqCoreUtilities::connect(
      property, vtkCommand::UncheckedPropertyModifiedEvent, this, SIGNAL(enableStateChanged())));
}

void pqBoundParticleInputDecorator::inputChanged()
{
  Q_EMIT this->visibilityChanged();
  Q_EMIT this->enableStateChanged();
}

bool pqBoundParticleInputDecorator::actsAs(const char* mode) const
{
  const char* configured = this->xml()->GetAttribute("mode");
  return configured && std::strcmp(configured, mode) == 0;
}

bool pqBoundParticleInputDecorator::conditionHolds() const
{
  if (!this->Input)
  {
    return true;
  }
  vtkSMUncheckedPropertyHelper input(this->Input);
  auto* source = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy());
  const std::string when = this->xml()->GetAttributeOrDefault("when", "");
  if (when == "connected" || when == "unconnected")
  {
    return (source != nullptr) == (when == "connected");
  }
  if (when == "emitter_box")
  {
    if (source)
    {
      return false; // a Seed Source replaces every Seed Type
    }
    // The Emitter Box entry is a null proxy; no value at all (the property
    // not yet initialised) is the filter's default, the box too.
    vtkSMProxy* seeds =
      this->SeedType ? vtkSMUncheckedPropertyHelper(this->SeedType).GetAsProxy() : nullptr;
    return !seeds || !seeds->GetXMLName() || std::strcmp(seeds->GetXMLName(), "EmitterBox") == 0;
  }
  if (when == "steady" || when == "unsteady")
  {
    // Before the input has data its time steps are unknown: show and enable.
    vtkPVDataInformation* info =
      source ? source->GetDataInformation(input.GetOutputPort()) : nullptr;
    if (!info || info->GetNumberOfPoints() == 0)
    {
      return true;
    }
    return (info->GetNumberOfTimeSteps() >= 2) == (when == "unsteady");
  }
  if (when == "resampled")
  {
    // As FieldResampler::needed(): anything but an image or a rectilinear grid.
    vtkPVDataInformation* info =
      source ? source->GetDataInformation(input.GetOutputPort()) : nullptr;
    if (!info || (info->GetNumberOfPoints() == 0 && !info->IsCompositeDataSet()))
    {
      return true;
    }
    const int type = info->GetDataSetType();
    return info->IsCompositeDataSet() ||
      (type != VTK_IMAGE_DATA && type != VTK_STRUCTURED_POINTS && type != VTK_UNIFORM_GRID &&
        type != VTK_RECTILINEAR_GRID);
  }
  return true;
}

bool pqBoundParticleInputDecorator::canShowWidget(bool showAdvanced) const
{
  if (this->actsAs("visibility") && !this->conditionHolds())
  {
    return false;
  }
  return this->Superclass::canShowWidget(showAdvanced);
}

bool pqBoundParticleInputDecorator::enableWidget() const
{
  if (this->actsAs("enabled_state") && !this->conditionHolds())
  {
    return false;
  }
  return this->Superclass::enableWidget();
}
