// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMBoundParticleVectorsDomain.h"

#include "VelocityNames.h"

#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkObjectFactory.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVDataSetAttributesInformation.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMStringVectorProperty.h"

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSMBoundParticleVectorsDomain);

bool vtkSMBoundParticleVectorsDomain::IsActiveVectors(const char* name, int association)
{
  vtkPVDataInformation* input = this->GetInputDataInformation("Input");
  vtkPVDataSetAttributesInformation* arrays =
    input ? input->GetAttributeInformation(association) : nullptr;
  vtkPVArrayInformation* vectors =
    arrays ? arrays->GetAttributeInformation(vtkDataSetAttributes::VECTORS) : nullptr;
  return vectors && vectors->GetName() && name && std::strcmp(vectors->GetName(), name) == 0;
}

int vtkSMBoundParticleVectorsDomain::SetDefaultValues(
  vtkSMProperty* property, bool useUncheckedValues)
{
  auto* strings = vtkSMStringVectorProperty::SafeDownCast(property);
  const char* xmlDefault = strings ? strings->GetDefaultValue(4) : nullptr;
  // Not a SetInputArrayToProcess, or the XML names a default: as ArrayListDomain.
  const bool choosing =
    strings && strings->GetNumberOfElements() == 5 && !(xmlDefault && *xmlDefault);
  std::string mismatched, fitting;
  if (choosing && this->GetNumberOfStrings() >= 2)
  {
    // Asked before this sets a value: the tracer then has no Vectors yet.
    this->FindFittingUnits(property, mismatched, fitting);
  }
  const int set = this->Superclass::SetDefaultValues(property, useUncheckedValues);
  if (!set || !choosing)
  {
    return set;
  }
  vtkSMPropertyHelper helper(property);
  helper.SetUseUnchecked(useUncheckedValues);
  const char* chosen = helper.GetAsString(4);
  const int association = std::atoi(helper.GetAsString(3));
  if (!this->IsActiveVectors(chosen, association))
  {
    std::vector<std::string> names;
    for (unsigned int i = 0; i < this->GetNumberOfStrings(); ++i)
    {
      names.emplace_back(this->GetString(i));
    }
    const int velocity = bp::pickVelocityName(names);
    if (velocity >= 0 && (!chosen || names[std::size_t(velocity)] != chosen))
    {
      helper.Set(3, std::to_string(this->GetFieldAssociation(unsigned(velocity))).c_str());
      helper.Set(4, names[std::size_t(velocity)].c_str());
    }
  }
  // The array whose units fit in place of the one chosen by name, where
  // the tracer found that one's failing its time line's check.
  chosen = helper.GetAsString(4);
  const int points = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (fitting.empty() || !chosen || mismatched != chosen ||
    std::atoi(helper.GetAsString(3)) != points)
  {
    return set;
  }
  for (unsigned int i = 0; i < this->GetNumberOfStrings(); ++i)
  {
    if (fitting == this->GetString(i) && this->GetFieldAssociation(i) == points)
    {
      helper.Set(4, fitting.c_str());
      break;
    }
  }
  return set;
}

void vtkSMBoundParticleVectorsDomain::FindFittingUnits(
  vtkSMProperty* property, std::string& mismatched, std::string& fitting)
{
  vtkSMProxy* tracer = property->GetParent();
  vtkSMProperty* from = tracer ? tracer->GetProperty("UnitsMismatchedVectors") : nullptr;
  vtkSMProperty* to = tracer ? tracer->GetProperty("UnitsFittingVectors") : nullptr;
  if (!from || !to)
  {
    return;
  }
  // Read only: nothing pushed or updated for a default (the tracer's input
  // is shared with other consumers, and may be only the active source that
  // pvpython connects before the Input asked for).
  tracer->UpdatePropertyInformation(from);
  tracer->UpdatePropertyInformation(to);
  const char* a = vtkSMPropertyHelper(from).GetAsString();
  const char* b = vtkSMPropertyHelper(to).GetAsString();
  mismatched = a ? a : "";
  fitting = b ? b : "";
}

void vtkSMBoundParticleVectorsDomain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
