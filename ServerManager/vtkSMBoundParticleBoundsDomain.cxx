// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMBoundParticleBoundsDomain.h"

#include "vtkObjectFactory.h"
#include "vtkPVDataInformation.h"

vtkStandardNewMacro(vtkSMBoundParticleBoundsDomain);

int vtkSMBoundParticleBoundsDomain::SetDefaultValues(
  vtkSMProperty* property, bool useUncheckedValues)
{
  vtkPVDataInformation* input = this->GetInputInformation();
  if (!input || input->GetNumberOfPoints() <= 0)
  {
    return 0; // nothing ran yet: the XML's default stands
  }
  const double* bounds = input->GetBounds();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!(bounds[2 * axis] <= bounds[2 * axis + 1]))
    {
      return 0; // uninitialised bounds (min above max, or NaN)
    }
  }
  return this->Superclass::SetDefaultValues(property, useUncheckedValues);
}

void vtkSMBoundParticleBoundsDomain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
