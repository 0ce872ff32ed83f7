// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMBoundParticleVectorsDomain
 * @brief The tracer's Vectors list, whose default prefers a velocity.
 *
 * An ArrayListDomain (the input's 3-component point and cell arrays) whose
 * default is the input's active vectors where it has them, else the array
 * named most like a velocity (bp::pickVelocityName: VEL over ACCL and DISPL,
 * U, wind...), else the first, as ArrayListDomain's; but where the tracer
 * found that array's units failing its time line's check while another
 * 3-component point array's passed (its UnitsMismatchedVectors and
 * UnitsFittingVectors, bp::preferFittingUnits), the one that passed
 * (gfs_wind10m: velocity_deg_per_hour, not its active vectors, velocity
 * in m/s on a grid in degrees). The XML names it
 * `BoundParticleVectorsDomain`; it reads the same attributes as
 * `ArrayListDomain`.
 */
#ifndef vtkSMBoundParticleVectorsDomain_h
#define vtkSMBoundParticleVectorsDomain_h

#include "BoundParticlesServerManagerModule.h" // for the export macro
#include "vtkSMArrayListDomain.h"

#include <string> // for FindFittingUnits

class BOUNDPARTICLESSERVERMANAGER_EXPORT vtkSMBoundParticleVectorsDomain
  : public vtkSMArrayListDomain
{
public:
  static vtkSMBoundParticleVectorsDomain* New();
  vtkTypeMacro(vtkSMBoundParticleVectorsDomain, vtkSMArrayListDomain);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// ArrayListDomain's default (the XML's default value, else the input's
  /// active vectors), or, where that is only the first array, the one
  /// named like a velocity.
  int SetDefaultValues(vtkSMProperty* property, bool useUncheckedValues) override;

protected:
  vtkSMBoundParticleVectorsDomain() = default;
  ~vtkSMBoundParticleVectorsDomain() override = default;

private:
  /// Whether `name` of `association` is the input's active vectors there.
  bool IsActiveVectors(const char* name, int association);
  /// What the tracer (`property`'s proxy) found of its input in its last
  /// RequestInformation: the array by name whose units fail its time line's
  /// check and the one whose units fit (its UnitsMismatchedVectors and
  /// UnitsFittingVectors, read, nothing run); empty where there is none.
  void FindFittingUnits(vtkSMProperty* property, std::string& mismatched, std::string& fitting);

  vtkSMBoundParticleVectorsDomain(const vtkSMBoundParticleVectorsDomain&) = delete;
  void operator=(const vtkSMBoundParticleVectorsDomain&) = delete;
};

#endif
