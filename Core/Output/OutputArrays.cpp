// SPDX-License-Identifier: BSD-3-Clause
#include "OutputArrays.h"

#include "Pose.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{

namespace
{
/// The flags that end a row, by name; a row combines them with | (NoFlags:
/// the colour source as it is, on by default, no poses needed).
enum RowFlag : unsigned
{
  NoFlags = 0,
  ColorsMagnitude = 1u << 0, ///< OutputArray::colorsMagnitude
  OffByDefault = 1u << 1,    ///< not OutputArray::onByDefault
  NeedsPoses = 1u << 2       ///< OutputArray::needsPoses
};

OutputArray row(OutputArrayId id, const char* name, int components, ValueType type, ArrayRole role,
  ArraySource source, ColorSource color, RangeSource range, unsigned flags)
{
  return { id, name, components, type, role, source, color, (flags & ColorsMagnitude) != 0, range,
    (flags & OffByDefault) == 0, (flags & NeedsPoses) != 0 };
}
} // namespace

const std::vector<OutputArray>& outputArrays()
{
  using Id = OutputArrayId;
  using V = ValueType;
  using Role = ArrayRole;
  using Src = ArraySource;
  using C = ColorSource;
  using R = RangeSource;
  // id, name, components, value type, role, source, colour source, range source, flags.
  static const std::vector<OutputArray> table = {
    row(Id::Normals, "Normals", 3, V::Float, Role::Normals, Src::ParticleState, C::Solid,
      R::UnitComponents, NoFlags),
    row(Id::Velocity, "Velocity", 3, V::Float, Role::Vectors, Src::FieldSample, C::Velocity,
      R::SignedSpeed, NoFlags),
    row(Id::Speed, "Speed", 1, V::Float, Role::Scalars, Src::Derived, C::Velocity, R::Speed,
      ColorsMagnitude),
    row(Id::Force, "Force", 1, V::Float, Role::Plain, Src::ParticleState, C::Force, R::StepMotion,
      NoFlags),
    row(Id::Lifetime, "Lifetime", 1, V::Float, Role::Plain, Src::ElementState, C::Lifetime,
      R::Lifetime, NoFlags),
    row(Id::ElementId, "ElementId", 1, V::IdType, Role::Plain, Src::ElementState, C::ElementIndex,
      R::Elements, NoFlags),
    row(Id::ParticleIndex, "ParticleIndex", 1, V::Int, Role::Plain, Src::TemplateIndex,
      C::ParticleIndex, R::Particles, NoFlags),
    row(Id::Vorticity, "Vorticity", 1, V::Float, Role::Plain, Src::FieldSample, C::Vorticity,
      R::Vorticity, NoFlags),
    row(Id::Layer, "Layer", 1, V::Float, Role::Plain, Src::ElementState, C::Layer, R::EmitterAxis,
      NoFlags),
    row(Id::Radius, "Radius", 1, V::Float, Role::Plain, Src::ElementState, C::Radius,
      R::EmitterRadius, NoFlags),
    // The pose arrays make the CPU engine fit every element every step.
    row(Id::ElementOrientation, "Orientation", 4, V::Float, Role::Plain, Src::ElementState,
      C::Orientation, R::UnitComponents, OffByDefault | NeedsPoses),
    row(Id::ElementSpin, "ElementSpin", 3, V::Float, Role::Plain, Src::ElementState, C::Spin,
      R::HalfVorticity, OffByDefault | NeedsPoses),
    row(Id::SpinVorticityRatio, "SpinVorticityRatio", 1, V::Float, Role::Plain, Src::ElementState,
      C::SpinRatio, R::SpinRatio, OffByDefault | NeedsPoses),
    row(Id::Age, "Age", 1, V::Float, Role::Plain, Src::TrailAge, C::Age, R::TrailAge, NoFlags),
    // Deformation: a fit per element per output (Core/Elements/ElementStretch.h).
    row(Id::ElementStretch, "ElementStretch", 2, V::Float, Role::Plain, Src::ElementState,
      C::Stretch, R::Stretch, OffByDefault),
    row(Id::ElementFTLE, "ElementFTLE", 1, V::Float, Role::Plain, Src::ElementState, C::Ftle,
      R::Ftle, OffByDefault),
    // Heavy particles (Inertia.h): the slip, 0 without inertia.
    row(Id::ParticleVelocity, "ParticleVelocity", 3, V::Float, Role::Plain, Src::Derived,
      C::ParticleVelocity, R::SignedSpeed, OffByDefault),
    row(Id::SlipVelocity, "SlipVelocity", 3, V::Float, Role::Plain, Src::ParticleState, C::Slip,
      R::SignedSpeed, OffByDefault),
  };
  return table;
}

std::array<double, 2> radialCenter(const std::array<double, 6>& bounds, int axis)
{
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return { 0.5 * (bounds[2 * u] + bounds[2 * u + 1]), 0.5 * (bounds[2 * v] + bounds[2 * v + 1]) };
}

const OutputArray& outputArray(OutputArrayId id)
{
  return outputArrays()[std::size_t(id)];
}

const OutputArray* findOutputArray(const std::string& name)
{
  for (const OutputArray& a : outputArrays())
  {
    if (name == a.name)
    {
      return &a;
    }
  }
  return nullptr;
}

std::string colorSourceDefinitions()
{
  static const char* const names[] = { "SOLID", "FORCE", "LIFETIME", "VELOCITY", "VORTICITY",
    "LAYER", "RADIUS", "ELEMENT_INDEX", "PARTICLE_INDEX", "ORIENTATION", "SPIN", "SPIN_RATIO",
    "AGE", "STRETCH", "FTLE", "SLIP", "PARTICLE_VELOCITY" };
  static_assert(sizeof(names) / sizeof(names[0]) == std::size_t(ColorSource::Count),
    "a name per colour source");
  std::ostringstream out;
  for (int k = 0; k < int(ColorSource::Count); ++k)
  {
    out << "#define BP_COLOR_" << names[k] << " " << k << "\n";
  }
  return out.str();
}

namespace
{
/// The largest |curl v| at the start time on a lattice of at most 32^3 of
/// the field's points (the cell gradient, as the Vorticity array).
double latticeVorticity(const VectorField& field)
{
  const GridGeometry& g = field.grid();
  float vorticity = 0.0f;
  int stride[3];
  for (int a = 0; a < 3; ++a)
    stride[a] = std::max(1, g.dims[a] / 32);
  for (int k = 0; k < g.dims[2]; k += stride[2])
    for (int j = 0; j < g.dims[1]; j += stride[1])
      for (int i = 0; i < g.dims[0]; i += stride[0])
      {
        const float q[3] = { float(g.coordinate(0, i)), float(g.coordinate(1, j)),
          float(g.coordinate(2, k)) };
        vorticity = std::max(vorticity, field.vorticityMagnitude(q, field.firstSlice().time));
      }
  return double(vorticity);
}
} // namespace

RangeFacts rangeFactsOf(const VectorField& field, const Parameters& p, double dt, int axis,
  const std::array<double, 3>& offset, const std::array<double, 6>& bounds,
  std::size_t particlesPerElement)
{
  RangeFacts f;
  f.maxSpeed = field.maxSpeed();
  f.maxVorticity = latticeVorticity(field);
  f.dt = dt;
  f.lifetimeMax = p.lifetimeMax;
  f.emitterAxis = { p.emitterMin[axis] + offset[axis], p.emitterMax[axis] + offset[axis] };
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const std::array<double, 2> centre = radialCenter(bounds, axis);
  const double cu = centre[0], cv = centre[1];
  for (int corner = 0; corner < 4; ++corner)
  {
    const double x = (corner & 1) ? p.emitterMax[u] : p.emitterMin[u];
    const double y = (corner & 2) ? p.emitterMax[v] : p.emitterMin[v];
    f.emitterRadius = std::max(f.emitterRadius, std::hypot(x - cu, y - cv));
  }
  f.elements = double(p.numberOfElements);
  f.particlesPerElement = double(particlesPerElement);
  f.trailSpan = std::max(p.trailLength, 0) * p.trailInterval;
  return f;
}

std::array<double, 2> expectedRange(const OutputArray& array, const RangeFacts& f)
{
  switch (array.range)
  {
    case RangeSource::UnitComponents:
      return { -1.0, 1.0 };
    case RangeSource::SignedSpeed:
      return { -f.maxSpeed, f.maxSpeed };
    case RangeSource::Speed:
      return { 0.0, f.maxSpeed };
    case RangeSource::Vorticity:
      return { 0.0, f.maxVorticity };
    case RangeSource::StepMotion:
      return { 0.0, f.dt * f.maxSpeed };
    case RangeSource::Lifetime:
      return { 0.0, f.lifetimeMax };
    case RangeSource::EmitterAxis:
      return f.emitterAxis;
    case RangeSource::EmitterRadius:
      return { 0.0, f.emitterRadius };
    case RangeSource::Elements:
      return { 0.0, f.elements - 1.0 };
    case RangeSource::Particles:
      return { 0.0, f.particlesPerElement - 1.0 };
    case RangeSource::HalfVorticity:
      return { -0.5 * f.maxVorticity, 0.5 * f.maxVorticity };
    case RangeSource::SpinRatio:
      return { -double(MaxSpinVorticityRatio), double(MaxSpinVorticityRatio) };
    case RangeSource::TrailAge:
      return { 0.0, f.trailSpan };
    case RangeSource::Stretch:
      return { 0.0, 2.0 };
    case RangeSource::Ftle:
      return { 0.0, f.maxVorticity };
  }
  return { 0.0, 1.0 };
}

} // namespace bp
