// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkBoundParticlePointCloudSeeds
 * @brief Seed Type "Point Cloud": NumberOfPoints release points drawn
 * uniformly inside a sphere.
 *
 * As ParaView's Point Cloud seeds (vtkPointSource's uniform distribution),
 * but drawn from the tracer's counter-based random numbers with its Seed:
 * point i depends only on (Seed, i), so every process of a parallel run, and
 * every run, gets the same cloud. On a field that is flat along an axis (a
 * 2D slice) the points fill the disc of the sphere in the field's plane
 * rather than a ball squashed onto it, which would crowd its centre.
 */
#ifndef vtkBoundParticlePointCloudSeeds_h
#define vtkBoundParticlePointCloudSeeds_h

#include "BoundParticlesFiltersModule.h" // for export macro
#include "vtkBoundParticleSeedType.h"

#include <algorithm> // for std::max

class BOUNDPARTICLESFILTERS_EXPORT vtkBoundParticlePointCloudSeeds : public vtkBoundParticleSeedType
{
public:
  static vtkBoundParticlePointCloudSeeds* New();
  vtkTypeMacro(vtkBoundParticlePointCloudSeeds, vtkBoundParticleSeedType);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The sphere's centre (default the origin) and radius (default 1).
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  /// (one not above 0, or not finite, puts every point on the centre, said
  /// by DescribeUnusableParameters).
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// How many points (default 1000; below 1, one, said by
  /// DescribeUnusableParameters).
  vtkSetMacro(NumberOfPoints, int);
  vtkGetMacro(NumberOfPoints, int);
  ///@}

  const char* GetSeedTypeName() override { return "Point Cloud"; }
  const char* GetPointCountName() override { return "Number Of Points"; }
  vtkIdType GetNumberOfSeedPoints() override { return std::max(this->NumberOfPoints, 1); }
#ifndef __VTK_WRAP__
  void AppendPoints(
    std::uint32_t seed, const bool flat[3], vtkIdType maxPoints, std::vector<double>& xyz) override;
  std::string DescribeUnusableParameters() override;
#endif

protected:
  vtkBoundParticlePointCloudSeeds() = default;
  ~vtkBoundParticlePointCloudSeeds() override = default;

  double Center[3] = { 0.0, 0.0, 0.0 };
  double Radius = 1.0;
  int NumberOfPoints = 1000;

private:
  vtkBoundParticlePointCloudSeeds(const vtkBoundParticlePointCloudSeeds&) = delete;
  void operator=(const vtkBoundParticlePointCloudSeeds&) = delete;
};

#endif
