// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkBoundParticleLineSeeds
 * @brief Seed Type "Line": Resolution + 1 release points evenly spaced from
 * Point1 to Point2, in that order.
 *
 * The points of vtkLineSource (ParaView's Line seeds), so that releases,
 * which take the seed points in order, start along the line from Point1.
 */
#ifndef vtkBoundParticleLineSeeds_h
#define vtkBoundParticleLineSeeds_h

#include "BoundParticlesFiltersModule.h" // for export macro
#include "vtkBoundParticleSeedType.h"

class BOUNDPARTICLESFILTERS_EXPORT vtkBoundParticleLineSeeds : public vtkBoundParticleSeedType
{
public:
  static vtkBoundParticleLineSeeds* New();
  vtkTypeMacro(vtkBoundParticleLineSeeds, vtkBoundParticleSeedType);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The line's ends (default the origin and (1, 0, 0)).
  vtkSetVector3Macro(Point1, double);
  vtkGetVector3Macro(Point1, double);
  vtkSetVector3Macro(Point2, double);
  vtkGetVector3Macro(Point2, double);
  ///@}

  ///@{
  /// Segments along the line (default 1000): Resolution + 1 points; below
  /// 1, one segment (its two ends), said by DescribeUnusableParameters.
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}

  const char* GetSeedTypeName() override { return "Line"; }
  const char* GetPointCountName() override { return "Resolution"; }
  vtkIdType GetNumberOfSeedPoints() override { return vtkIdType(this->Segments()) + 1; }
#ifndef __VTK_WRAP__
  void AppendPoints(
    std::uint32_t seed, const bool flat[3], vtkIdType maxPoints, std::vector<double>& xyz) override;
  std::string DescribeUnusableParameters() override;
#endif

protected:
  vtkBoundParticleLineSeeds() = default;
  ~vtkBoundParticleLineSeeds() override = default;

  double Point1[3] = { 0.0, 0.0, 0.0 };
  double Point2[3] = { 1.0, 0.0, 0.0 };
  int Resolution = 1000;

private:
  /// The segments used: Resolution, at least 1.
  int Segments() const
  {
    return this->Resolution < 1 ? 1 : this->Resolution;
  }

  vtkBoundParticleLineSeeds(const vtkBoundParticleLineSeeds&) = delete;
  void operator=(const vtkBoundParticleLineSeeds&) = delete;
};

#endif
