// SPDX-License-Identifier: BSD-3-Clause
// The VTK classes' enumerations are Core's, value for value, where a
// property's setter takes a VTK enum that is converted to its Core enum with
// a plain cast. The tracer's are generated with their checks from the proxy
// XML (cmake/BoundParticlesEnumerations.cmake); the analytic source's, and
// that the tracer's shapes are all of Core's, are checked here. The proxy
// XML's entries are checked against the classes by
// Testing/Cxx/TestPropertyDefaults.cxx: whatever the XML offers, the setter
// keeps.
#include "vtkAnalyticFlowSource.h"
#include "vtkBoundParticleTracer.h"

#include "AnalyticFlows.h"
#include "ElementTemplate.h"

namespace
{
template <typename Core>
constexpr bool same(int vtkValue, Core coreValue)
{
  return vtkValue == static_cast<int>(coreValue);
}

static_assert(vtkBoundParticleTracer::FISH + 1 == bp::enumCount<bp::BuiltinShape>(),
  "the tracer's Element Shape offers every built-in shape");

using F = vtkAnalyticFlowSource;
static_assert(same(F::SOLID_BODY_ROTATION, bp::AnalyticFlow::SolidBodyRotation) &&
    same(F::SHEAR_LAYER, bp::AnalyticFlow::ShearLayer) &&
    same(F::VERTICAL_SHEAR, bp::AnalyticFlow::VerticalShear) &&
    same(F::ABC, bp::AnalyticFlow::ABC) && same(F::HURRICANE, bp::AnalyticFlow::Hurricane) &&
    same(F::DOUBLE_GYRE, bp::AnalyticFlow::DoubleGyre),
  "vtkAnalyticFlowSource::Flows is bp::AnalyticFlow");
} // namespace
