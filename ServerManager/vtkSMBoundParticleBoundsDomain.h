// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMBoundParticleBoundsDomain
 * @brief A BoundsDomain that takes its default only from an input that has data.
 *
 * ParaView's BoundsDomain sets its property's default from the input's
 * bounds when the proxy is made. A source that has not run yet (a script's
 * filter made before its reader updates, or a simulation's producer in situ
 * before its first step) has no bounds: ParaView 5.11 then gives an emitter
 * box of size -2 and ParaView 6.1 one of size 0, which releases every element
 * at one point. This domain leaves the XML's default there (Emitter Size
 * -1 -1 -1, which spans the field whenever the trace runs) and otherwise is
 * ParaView's BoundsDomain. The XML names it `BoundParticleBoundsDomain`; it
 * reads the same attributes as `BoundsDomain`.
 */
#ifndef vtkSMBoundParticleBoundsDomain_h
#define vtkSMBoundParticleBoundsDomain_h

#include "BoundParticlesServerManagerModule.h" // for the export macro
#include "vtkSMBoundsDomain.h"

class BOUNDPARTICLESSERVERMANAGER_EXPORT vtkSMBoundParticleBoundsDomain : public vtkSMBoundsDomain
{
public:
  static vtkSMBoundParticleBoundsDomain* New();
  vtkTypeMacro(vtkSMBoundParticleBoundsDomain, vtkSMBoundsDomain);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// BoundsDomain's default where the input has points within valid
  /// bounds; none (the XML's default stands) where it has not.
  int SetDefaultValues(vtkSMProperty* property, bool useUncheckedValues) override;

protected:
  vtkSMBoundParticleBoundsDomain() = default;
  ~vtkSMBoundParticleBoundsDomain() override = default;

private:
  vtkSMBoundParticleBoundsDomain(const vtkSMBoundParticleBoundsDomain&) = delete;
  void operator=(const vtkSMBoundParticleBoundsDomain&) = delete;
};

#endif
