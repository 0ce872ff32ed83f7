// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMBoundParticleSurfaceArraysDomain.h"

#include "vtkObjectFactory.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkSMBoundParticleSurfaceArraysDomain);

int vtkSMBoundParticleSurfaceArraysDomain::ReadXMLAttributes(
  vtkSMProperty* property, vtkPVXMLElement* element)
{
  if (!this->Superclass::ReadXMLAttributes(property, element))
  {
    return 0;
  }
  // StringListDomain put the none string in the list; ArrayListDomain's
  // Update puts it back, with its information, once an input is connected.
  this->SetStrings(std::vector<std::string>());
  return 1;
}

void vtkSMBoundParticleSurfaceArraysDomain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
