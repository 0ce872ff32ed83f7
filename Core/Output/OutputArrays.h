// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OutputArrays.h
 * @brief The one table of the tracer's output arrays.
 *
 * Every point array the tracer outputs is a row here: its name, components
 * and value type, which attribute it is (normals, vectors or a plain array),
 * how it is computed, how the Bound Particles display colours by it on the
 * GPU (ColorSource, whose numbers the draw shader gets as #defines from
 * colorSourceDefinitions()), and how its range is known without the
 * particles (for the GPU display's output, which has none). The CPU output,
 * the GPU output's expected ranges, the display's colour modes and the
 * shader's mode numbers all follow from this table.
 *
 * To add an array: add its OutputArrayId (before Count) and its row, in the
 * same order; compute it in Filters/TracerOutputArrays.cxx, in the writer
 * of its ArraySource (a case per id there); give it a RangeSource. To colour by it
 * on the GPU, give it a ColorSource and a case in Shaders/bp_draw_vs_dec.glsl
 * reading engine state the draw shader can fetch (Gpu/GpuEngine.h
 * DrawInputs); otherwise ColorSource::Solid (the display then colours it
 * solid, as for Normals). docs/design.md lists every step.
 */
#ifndef BoundParticles_OutputArrays_h
#define BoundParticles_OutputArrays_h

#include "Engine.h"
#include "VectorField.h"

#include <array>
#include <string>
#include <vector>

namespace bp
{

enum class OutputArrayId
{
  Normals,
  Velocity,
  Speed,
  Force,
  Lifetime,
  ElementId,
  ParticleIndex,
  Vorticity,
  Layer,
  Radius,
  ElementOrientation,
  ElementSpin,
  SpinVorticityRatio,
  Age,
  ElementStretch,
  ElementFTLE,
  ParticleVelocity, ///< a heavy particle's velocity: the flow's plus its slip (Inertia.h)
  SlipVelocity,     ///< its velocity less the flow's; 0 without inertia
  Count ///< not an array: how many there are
};

enum class ValueType
{
  Float,
  IdType,
  Int
};

/// Which attribute the array is: what displays pick by default (ParaView
/// colours a new display by the active scalars).
enum class ArrayRole
{
  Normals,
  Vectors,
  Scalars,
  Plain
};

/// How the CPU output computes the array.
enum class ArraySource
{
  ParticleState, ///< copied from the engine's per-particle state
  FieldSample,   ///< the field sampled at each particle at the output's time
  Derived,       ///< from another array of the same particle
  ElementState,  ///< per element, written on each of its particles
  TemplateIndex, ///< the particle's index in its element's template
  TrailAge       ///< 0 on the elements, how long ago on their trails' poses
};

/// What the GPU display's draw shader colours by (bpScalarMode).
enum class ColorSource
{
  Solid = 0,
  Force,
  Lifetime,
  Velocity, ///< a component, or the magnitude
  Vorticity,
  Layer,
  Radius,
  ElementIndex,
  ParticleIndex,
  Orientation, ///< a component of the pose quaternion, or its magnitude
  Spin,        ///< a component of the spin, or its magnitude
  SpinRatio,   ///< SpinVorticityRatio
  Age,         ///< of a trail's pose (0 on the elements)
  Stretch,     ///< ElementStretch: a component (largest, smallest), or the magnitude
  Ftle,        ///< ElementFTLE
  Slip,        ///< SlipVelocity: a component, or the magnitude (0 without inertia)
  ParticleVelocity, ///< Velocity plus the slip: a component, or the magnitude
  Count
};

/// How an array's range is known without the particles.
enum class RangeSource
{
  UnitComponents, ///< [-1, 1]
  SignedSpeed,    ///< [-max speed, max speed]
  Speed,          ///< [0, max speed]
  Vorticity,      ///< [0, the field's largest |curl v| on a lattice of its points]
  StepMotion,     ///< [0, dt * max speed]: the largest relative motion in a step
  Lifetime,       ///< [0, largest lifetime]
  EmitterAxis,    ///< the emitter box along the colouring axis
  EmitterRadius,  ///< [0, farthest emitter corner from the colouring axis]
  Elements,       ///< [0, elements - 1]
  Particles,      ///< [0, template particles - 1]
  HalfVorticity,  ///< [-max |curl v| / 2, max |curl v| / 2]: a fluid parcel's spin
  SpinRatio,      ///< [-MaxSpinVorticityRatio, MaxSpinVorticityRatio]
  TrailAge,       ///< [0, trail length * trail interval]
  Stretch,        ///< [0, 2]: about 1, unstretched (a colour map's span, not a bound)
  Ftle            ///< [0, max |curl v|]: the flow's rate (a colour map's span, not a bound)
};

struct OutputArray
{
  OutputArrayId id;
  const char* name;
  int components;
  ValueType type;
  ArrayRole role;
  ArraySource source;
  ColorSource color;    ///< Solid: the GPU display cannot colour by it
  bool colorsMagnitude; ///< colours the magnitude of a vector's colour source
  RangeSource range;
  /// Ticked in Output Arrays by default: the pose arrays are not, since
  /// they make the CPU engine fit every element every step (trackPoses),
  /// nor the deformation arrays (a fit per element every output).
  bool onByDefault;
  /// Needs Parameters::trackPoses.
  bool needsPoses;
};

/// Every output array, in output order.
const std::vector<OutputArray>& outputArrays();
const OutputArray& outputArray(OutputArrayId id);
/// The row named `name`, or null.
const OutputArray* findOutputArray(const std::string& name);

/// The centre of the Radius colouring: the middle of `bounds` (xmin, xmax,
/// ymin, ...) along the two axes other than `axis`, (axis + 1) % 3 then
/// (axis + 2) % 3. The CPU output, the expected ranges and the GPU display's
/// draw settings all take it from here.
std::array<double, 2> radialCenter(const std::array<double, 6>& bounds, int axis);

/// "#define BP_COLOR_FORCE 1" and so on, one line per ColorSource.
std::string colorSourceDefinitions();

/// What the ranges depend on.
struct RangeFacts
{
  double maxSpeed = 0.0;
  double maxVorticity = 0.0;
  double dt = 0.0;
  double lifetimeMax = 0.0;
  std::array<double, 2> emitterAxis = { 0, 0 }; ///< world coordinates
  double emitterRadius = 0.0;
  double elements = 1.0;
  double particlesPerElement = 1.0;
  double trailSpan = 0.0; ///< trail length * interval: the oldest pose's age
};

/// The facts of a configured trace: `offset` is the world position of the
/// grid-local origin, `axis` the colouring axis, `bounds` the whole field's
/// grid-local bounds.
RangeFacts rangeFactsOf(const VectorField& field, const Parameters& p, double dt, int axis,
  const std::array<double, 3>& offset, const std::array<double, 6>& bounds,
  std::size_t particlesPerElement);

/// The range `array` is expected to span (every component).
std::array<double, 2> expectedRange(const OutputArray& array, const RangeFacts& facts);

} // namespace bp

#endif
