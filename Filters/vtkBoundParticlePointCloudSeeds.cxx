// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticlePointCloudSeeds.h"

#include "CounterHash.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkBoundParticlePointCloudSeeds);

namespace
{
/// The counter lane of the cloud's draws. Element releases use their
/// generation there (counting up from 0), so the cloud's draws never repeat
/// those of a release.
constexpr std::uint32_t CloudLane = 0xffffffffu;
/// Candidates tried per point: a cube's candidate misses the ball about half
/// the time, so the last is reached with probability 2^-64.
constexpr int Candidates = 64;
}

void vtkBoundParticlePointCloudSeeds::AppendPoints(
  std::uint32_t seed, const bool flat[3], vtkIdType maxPoints, std::vector<double>& xyz)
{
  const vtkIdType count = std::min<vtkIdType>(this->GetNumberOfSeedPoints(), maxPoints);
  const double radius = this->Radius > 0.0 && std::isfinite(this->Radius) ? this->Radius : 0.0;
  xyz.reserve(xyz.size() + 3 * std::size_t(std::max<vtkIdType>(count, 0)));
  for (vtkIdType i = 0; i < count; ++i)
  {
    // Uniform in the ball (disc, segment) of the axes that are not flat: the
    // first candidate from the cube around it that lies inside.
    double offset[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < Candidates; ++k)
    {
      double candidate[3] = { 0.0, 0.0, 0.0 }, length2 = 0.0;
      for (int a = 0; a < 3; ++a)
      {
        if (!flat[a])
        {
          const float u =
            bp::uniformDraw(seed, std::uint32_t(i), CloudLane, std::uint32_t(3 * k + a));
          candidate[a] = 2.0 * double(u) - 1.0;
          length2 += candidate[a] * candidate[a];
        }
      }
      if (length2 <= 1.0)
      {
        std::copy(candidate, candidate + 3, offset);
        break;
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      xyz.push_back(this->Center[a] + radius * offset[a]);
    }
  }
}

std::string vtkBoundParticlePointCloudSeeds::DescribeUnusableParameters()
{
  std::ostringstream say;
  if (!(this->Radius > 0.0) || !std::isfinite(this->Radius))
  {
    say << "The Point Cloud's Radius " << this->Radius
        << " is not a positive number: every seed point is its Center. Give a positive Radius.";
  }
  if (this->NumberOfPoints < 1)
  {
    say << (say.tellp() > 0 ? " " : "") << "The Point Cloud's Number Of Points "
        << this->NumberOfPoints << " is below 1: it has 1 point.";
  }
  return say.str();
}

void vtkBoundParticlePointCloudSeeds::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Center: " << this->Center[0] << " " << this->Center[1] << " " << this->Center[2]
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "NumberOfPoints: " << this->NumberOfPoints << "\n";
}
