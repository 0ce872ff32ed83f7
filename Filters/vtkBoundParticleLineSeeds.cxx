// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleLineSeeds.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkBoundParticleLineSeeds);

void vtkBoundParticleLineSeeds::AppendPoints(
  std::uint32_t, const bool[3], vtkIdType maxPoints, std::vector<double>& xyz)
{
  const vtkIdType count = std::min(this->GetNumberOfSeedPoints(), maxPoints);
  xyz.reserve(xyz.size() + 3 * std::size_t(std::max<vtkIdType>(count, 0)));
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double t = double(i) / double(this->Segments());
    for (int a = 0; a < 3; ++a)
    {
      xyz.push_back(this->Point1[a] + t * (this->Point2[a] - this->Point1[a]));
    }
  }
}

std::string vtkBoundParticleLineSeeds::DescribeUnusableParameters()
{
  return this->Resolution >= 1 ? std::string()
                               : "The Line's Resolution " + std::to_string(this->Resolution) +
      " is below 1: it has 1 segment (its two ends). Raise the Resolution.";
}

void vtkBoundParticleLineSeeds::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Point1: " << this->Point1[0] << " " << this->Point1[1] << " " << this->Point1[2]
     << "\n";
  os << indent << "Point2: " << this->Point2[0] << " " << this->Point2[1] << " " << this->Point2[2]
     << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
}
