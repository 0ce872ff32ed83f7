// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BoundParticlesChoices.h
 * @brief Every enumeration a property of the plugin takes, each with the
 * panel's texts of its values beside it.
 *
 * A value's number is what a saved state (.pvsm) and the proxy XML hold, so
 * no enumerator may change its value or move. `EnumTraits<E>::names[v]` is
 * the text the panel shows for value v; Plugin/BoundParticles.xml lists the
 * same entries by hand, and PropertyDefaults.EveryPropertyOfEveryProxyHasOneVerdict
 * holds the two together (E is the type of the class's typed getter).
 *
 * This header depends on nothing but the standard library, so any layer may
 * include it: Core's modules, the filters, the display and the GPU engine.
 */
#ifndef BoundParticles_BoundParticlesChoices_h
#define BoundParticles_BoundParticlesChoices_h

#include <iterator>

namespace bp
{

/// Specialised beside each enumeration: `names[v]` is the panel's text of
/// value v, for v = 0 .. n-1 (every enumeration here counts from 0 with no gap).
template <typename E>
struct EnumTraits;

/// How many values the enumeration has.
template <typename E>
constexpr int enumCount()
{
  return int(std::size(EnumTraits<E>::names));
}

/// The panel's text of value v ("Runge-Kutta 4", "Fish", ...), "?" for a
/// number that names no value.
template <typename E>
constexpr const char* enumName(E v)
{
  const int i = int(v);
  return i >= 0 && i < enumCount<E>() ? EnumTraits<E>::names[i] : "?";
}

/// How particles are advected (Integrator): Euler (thesis eq. 2.2), the
/// midpoint rule or classic Runge-Kutta.
enum class Integrator
{
  Euler = 0,
  RK2,
  RK4
};
template <>
struct EnumTraits<Integrator>
{
  static constexpr const char* names[] = { "Euler", "Runge-Kutta 2", "Runge-Kutta 4" };
};

/// How an element's springs are restored after a step (Restoration).
enum class Restoration
{
  AveragedJacobi = 0,
  Jacobi,
  GaussSeidel,
  ShapeMatching ///< best rigid fit (Core/Elements/ShapeMatching.h), goals blended by shapeStiffness
};
template <>
struct EnumTraits<Restoration>
{
  static constexpr const char* names[] = { "Averaged Jacobi", "Jacobi", "Gauss-Seidel",
    "Shape Matching" };
};

/// How an element is turned when it is placed (Engine::place).
enum class Orientation
{
  Fixed = 0, ///< by Parameters::frame (Element Rotation)
  Random,    ///< a uniform random rotation (about the plane's axis on a flat field)
  AlongFlow  ///< the frame's x axis turned onto the flow at the release centre
};
template <>
struct EnumTraits<Orientation>
{
  static constexpr const char* names[] = { "Fixed", "Random", "Along Flow" };
};

/// Where releases land in the emitter box (Engine::releaseCenter).
enum class ReleasePattern
{
  Random = 0, ///< uniform draws (with Release Weights: in proportion to the weights)
  Lattice     ///< element e at point e of Parameters::lattice, release after release
};
template <>
struct EnumTraits<ReleasePattern>
{
  static constexpr const char* names[] = { "Random", "Lattice" };
};

/// What holds an element in place (Engine::anchor).
enum class Anchor
{
  None = 0, ///< free: advected with the flow
  Centre    ///< its centre kept where it was released; it still turns and deforms
};
template <>
struct EnumTraits<Anchor>
{
  static constexpr const char* names[] = { "None", "Centre" };
};

/// Whether particles carry inertia (Core/Engine/Inertia.h): None, the massless
/// tracer; MaxeyRiley, the reduced Maxey-Riley equation with drag, the
/// fluid's acceleration with added mass, and gravity with buoyancy.
enum class Inertia
{
  None = 0,
  MaxeyRiley
};
template <>
struct EnumTraits<Inertia>
{
  static constexpr const char* names[] = { "None", "Maxey-Riley" };
};

/// When an element is released again (Reset When): once its centre has left
/// the field, or once any of its particles has.
enum class ResetWhen
{
  CenterLeaves = 0,
  AnyParticleLeaves
};
template <>
struct EnumTraits<ResetWhen>
{
  static constexpr const char* names[] = { "Center Leaves", "Any Particle Leaves" };
};

/// What happens to an element that leaves the field (Boundary): through a
/// side of the grid or into a cell outside the flow, as Reset When tests it.
/// ReleaseAgain places it again at once (its next generation); Terminate
/// hides it until its lifetime runs out, and only then places it again, so
/// its slot stays empty meanwhile. Stick, Slip and Bounce make the field's
/// boundary a wall that keeps the particles in (Walls.h): one that crosses
/// it is held on it (Stick), slides along it (Slip) or is reflected with the
/// Restitution (Bounce), and the springs restore the rest of the element
/// (engine specification, "Boundaries").
enum class Boundary
{
  ReleaseAgain = 0,
  Terminate,
  Stick,
  Slip,
  Bounce
};
template <>
struct EnumTraits<Boundary>
{
  static constexpr const char* names[] = { "Release Again", "Terminate", "Stick", "Slip",
    "Bounce" };
};

/// What a surface of the tracer's Surfaces input does to the elements that
/// pass it (Surface Interaction; engine specification 2.10): a Gate lets
/// them through and records each passage, an Outlet ends them (as Boundary
/// Terminate does) and records it, a Wall acts as the Boundary does at the
/// field's sides. A Surface Interaction Array holds these values per cell.
enum class SurfaceInteraction
{
  Gate = 0,
  Outlet,
  Wall
};
template <>
struct EnumTraits<SurfaceInteraction>
{
  static constexpr const char* names[] = { "Gate", "Outlet", "Wall" };
};

/// The unit of the tracer's Step Size (Step Size Unit): cells, the fastest
/// particle of the field moving that many cell lengths per step
/// (TraceSettings::stepInCellLengths), or the data's time units.
enum class StepUnit
{
  CellLength = 0,
  Time
};
template <>
struct EnumTraits<StepUnit>
{
  static constexpr const char* names[] = { "Cell Length", "Time" };
};

/// Shape matching's fit (Shape Matching Mode): the best rotation, or that
/// blended with the best affine fit (Müller et al. 2005, section 4.3;
/// Parameters::linearShapeMatching).
enum class ShapeFit
{
  Rigid = 0,
  Linear
};
template <>
struct EnumTraits<ShapeFit>
{
  static constexpr const char* names[] = { "Rigid", "Linear" };
};

/// The built-in shapes of thesis Fig. 3.4, with no power-of-two padding
/// (Core/Elements/ElementTemplate.h builds their templates).
enum class BuiltinShape
{
  Point = 0,
  Square,
  Strip4,
  Strip8,
  Strip16,
  Cross,
  Paddlewheel,
  Tetrahedron,
  Fish,
};
template <>
struct EnumTraits<BuiltinShape>
{
  static constexpr const char* names[] = { "Point", "Square", "Strip4", "Strip8", "Strip16",
    "Cross", "Paddlewheel", "Tetrahedron", "Fish" };
};

/// Which springs a mesh without lines gets (thesis §3.3: springs decide how
/// an element may fold).
enum class MeshSprings
{
  Edges = 0,         ///< the triangles' edges: a sheet that folds freely
  EdgesAndDiagonals, ///< plus, across every edge two triangles share, their far corners
  AllPairs           ///< every pair of particles: rigid
};
template <>
struct EnumTraits<MeshSprings>
{
  static constexpr const char* names[] = { "Edges", "Edges + Diagonals", "All Pairs" };
};

/// How the elements of a system are linked into a super set (thesis §5.1,
/// Core/Elements/SuperSet.h): not at all, or as a chain, ring, sheet, tube
/// or torus of elements.
enum class Linking
{
  None = 0,
  Chain,
  Ring,
  Sheet,
  Tube,
  Torus
};
template <>
struct EnumTraits<Linking>
{
  static constexpr const char* names[] = { "None", "Chain", "Ring", "Sheet", "Tube", "Torus" };
};

/// The tracer's Engine property (Core/Stepping/EngineChoice.h: usesGpuEngine).
/// The panel lists Automatic first; the values keep this order.
enum class EngineChoice
{
  Cpu = 0,
  Gpu = 1,
  Automatic = 2
};
template <>
struct EnumTraits<EngineChoice>
{
  static constexpr const char* names[] = { "CPU", "GPU", "Automatic" };
};

/// Which way a trace runs in time (Time Direction; Core/Plan/TimeDirection.h):
/// toward later times, or from the end of the release window toward earlier
/// times through the reversed flow.
enum class TimeDirection
{
  Forward = 0,
  Backward
};
template <>
struct EnumTraits<TimeDirection>
{
  static constexpr const char* names[] = { "Forward", "Backward" };
};

/// The analytic source's flows (Core/Field/AnalyticFlows.h; the formulas are
/// in docs/user-guide.md, "Analytic Flow").
enum class AnalyticFlow
{
  SolidBodyRotation = 0, ///< unit angular velocity about the box's vertical axis
  ShearLayer,            ///< thesis Fig. 4.2: flow along x whose speed peaks mid-depth in z
  VerticalShear,         ///< thesis Fig. 4.4: horizontal wind veering 90 degrees with height
  ABC,                   ///< Arnold-Beltrami-Childress flow, one period over the box
  Hurricane,             ///< tangential winds, inflow, eyewall updraft, decaying with height
  DoubleGyre,            ///< unsteady double gyre (Shadden et al. 2005), period 10
};
template <>
struct EnumTraits<AnalyticFlow>
{
  static constexpr const char* names[] = { "Solid Body Rotation", "Shear Layer", "Vertical Shear",
    "ABC", "Hurricane", "Double Gyre" };
};

} // namespace bp

#endif
