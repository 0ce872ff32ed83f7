// SPDX-License-Identifier: BSD-3-Clause
#include "TraceSettings.h"

#include "ElementStretch.h"
#include "Quaternion.h"

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
  if (s.emitterSize[0] == 0.0 && s.emitterSize[1] == 0.0 && s.emitterSize[2] == 0.0)
  {
    // ParaView 6 gives a tracer made before its input has run a box of size
    // 0 at the origin: say what that does rather than trace from one point.
    std::ostringstream w;
    w << "The emitter box has size 0 along every axis: every element is released at ("
      << s.emitterCenter[0] << ", " << s.emitterCenter[1] << ", " << s.emitterCenter[2]
      << "). Give Emitter Size a negative value to span the field, or press Reset Bounds.";
    r.warnings.push_back(w.str());
  }
}

/// An error when the emitter box misses the field on an axis: elements
/// placed there would be reset forever and never be seen in the flow.
std::string checkEmitter(const TraceSettings& s, const FieldFacts& f, const Parameters& p)
{
  for (int a = 0; a < 3; ++a)
  {
    if (!std::isfinite(s.emitterCenter[a]) || !std::isfinite(s.emitterSize[a]))
    {
      return "The emitter box must be finite: EmitterCenter and EmitterSize hold a NaN or Inf.";
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    // A flat axis (one point) has no extent to miss; a super set lives out
    // its lifetime wherever it goes, but still starts in the field.
    const double lo = f.bounds[2 * a], hi = f.bounds[2 * a + 1];
    const double slack = 1e-9 * std::max(1.0, hi - lo);
    if (f.dims[a] > 1 && (p.emitterMax[a] < lo - slack || p.emitterMin[a] > hi + slack))
    {
      std::ostringstream err;
      err << "The emitter box (" << p.emitterMin[a] + f.offset[a] << " to "
          << p.emitterMax[a] + f.offset[a] << " along "
          << "XYZ"[a] << ") lies outside the field (" << lo + f.offset[a] << " to "
          << hi + f.offset[a]
          << "); move it into the field, or give a negative EmitterSize to span the field.";
      return err.str();
    }
  }
  return std::string();
}

/// Release Pattern = Lattice: the lattice over the emitter box (flat on a
/// flat field's plane), whose size is the element count; seed points win.
std::string resolveLattice(const TraceSettings& s, const FieldFacts& f, Resolution& r)
{
  Parameters& p = r.parameters;
  if (s.weighted && (s.seeded || p.releasePattern == ReleasePattern::Lattice))
  {
    r.warnings.push_back(std::string("Release Weights is not used: releases take ") +
      (s.seeded ? "the seed points (Seed Source or Seed Type)."
                : "the lattice's points (Release Pattern)."));
  }
  if (p.releasePattern != ReleasePattern::Lattice)
  {
    return std::string();
  }
  if (s.seeded)
  {
    r.warnings.push_back("Release Pattern = Lattice is not used: releases take the seed "
                         "points (Seed Source or Seed Type).");
    p.releasePattern = ReleasePattern::Random;
    return std::string();
  }
  if (!(s.latticeSpacing >= 0.0) || !std::isfinite(s.latticeSpacing))
  {
    return "LatticeSpacing must be positive, or 0 for automatic (from Number Of Elements).";
  }
  std::array<float, 3> lo = p.emitterMin, hi = p.emitterMax;
  for (int a = 0; a < 3; ++a)
  {
    if (f.dims[a] <= 1)
    {
      lo[a] = hi[a] = float(f.bounds[2 * a]);
    }
  }
  p.lattice = releaseLattice(lo, hi, p.numberOfElements, s.latticeSpacing);
  const std::size_t asked = p.numberOfElements;
  p.numberOfElements = p.lattice.size();
  if (s.latticeSpacing > 0.0 && p.numberOfElements >= LatticeOverrunWarning * asked)
  {
    // A set spacing decides the count: say so when it is far from the one asked.
    std::ostringstream w;
    w << "LatticeSpacing " << s.latticeSpacing << " gives a lattice of " << p.numberOfElements
      << " points (" << p.lattice.counts[0] << " x " << p.lattice.counts[1] << " x "
      << p.lattice.counts[2] << "), an element each: " << p.numberOfElements / asked
      << " times Number Of Elements (" << asked
      << "). Raise LatticeSpacing, or set it to 0 to release Number Of Elements on the lattice.";
    r.warnings.push_back(w.str());
  }
  return std::string();
}

double longestSide(const FieldFacts& f)
{
  return std::max(
    { f.bounds[1] - f.bounds[0], f.bounds[3] - f.bounds[2], f.bounds[5] - f.bounds[4] });
}

/// The time the top speed (Resolution::speed) takes to cross the field's
/// longest side; 0 where nothing moves.
double crossingTime(const FieldFacts& f, double speed)
{
  const double longest = longestSide(f);
  return speed > 0.0 && longest > 0.0 ? longest / speed : 0.0;
}

/// (0, 0) picks half to all of T: the time the fastest flow takes to cross
/// the field, within the animation's span (or 100 steps when both are
/// empty). Elements are renewed before they pile up where the flow is slow.
/// An error names the setting that made them unusable.
std::string resolveLifetimes(const TraceSettings& s, const FieldFacts& f, Resolution& r)
{
  double lifetime[2] = { s.lifetimeRange[0], s.lifetimeRange[1] };
  const bool automatic = lifetime[0] == 0.0 && lifetime[1] == 0.0;
  if (automatic)
  {
    const double crossing = crossingTime(f, r.speed);
    double scale = f.timeSpan > 0.0 ? f.timeSpan : 100.0 * r.dt;
    scale = crossing > 0.0 ? std::min(scale, crossing) : scale;
    lifetime[0] = 0.5 * scale;
    lifetime[1] = scale;
  }
  r.parameters.lifetimeMin = float(lifetime[0]);
  r.parameters.lifetimeMax = float(lifetime[1]);
  const bool usable = r.parameters.lifetimeMin > 0.0f && std::isfinite(r.parameters.lifetimeMax);
  if (automatic && !usable)
  {
    std::ostringstream err;
    err << "The animation's time span (" << f.timeSpan
        << ") gives automatic lifetimes that are not usable (" << lifetime[0] << " to "
        << lifetime[1]
        << "); set LifetimeRange, or for a steady input a Duration between 1e-30 and 1e30.";
    return err.str();
  }
  return std::string();
}

/// On a flat field (one axis of one point) Random and Along Flow turn the
/// elements about that axis only, the template's x-y plane laid into the
/// field's plane, so that strips are not seen edge-on.
void resolvePlane(const FieldFacts& f, Parameters& p)
{
  int flat = -1, flatAxes = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (f.dims[a] <= 1)
    {
      flat = a;
      ++flatAxes;
    }
  }
  if (p.orientation == Orientation::Fixed || flatAxes != 1)
  {
    return;
  }
  p.planeAxis = flat;
  // The template's normal (z) onto the flat axis: x-y stays, x-z is a turn
  // of -90 degrees about x, y-z one of 90 degrees about y.
  p.frame = flat == 2 ? rotationFromDegrees(0, 0, 0)
    : flat == 1       ? rotationFromDegrees(-90, 0, 0)
                      : rotationFromDegrees(0, 90, 0);
}

/// A flat field (one point along an axis) keeps its elements in its plane:
/// the velocity's crossing component is dropped as it is read
/// (dropFlatComponents), and so is Gravity's here, or heavy particles would
/// fall out of the plane and never come back. A non-finite component is
/// kept for Engine::validate to name. Said only where gravity acts (a heavy
/// particle's trace).
void resolveGravity(const FieldFacts& f, Parameters& p, std::vector<std::string>& warnings)
{
  std::string axes;
  std::ostringstream dropped;
  for (int a = 0; a < 3; ++a)
  {
    const float g = p.gravity[a];
    if (f.dims[a] <= 1 && g != 0.0f && std::isfinite(g))
    {
      const std::string joint = axes.empty() ? "" : " and ";
      axes += joint + "XYZ"[a];
      dropped << joint << g << " along "
              << "XYZ"[a];
      p.gravity[a] = 0.0f;
    }
  }
  if (axes.empty() || !carriesInertia(p))
  {
    return;
  }
  const bool none = p.gravity[0] == 0.0f && p.gravity[1] == 0.0f && p.gravity[2] == 0.0f;
  std::ostringstream w;
  w << "The field is flat along " << axes << " (one point) but Gravity crosses its plane ("
    << dropped.str()
    << "): elements stay in the plane, so that component is dropped and Gravity in the plane is ("
    << p.gravity[0] << ", " << p.gravity[1] << ", " << p.gravity[2] << ")"
    << (none ? ": heavy particles lag the flow but do not fall." : ".");
  warnings.push_back(w.str());
}

/// The warning of an unsteady field whose typical speed crosses more than
/// UnitsWarningShare of it and more than UnitsWarningCells cells between two
/// input time steps; empty otherwise.
std::string unitsPerInterval(const std::vector<double>& inputTimes, const TimeScale& scale)
{
  double longest = 0.0;
  for (std::size_t k = 1; k < inputTimes.size(); ++k)
  {
    longest = std::max(longest, inputTimes[k] - inputTimes[k - 1]);
  }
  const double travel = scale.typicalSpeed * longest;
  const double share = scale.extent > 0.0 ? travel / scale.extent : 0.0;
  const double cells = scale.cellLength > 0.0 ? travel / scale.cellLength : 0.0;
  if (!(share > UnitsWarningShare && cells > UnitsWarningCells) || !std::isfinite(share))
  {
    return std::string();
  }
  std::ostringstream w;
  w << "At the field's typical speed (" << scale.typicalSpeed
    << ": 90% of its moving points are slower) an element crosses "
    << int(std::round(100.0 * std::min(share, 1e6))) << "% of the field (" << scale.extent
    << " long), " << std::round(std::min(cells, 1e12)) << " cells of " << scale.cellLength
    << ", between two input time steps (" << longest
    << " apart), so the trace crumples: the velocity's units may not match the grid's or the "
       "time's (e.g. m/s on a grid in degrees, with time in hours). Pick Vectors in the grid's "
       "units per time unit, or convert them with a Calculator; Step Size in Time units then "
       "steps in the data's own time.";
  return w.str();
}

/// Gravity's settling over the longest lifetime, when it carries a particle
/// more than GravityWarningFields times the field's longest side. Automatic
/// lifetimes follow gravity where it is faster than the flow, so there it is
/// the settling over the time the flow takes to cross the field (about the
/// settling speed over the flow's, in fields); in still fluid (a flow
/// StillFlowRatio times slower than gravity's motion, or none) settling is
/// what heavy particles do, and nothing is said.
void checkGravityUnits(
  const TraceSettings& s, const FieldFacts& f, const GravityMotion& motion, Resolution& r)
{
  const Parameters& p = r.parameters;
  const double longest = longestSide(f);
  const bool automatic = s.lifetimeRange[0] == 0.0 && s.lifetimeRange[1] == 0.0;
  if (automatic && !(f.maxSpeed * StillFlowRatio > motion.speed))
  {
    return;
  }
  const double over = automatic ? crossingTime(f, f.maxSpeed) : double(p.lifetimeMax);
  const double settling = settlingDistance(p, over);
  // A gravity that is not finite is refused by validate(), with its own message.
  if (!(longest > 0.0) || !(settling > GravityWarningFields * longest) || !std::isfinite(settling))
  {
    return;
  }
  std::ostringstream w;
  w << "Gravity (" << p.gravity[0] << ", " << p.gravity[1] << ", " << p.gravity[2]
    << ") alone carries a particle " << settling
    << (automatic ? " in the time the flow takes to cross the field ("
                  : " over its longest lifetime (")
    << over << "), " << std::round(std::min(settling / longest, 1e12))
    << " times the field's longest side (" << longest << "; Response Time " << p.responseTime
    << " and Density Ratio " << p.densityRatio << " settle it at " << terminalSettlingSpeed(p)
    << "): Gravity may not be in the data's units, length per time unit squared (9.81 m/s^2 "
       "is 1.27e5 km/h^2, and 9810 in mm/s^2). Convert it, or check Response Time.";
  r.warnings.push_back(w.str());
}

Resolution failure(const std::string& message)
{
  Resolution r;
  r.error = message;
  return r;
}
} // namespace

EmitterBox emitterInChangedField(
  const TraceSettings& settings, const FieldFacts& field, double elementSize)
{
  Resolution r;
  r.elementSize = elementSize;
  resolveEmitter(settings, field, r);
  EmitterBox box;
  box.min = r.parameters.emitterMin;
  box.max = r.parameters.emitterMax;
  std::string missed;
  for (int a = 0; a < 3; ++a)
  {
    if (field.dims[a] <= 1)
    {
      continue;
    }
    const float lo = float(field.bounds[2 * a]), hi = float(field.bounds[2 * a + 1]);
    if (box.max[a] < lo || box.min[a] > hi)
    {
      missed += std::string(missed.empty() ? "" : " and ") + "XYZ"[a];
      box.min[a] = lo;
      box.max[a] = hi;
      continue;
    }
    box.min[a] = std::max(box.min[a], lo);
    box.max[a] = std::min(box.max[a], hi);
  }
  if (!missed.empty())
  {
    std::ostringstream w;
    w << "The emitter box (EmitterCenter " << settings.emitterCenter[0] << " "
      << settings.emitterCenter[1] << " " << settings.emitterCenter[2] << ", EmitterSize "
      << settings.emitterSize[0] << " " << settings.emitterSize[1] << " " << settings.emitterSize[2]
      << ") lies outside the new grid along " << missed << ": releases span the new grid along "
      << (missed.size() > 1 ? "them" : "it") << " until the box meets the grid again.";
    box.warning = w.str();
  }
  return box;
}

GravityMotion gravityMotion(const Parameters& engine, const FieldFacts& field)
{
  Parameters p = engine;
  for (int a = 0; a < 3; ++a)
  {
    // As resolveGravity: a flat field's elements do not fall across its plane.
    p.gravity[a] = field.dims[a] <= 1 ? 0.0f : p.gravity[a];
  }
  GravityMotion motion;
  motion.time = settlingTime(p, longestSide(field));
  motion.speed = settlingSpeedAfter(p, motion.time);
  if (!(motion.speed > 0.0) || !std::isfinite(motion.speed))
  {
    motion = GravityMotion();
  }
  return motion;
}

/// A Response Time far below the resolved step: said, since the trace is
/// then close to massless.
static void noteNearlyMassless(Resolution& r)
{
  if (nearlyMassless(r.parameters, r.dt))
  {
    std::ostringstream w;
    w << "Response Time " << r.parameters.responseTime << " is far below the step (" << r.dt
      << "): the particles keep up with the flow within the step, so the trace is close to "
         "massless (Inertia = None traces the same, faster).";
    r.warnings.push_back(w.str());
  }
}

Resolution resolveSettings(const TraceSettings& s, const FieldFacts& f)
{
  Resolution r;
  const std::string refused = checkTimeDirection(s.timeDirection, s.engine);
  if (!refused.empty() || !(s.stepSize > 0.0) || !std::isfinite(s.stepSize))
  {
    return failure(!refused.empty()
        ? refused
        : "StepSize must be positive (it is " + std::to_string(s.stepSize) + ").");
  }
  // Heavy particles move by gravity too: the step and automatic lifetimes
  // follow the faster of the two (settling through still fluid, or noise).
  const GravityMotion motion = gravityMotion(s.engine, f);
  double speed = std::max(f.maxSpeed, motion.speed);
  r.speed = speed;
  if (!(speed > 0.0))
  {
    r.warnings.push_back("The vector field is zero everywhere at the start time; elements will "
                         "not move until it is not.");
    speed = 1.0;
  }
  r.dt = s.stepInCellLengths ? s.stepSize * f.cellLength / speed : s.stepSize;
  if (!(r.dt > 0.0) || !std::isfinite(r.dt))
  {
    std::ostringstream err;
    err << "The time step (StepSize " << s.stepSize << (s.stepInCellLengths ? " cell lengths" : "")
        << " at a top speed of " << f.maxSpeed << ") comes to " << r.dt
        << ", which cannot step; check the velocity's units or set StepSize in time units.";
    return failure(err.str());
  }
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
  resolvePlane(f, r.parameters);
  resolveGravity(f, r.parameters, r.warnings);
  r.parameters.elementSize = float(r.elementSize);
  if (!s.seeded && !(s.minimumReleaseSpeed >= 0.0 && s.minimumReleaseSpeed <= 1.0))
  {
    return failure("MinimumReleaseSpeed must be a fraction of the top speed in [0, 1].");
  }
  // The user chose where seeded releases land: none is retried for its speed.
  r.parameters.releaseMinSpeed =
    s.seeded ? 0.0f : float(s.minimumReleaseSpeed * std::max(f.maxSpeed, 0.0));
  if (s.trailLength < 0 || s.trailLength > MaxTrailLength)
  {
    return failure("TrailLength must be in [1, " + std::to_string(MaxTrailLength) +
      "] poses (it is " + std::to_string(s.trailLength) + ").");
  }
  if (s.trailLength > 0 && (s.trailSpacing < 1 || s.trailSpacing > MaxTrailSpacing))
  {
    return failure("TrailSpacing must be in [1, " + std::to_string(MaxTrailSpacing) +
      "] steps (it is " + std::to_string(s.trailSpacing) + ").");
  }
  // A pose every TrailSpacing steps of the schedule (recordsTrailAt); the
  // schedule's start is the tracer's (Parameters::trailStart).
  r.parameters.ftleMinimumAge = MinimumFtleSteps * r.dt;
  r.parameters.trailLength = s.trailLength;
  r.parameters.trailInterval = s.trailSpacing * r.dt;
  if (!s.seeded)
  {
    resolveEmitter(s, f, r);
    const std::string emitterError = checkEmitter(s, f, r.parameters);
    if (!emitterError.empty())
    {
      return failure(emitterError);
    }
  }
  const std::string latticeError = resolveLattice(s, f, r);
  if (!latticeError.empty())
  {
    return failure(latticeError);
  }
  const std::string lifetimeError = resolveLifetimes(s, f, r);
  if (!lifetimeError.empty())
  {
    return failure(lifetimeError);
  }
  checkGravityUnits(s, f, motion, r);
  noteNearlyMassless(r);
  return r;
}

TimeLine resolveTimeLine(double duration, int framesPerInterval, int count, double stepSize,
  bool stepInCellLengths, const std::vector<double>& inputTimes, const TimeScale& scale)
{
  TimeLine line;
  line.duration = duration;
  line.framesPerInterval = std::max(framesPerInterval, 1);
  const bool unsteady = inputTimes.size() >= 2;
  const bool automatic = unsteady ? framesPerInterval <= 0 : duration <= 0.0;
  // The flow's top speed, or gravity's motion of heavy particles where faster.
  const double speed = scale.speed();
  const double dt = !scale.valid() ? 0.0
    : stepInCellLengths            ? stepSize * scale.cellLength / speed
                                   : stepSize;
  const bool stepKnown = dt > 0.0 && std::isfinite(dt);
  if (automatic && !unsteady)
  {
    line.duration = FallbackDuration;
    if (stepKnown)
    {
      // A step the user gave in time units is theirs: no cap on the steps.
      const double crossings = AutomaticCrossings * scale.extent / speed;
      const double framed = FrameSteps * std::max(count - 1, 1) * dt;
      line.duration = stepInCellLengths ? std::min(crossings, framed) : crossings;
    }
  }
  if (automatic && unsteady)
  {
    // Enough frames in all for smooth Play (nek_eddy's 11 steps once gave 11).
    const double intervals = double(inputTimes.size() - 1);
    line.framesPerInterval =
      int(std::min(std::ceil((MinAutomaticFrames - 1) / intervals), double(MaxFramesPerInterval)));
  }
  if (automatic && unsteady && stepKnown)
  {
    double longest = 0.0;
    for (std::size_t k = 1; k < inputTimes.size(); ++k)
    {
      longest = std::max(longest, inputTimes[k] - inputTimes[k - 1]);
    }
    const double frames = std::ceil(longest / (FrameSteps * dt) - 1e-9);
    line.framesPerInterval =
      int(std::min(std::max(frames, double(line.framesPerInterval)), double(MaxFramesPerInterval)));
    if (frames > double(MaxFramesPerInterval))
    {
      std::ostringstream w;
      w << "Even at " << MaxFramesPerInterval << " frames per input time step a frame takes up to "
        << std::ceil(longest / (MaxFramesPerInterval * dt))
        << " steps; check the velocity's units, or set Step Size in time units.";
      line.warnings.push_back(w.str());
    }
  }
  const std::string perInterval = unitsPerInterval(inputTimes, scale);
  if (!perInterval.empty())
  {
    line.warnings.push_back(perInterval);
  }
  if (!stepKnown)
  {
    return line;
  }
  // The velocity's scale against the grid's units and the time range.
  const double span = unsteady ? inputTimes.back() - inputTimes.front() : line.duration;
  std::ostringstream w;
  if (scale.maxSpeed * dt > scale.extent)
  {
    w << "At the field's top speed (" << scale.maxSpeed << ") an element crosses the whole field ("
      << scale.extent << " long) in less than one step (" << dt
      << "): the velocity's units may not match the grid's (e.g. m/s on a grid in degrees or "
         "kilometres). Check the units, or set Step Size in Cell Length.";
  }
  else if (span > 0.0 && speed * span < scale.cellLength)
  {
    w << "At the field's top speed (" << scale.maxSpeed << ") an element moves less than one cell ("
      << scale.cellLength << ") over the whole time range (" << span
      << "): the velocity's units may not match the grid's or the time's (e.g. m/s on a grid in "
         "degrees, or time in hours). Check the units"
      << (unsteady ? "." : ", or lengthen Duration.");
  }
  if (!w.str().empty())
  {
    line.warnings.push_back(w.str());
  }
  return line;
}

} // namespace bp
