// SPDX-License-Identifier: BSD-3-Clause
#include "TraceSettings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{
namespace
{
double diagonalOf(const std::array<double, 6>& b)
{
  return std::sqrt(std::pow(b[1] - b[0], 2) + std::pow(b[3] - b[2], 2) + std::pow(b[5] - b[4], 2));
}

/// The emitter box in grid-local coordinates. With Reset When = Any Particle
/// Leaves elements are placed whole inside the field, so no particle is ever
/// advected from outside it: centres keep one element radius from the bounds.
void resolveEmitter(const TraceSettings& s, const FieldFacts& f, Resolution& r)
{
  Parameters& p = r.parameters;
  for (int a = 0; a < 3; ++a)
  {
    const bool whole = s.emitterSize[a] < 0.0;
    const double center = s.emitterCenter[a] - f.offset[a];
    const double lo = whole ? f.bounds[2 * a] : center - 0.5 * s.emitterSize[a];
    const double hi = whole ? f.bounds[2 * a + 1] : center + 0.5 * s.emitterSize[a];
    p.emitterMin[a] = float(lo);
    p.emitterMax[a] = float(hi);
    if (s.engine.resetWhen != ResetWhen::AnyParticleLeaves || f.dims[a] <= 1)
    {
      continue;
    }
    const double radius = 0.5 * r.elementSize;
    const double inLo = f.bounds[2 * a] + radius, inHi = f.bounds[2 * a + 1] - radius;
    if (inLo > inHi)
    {
      std::ostringstream w;
      w << "Elements of size " << r.elementSize << " do not fit in the field along "
        << "XYZ"[a]
        << "; with Reset When = Any Particle Leaves they are reset every step. Choose a "
           "smaller Element Size.";
      r.warnings.push_back(w.str());
      continue;
    }
    p.emitterMin[a] = float(std::min(std::max(lo, inLo), inHi));
    p.emitterMax[a] = float(std::max(std::min(hi, inHi), inLo));
  }
}

/// (0, 0) picks half to all of the animation's span (or of 100 steps when
/// the span is empty).
void resolveLifetimes(const TraceSettings& s, const FieldFacts& f, Resolution& r)
{
  double lifetime[2] = { s.lifetimeRange[0], s.lifetimeRange[1] };
  if (lifetime[0] == 0.0 && lifetime[1] == 0.0)
  {
    const double scale = f.timeSpan > 0.0 ? f.timeSpan : 100.0 * r.dt;
    lifetime[0] = 0.5 * scale;
    lifetime[1] = scale;
  }
  r.parameters.lifetimeMin = float(lifetime[0]);
  r.parameters.lifetimeMax = float(lifetime[1]);
}

Resolution failure(const std::string& message)
{
  Resolution r;
  r.error = message;
  return r;
}
} // namespace

Resolution resolveSettings(const TraceSettings& s, const FieldFacts& f)
{
  Resolution r;
  if (!(s.stepSize > 0.0) || !std::isfinite(s.stepSize))
  {
    return failure("StepSize must be positive (it is " + std::to_string(s.stepSize) + ").");
  }
  double speed = f.maxSpeed;
  if (!(speed > 0.0))
  {
    r.warnings.push_back("The vector field is zero everywhere at the start time; elements will "
                         "not move until it is not.");
    speed = 1.0;
  }
  r.dt = s.stepInCellLengths ? s.stepSize * f.cellLength / speed : s.stepSize;
  if (s.elementSize < 0.0 || !std::isfinite(s.elementSize))
  {
    return failure("ElementSize must be positive, or 0 for automatic.");
  }
  r.elementSize =
    s.elementSize > 0.0 ? s.elementSize : std::max(2.0 * f.cellLength, diagonalOf(f.bounds) / 40.0);
  if (s.numberOfElements < 1)
  {
    return failure(
      "NumberOfElements must be at least 1 (it is " + std::to_string(s.numberOfElements) + ").");
  }
  for (double angle : s.rotationDegrees)
  {
    if (!std::isfinite(angle))
    {
      return failure("ElementRotation must be finite.");
    }
  }
  r.parameters = s.engine;
  r.parameters.numberOfElements = std::size_t(s.numberOfElements);
  r.parameters.frame =
    rotationFromDegrees(s.rotationDegrees[0], s.rotationDegrees[1], s.rotationDegrees[2]);
  r.parameters.elementSize = float(r.elementSize);
  resolveEmitter(s, f, r);
  resolveLifetimes(s, f, r);
  return r;
}

} // namespace bp
