// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMBoundParticleTracerProxy
 * @brief The tracer's source proxy: a state file's values that are not
 * numbers are said, and NaN and infinity are kept for the tracer to check.
 *
 * ParaView reads a number in a state file (`<Element value="..."/>`) with a
 * stream, which reads "nan", "NaN", "inf" and "Infinity" (as ParaView writes
 * a NaN or infinite value itself), and any text, as 0 without a word: a
 * tracer refused for a NaN Response Time would reload as a working massless
 * trace, and `Inertia` written as its entry's text would load as None. This
 * proxy reads those values again where ParaView's reading fails, and says
 * each with the property's name and the text:
 * - NaN, infinity or a number beyond double's range is kept as that value
 *   (the tracer refuses it or clamps it, as it would a script's);
 * - an enumeration's entry text takes that entry's value;
 * - other text leaves the property as it was (its default).
 * The XML names it `BoundParticleTracerProxy`; otherwise it is a SourceProxy.
 */
#ifndef vtkSMBoundParticleTracerProxy_h
#define vtkSMBoundParticleTracerProxy_h

#include "BoundParticlesServerManagerModule.h" // for the export macro
#include "vtkSMSourceProxy.h"

class BOUNDPARTICLESSERVERMANAGER_EXPORT vtkSMBoundParticleTracerProxy : public vtkSMSourceProxy
{
public:
  static vtkSMBoundParticleTracerProxy* New();
  vtkTypeMacro(vtkSMBoundParticleTracerProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// ParaView's loading, then the values it could not read, read again and said.
  int LoadXMLState(vtkPVXMLElement* element, vtkSMProxyLocator* locator) override;

protected:
  vtkSMBoundParticleTracerProxy() = default;
  ~vtkSMBoundParticleTracerProxy() override = default;

private:
  vtkSMBoundParticleTracerProxy(const vtkSMBoundParticleTracerProxy&) = delete;
  void operator=(const vtkSMBoundParticleTracerProxy&) = delete;
};

#endif
