// SPDX-License-Identifier: BSD-3-Clause
// The VTK classes' enumerations are Core's, value for value: each public
// enum a property's setter takes is converted to its Core enum with a plain
// cast (vtkBoundParticleTracer::Settings and Config, vtkAnalyticFlowSource),
// which these checks make safe. The proxy XML's entries are checked against
// the classes by Testing/Cxx/TestPropertyDefaults.cxx: whatever the XML
// offers, the setter keeps.
#include "vtkAnalyticFlowSource.h"
#include "vtkBoundParticleTracer.h"

#include "AnalyticFlows.h"
#include "ElementTemplate.h"
#include "EngineParameters.h"
#include "SuperSet.h"
#include "WorkQueue.h"

namespace
{
using T = vtkBoundParticleTracer;

template <typename Core>
constexpr bool same(int vtkValue, Core coreValue)
{
  return vtkValue == static_cast<int>(coreValue);
}

static_assert(same(T::POINT, bp::BuiltinShape::Point) &&
    same(T::SQUARE, bp::BuiltinShape::Square) && same(T::STRIP4, bp::BuiltinShape::Strip4) &&
    same(T::STRIP8, bp::BuiltinShape::Strip8) && same(T::STRIP16, bp::BuiltinShape::Strip16) &&
    same(T::CROSS, bp::BuiltinShape::Cross) &&
    same(T::PADDLEWHEEL, bp::BuiltinShape::Paddlewheel) &&
    same(T::TETRAHEDRON, bp::BuiltinShape::Tetrahedron) && same(T::FISH, bp::BuiltinShape::Fish) &&
    T::FISH + 1 == bp::BuiltinShapeCount,
  "vtkBoundParticleTracer::Shapes is bp::BuiltinShape");
static_assert(same(T::EULER, bp::Integrator::Euler) &&
    same(T::RUNGE_KUTTA_2, bp::Integrator::RK2) && same(T::RUNGE_KUTTA_4, bp::Integrator::RK4),
  "vtkBoundParticleTracer::Integrators is bp::Integrator");
static_assert(same(T::AVERAGED_JACOBI, bp::Restoration::AveragedJacobi) &&
    same(T::JACOBI, bp::Restoration::Jacobi) &&
    same(T::GAUSS_SEIDEL, bp::Restoration::GaussSeidel) &&
    same(T::SHAPE_MATCHING, bp::Restoration::ShapeMatching),
  "vtkBoundParticleTracer::RestorationMethods is bp::Restoration");
static_assert(same(T::CENTER_LEAVES, bp::ResetWhen::CenterLeaves) &&
    same(T::ANY_PARTICLE_LEAVES, bp::ResetWhen::AnyParticleLeaves),
  "vtkBoundParticleTracer::ResetConditions is bp::ResetWhen");
static_assert(same(T::NO_ANCHOR, bp::Anchor::None) && same(T::ANCHOR_CENTRE, bp::Anchor::Centre),
  "vtkBoundParticleTracer::AnchorModes is bp::Anchor");
static_assert(
  same(T::NO_INERTIA, bp::Inertia::None) && same(T::MAXEY_RILEY, bp::Inertia::MaxeyRiley),
  "vtkBoundParticleTracer::InertiaModels is bp::Inertia");
static_assert(same(T::RANDOM_RELEASES, bp::ReleasePattern::Random) &&
    same(T::LATTICE_RELEASES, bp::ReleasePattern::Lattice),
  "vtkBoundParticleTracer::ReleasePatterns is bp::ReleasePattern");
static_assert(same(T::EDGES, bp::MeshSprings::Edges) &&
    same(T::EDGES_AND_DIAGONALS, bp::MeshSprings::EdgesAndDiagonals) &&
    same(T::ALL_PAIRS, bp::MeshSprings::AllPairs),
  "vtkBoundParticleTracer::TemplateSpringModes is bp::MeshSprings");
static_assert(same(T::NO_LINKING, bp::Linking::None) && same(T::CHAIN, bp::Linking::Chain) &&
    same(T::RING, bp::Linking::Ring) && same(T::SHEET, bp::Linking::Sheet) &&
    same(T::TUBE, bp::Linking::Tube) && same(T::TORUS, bp::Linking::Torus),
  "vtkBoundParticleTracer::LinkingModes is bp::Linking");
static_assert(same(T::FIXED_ORIENTATION, bp::Orientation::Fixed) &&
    same(T::RANDOM_ORIENTATION, bp::Orientation::Random) &&
    same(T::ALONG_FLOW, bp::Orientation::AlongFlow),
  "vtkBoundParticleTracer::ReleaseOrientations is bp::Orientation");
static_assert(same(T::CPU, bp::EngineChoice::Cpu) && same(T::GPU, bp::EngineChoice::Gpu) &&
    same(T::AUTOMATIC, bp::EngineChoice::Automatic),
  "vtkBoundParticleTracer::Engines is bp::EngineChoice");

using F = vtkAnalyticFlowSource;
static_assert(same(F::SOLID_BODY_ROTATION, bp::AnalyticFlow::SolidBodyRotation) &&
    same(F::SHEAR_LAYER, bp::AnalyticFlow::ShearLayer) &&
    same(F::VERTICAL_SHEAR, bp::AnalyticFlow::VerticalShear) &&
    same(F::ABC, bp::AnalyticFlow::ABC) && same(F::HURRICANE, bp::AnalyticFlow::Hurricane) &&
    same(F::DOUBLE_GYRE, bp::AnalyticFlow::DoubleGyre),
  "vtkAnalyticFlowSource::Flows is bp::AnalyticFlow");
} // namespace
