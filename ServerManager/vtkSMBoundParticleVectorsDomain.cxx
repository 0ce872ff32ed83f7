// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMBoundParticleVectorsDomain.h"

#include "VelocityNames.h"

#include "vtkDataSetAttributes.h"
#include "vtkObjectFactory.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVDataSetAttributesInformation.h"
#include "vtkSMPropertyHelper.h"
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
  const int set = this->Superclass::SetDefaultValues(property, useUncheckedValues);
  auto* strings = vtkSMStringVectorProperty::SafeDownCast(property);
  const char* xmlDefault = strings ? strings->GetDefaultValue(4) : nullptr;
  if (!set || !strings || strings->GetNumberOfElements() != 5 || (xmlDefault && *xmlDefault))
  {
    return set; // not a SetInputArrayToProcess, or the XML names a default
  }
  vtkSMPropertyHelper helper(property);
  helper.SetUseUnchecked(useUncheckedValues);
  const char* chosen = helper.GetAsString(4);
  if (this->IsActiveVectors(chosen, std::atoi(helper.GetAsString(3))))
  {
    return set; // the data's own choice
  }
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
  return set;
}

void vtkSMBoundParticleVectorsDomain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
