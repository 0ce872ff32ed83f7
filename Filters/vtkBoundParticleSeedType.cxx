// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleSeedType.h"

void vtkBoundParticleSeedType::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SeedTypeName: " << this->GetSeedTypeName() << "\n";
  os << indent << "NumberOfSeedPoints: " << this->GetNumberOfSeedPoints() << "\n";
}
