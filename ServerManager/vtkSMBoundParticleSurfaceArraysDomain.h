// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMBoundParticleSurfaceArraysDomain
 * @brief Surface Interaction Array's list: the Surfaces' cell arrays and
 * None, and nothing while Surfaces is not connected.
 *
 * An ArrayListDomain with a `none_string` holds that string from the XML on,
 * before any input: its string list then has an entry that its arrays'
 * information (association, partial) lacks until an input is connected, and
 * ParaView's array selector, built with the panel, asks for it: three
 * "Index out of range" errors in Output Messages for every tracer panel
 * shown while the optional Surfaces input is unconnected (ParaView 5.11 to
 * 6.1). This domain starts empty instead; connecting Surfaces fills it as
 * ArrayListDomain does (None, then the arrays). The property keeps its XML
 * default (None) meanwhile, and its widget is hidden then
 * (BoundParticleInputDecorator). The XML names it
 * `BoundParticleSurfaceArraysDomain`; it reads the same attributes as
 * `ArrayListDomain`.
 */
#ifndef vtkSMBoundParticleSurfaceArraysDomain_h
#define vtkSMBoundParticleSurfaceArraysDomain_h

#include "BoundParticlesServerManagerModule.h" // for the export macro
#include "vtkSMArrayListDomain.h"

class BOUNDPARTICLESSERVERMANAGER_EXPORT vtkSMBoundParticleSurfaceArraysDomain
  : public vtkSMArrayListDomain
{
public:
  static vtkSMBoundParticleSurfaceArraysDomain* New();
  vtkTypeMacro(vtkSMBoundParticleSurfaceArraysDomain, vtkSMArrayListDomain);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSMBoundParticleSurfaceArraysDomain() = default;
  ~vtkSMBoundParticleSurfaceArraysDomain() override = default;

  /// ArrayListDomain's attributes, without the none string's entry it
  /// lists before any input.
  int ReadXMLAttributes(vtkSMProperty* property, vtkPVXMLElement* element) override;

private:
  vtkSMBoundParticleSurfaceArraysDomain(const vtkSMBoundParticleSurfaceArraysDomain&) = delete;
  void operator=(const vtkSMBoundParticleSurfaceArraysDomain&) = delete;
};

#endif
