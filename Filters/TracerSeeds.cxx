// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, the seeds: a Seed Source's or a Seed Type's points
// turned into release centres in engine coordinates, with the warnings that
// say which of them cannot serve. See vtkBoundParticleTracerInternals.h.
#include "vtkBoundParticleTracerInternals.h"

#include "TracerInput.h"
#include "VectorField.h"
#include "vtkBoundParticleSeedType.h"

#include "vtkDataObject.h"
#include "vtkInformationVector.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace
{
/// The share of seed points in still flow that is warned of.
constexpr double StillShareWarning = 0.1;

/// How many seed points could not serve, and why: for the messages.
struct SeedCounts
{
  std::size_t outside = 0;    ///< outside the field's bounds
  std::size_t noFlow = 0;     ///< in a cell outside the flow's domain at the start
  std::size_t nonFinite = 0;  ///< not finite, or too far for the engine's floats
  std::size_t atBoundary = 0; ///< within half an element of the boundary
  std::size_t still = 0;      ///< where the flow is slower than 1% of its top speed
};

/// Point `i` of `xyz` in grid-local floats; false when it is not finite or
/// too far to hold in the engine's floats.
bool localPoint(
  const std::vector<double>& xyz, std::size_t i, const std::array<double, 3>& offset, float x[3])
{
  bool finite = true;
  for (int a = 0; a < 3; ++a)
  {
    const double local = xyz[3 * i + std::size_t(a)] - offset[a];
    finite = finite && std::isfinite(local) && std::abs(local) < 1e30;
    x[a] = finite ? float(local) : 0.0f;
  }
  return finite;
}

/// Whether `x` lies within `radius` of the domain's boundary along an axis
/// that has sides (not flat, not periodic: nothing leaves through a seam).
bool nearBoundary(const bp::Domain& domain, const float x[3], float radius)
{
  bool near = false;
  for (int a = 0; a < 3; ++a)
  {
    near = near ||
      (domain.bounded(a) &&
        (x[a] - domain.lower[a] < radius || domain.upper[a] - x[a] < radius));
  }
  return near;
}

/// Whether the flow at `x` is slower than `stillSpeed` at time `start`.
bool stillAt(const bp::VectorField& field, const float x[3], double start, double stillSpeed)
{
  float v[3];
  field.sample(x, start, v);
  return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]) < stillSpeed;
}

/// Where releases land: the seeds' box (the GPU display's colour ranges of
/// Layer and Radius are taken over the emitter box).
void boxAroundSeeds(bp::Parameters& p)
{
  for (std::size_t i = 0; i < p.seedPoints.size(); ++i)
  {
    const int a = int(i % 3);
    const float x = p.seedPoints[i];
    p.emitterMin[a] = i < 3 ? x : std::min(p.emitterMin[a], x);
    p.emitterMax[a] = i < 3 ? x : std::max(p.emitterMax[a], x);
  }
}

/// The error when no seed point lies in the flow.
std::string noSeedInFlow(const std::string& name, std::size_t used, const SeedCounts& n)
{
  std::ostringstream err;
  err << "None of the " << name << "'s " << used << " points lies in the flow (" << n.outside
      << " outside the field, " << n.noFlow << " in cells outside the flow's domain";
  if (n.nonFinite > 0)
  {
    err << ", " << n.nonFinite << " not finite";
  }
  err << "): no element can be released. Move the seeds into the field.";
  return err.str();
}

/// The warnings about seed points that serve badly or not at all.
void warnOfSeeds(vtkObject* owner, const bpvtk::TracerSeeds& seeds, std::size_t used,
  const SeedCounts& n, const bp::Parameters& p)
{
  const std::string& name = seeds.name;
  if (n.outside + n.nonFinite > 0)
  {
    vtkWarningWithObjectMacro(
      owner, << n.outside + n.nonFinite << " of the " << name << "'s " << used
             << " points lie outside the field" << (n.nonFinite ? " or are not finite" : "")
             << "; releases take only the other " << p.seedPoints.size() / 3 << ".");
  }
  // A wall (Stick, Slip, Bounce) keeps particles in: none leaves at once.
  if (n.atBoundary > 0 && p.resetWhen == bp::ResetWhen::AnyParticleLeaves &&
    !bp::isWall(p.boundary))
  {
    vtkWarningWithObjectMacro(
      owner, << n.atBoundary << " of the " << name << "'s points lie within half an element of the "
             << "field's boundary: with Reset When = Any Particle Leaves, elements released there "
             << "leave at once and "
             << (p.boundary == bp::Boundary::Terminate ? "are hidden until their lifetime ends"
                                                       : "are released again every step")
             << ". Move the seeds inward, or reset when the centre leaves.");
  }
  const std::size_t kept = p.seedPoints.size() / 3;
  // A few seeds in still flow are the flow's business; a share that changes
  // the picture is said.
  if (n.still > n.noFlow && double(n.still - n.noFlow) >= StillShareWarning * double(kept))
  {
    vtkWarningWithObjectMacro(
      owner, << n.still - n.noFlow << " of the " << name << "'s " << kept
             << " points in the flow lie where it is slower than 1% of its top speed at the start: "
                "elements released there barely move. Move the seeds into faster flow.");
  }
  if (p.numberOfElements > 2 * kept)
  {
    vtkWarningWithObjectMacro(
      owner, << p.numberOfElements << " elements share the " << name << "'s " << kept
             << " points: about " << (p.numberOfElements + kept - 1) / kept
             << " start at each point, on top of one another. " << seeds.advice);
  }
  if (n.noFlow > 0)
  {
    vtkWarningWithObjectMacro(owner,
      << n.noFlow << " of the " << name << "'s points lie in cells outside the flow's domain "
      << "(vtkValidPointMask 0 or a non-finite vector) at the start; releases pass over them "
      << "to the next point in the flow.");
  }
}
} // namespace

std::string vtkBoundParticleTracerInternals::readSeeds(
  const Config& config, vtkInformationVector** inputVector, std::vector<double>& xyz) const
{
  xyz.clear();
  if (!config.seedSource)
  {
    return std::string();
  }
  std::string error = bpvtk::appendSeedPoints(vtkDataObject::GetData(inputVector[2], 0), xyz);
  if (!this->Layout.distributed())
  {
    return error;
  }
  // Collective from here: every process takes part whatever it read.
  error = this->Layout.agree(error);
  if (!error.empty())
  {
    return error;
  }
  if (this->Layout.shareFirst(xyz) > 0)
  {
    vtkWarningWithObjectMacro(this->Owner,
      "The Seed Source gives a different number of points on different processes; every "
      "process releases from the first process's "
        << xyz.size() / 3 << ".");
  }
  return std::string();
}

void vtkBoundParticleTracerInternals::nameSeeds(
  vtkBoundParticleSeedType* type, bpvtk::TracerSeeds& seeds)
{
  seeds.name = type->GetSeedTypeName();
  seeds.total = std::size_t(std::max<vtkIdType>(type->GetNumberOfSeedPoints(), 0));
  seeds.advice = std::string("Raise the ") + seeds.name + "'s " + type->GetPointCountName() +
    ", or use fewer elements.";
  seeds.xyz.clear();
}

void vtkBoundParticleTracerInternals::putOnFlatAxes(
  const bp::Domain& domain, std::vector<double>& xyz) const
{
  // On a 2D slice the seeds lie in its plane, as the emitter box does (it is
  // clamped to the field's bounds): elsewhere no element would be released.
  for (std::size_t i = 0; i < xyz.size(); ++i)
  {
    const std::size_t a = i % 3;
    if (domain.degenerate[a])
    {
      xyz[i] = double(domain.lower[a]) + this->Held.offset[a];
    }
  }
}

void vtkBoundParticleTracerInternals::warnOfUnusableSeeds(vtkBoundParticleSeedType* type)
{
  const std::string unusable = type ? type->DescribeUnusableParameters() : std::string();
  if (!unusable.empty() && !this->Said.said(bpvtk::Topic::Seeds))
  {
    vtkWarningWithObjectMacro(this->Owner, << unusable); // once, as the seeds' other warnings
  }
}

void vtkBoundParticleTracerInternals::seedTypePoints(
  const Config& config, const bp::VectorField& field, bpvtk::TracerSeeds& seeds) const
{
  vtkBoundParticleSeedType* type = config.seedType;
  if (!type)
  {
    return; // the emitter box
  }
  // The whole field's flat axes, as every process sees them.
  const bp::Domain& domain = this->Layout.distributed() ? this->Layout.Domain : field.domain();
  const bool flat[3] = { domain.degenerate[0], domain.degenerate[1], domain.degenerate[2] };
  nameSeeds(type, seeds);
  // Only what releases can take: a Resolution of a billion costs no memory.
  type->AppendPoints(config.trace.engine.seed, flat, vtkIdType(bp::MaxSeedPoints), seeds.xyz);
  this->putOnFlatAxes(domain, seeds.xyz);
}

std::string vtkBoundParticleTracerInternals::seedPoints(
  const bpvtk::TracerSeeds& seeds, const bp::VectorField& field, bp::Parameters& p)
{
  const std::size_t count = seeds.total;
  if (count > bp::MaxSeedPoints)
  {
    vtkWarningWithObjectMacro(this->Owner,
      "The " << seeds.name << " has " << count << " points; releases take the first "
             << bp::MaxSeedPoints << ".");
  }
  // Releases take only the points in the field: one outside (or one too far
  // to hold in the engine's floats) would place an element where no flow is.
  // Every process decides alike, from the whole field's bounds.
  const bool distributed = this->Layout.distributed();
  const bp::Domain& domain = distributed ? this->Layout.Domain : field.domain();
  SeedCounts n;
  // Seeds where the flow barely moves at the start (below 1% of its top
  // speed): their elements sit where they were released.
  const double stillSpeed = 0.01 * field.maxSpeed();
  const double start = this->Plan.startTime();
  p.seedPoints.clear();
  for (std::size_t i = 0; i < std::min(seeds.xyz.size() / 3, bp::MaxSeedPoints); ++i)
  {
    float x[3];
    if (!localPoint(seeds.xyz, i, this->Held.offset, x))
    {
      ++n.nonFinite;
      continue;
    }
    if (!domain.contains(x))
    {
      ++n.outside;
      continue;
    }
    // Releases pass over points in cells outside the flow's domain (masked or
    // NaN) at their time; count those at the start (one process sees them all).
    n.noFlow += !distributed && field.outsideCellAt(x, 0.0f) ? 1 : 0;
    n.still += !distributed && stillAt(field, x, start, stillSpeed) ? 1 : 0;
    n.atBoundary += nearBoundary(domain, x, 0.5f * p.elementSize) ? 1 : 0;
    p.seedPoints.insert(p.seedPoints.end(), x, x + 3);
  }
  boxAroundSeeds(p);
  const std::size_t used = std::min(count, bp::MaxSeedPoints);
  if (p.seedPoints.empty() || n.noFlow == p.seedPoints.size() / 3)
  {
    return noSeedInFlow(seeds.name, used, n);
  }
  if (this->Said.first(bpvtk::Topic::Seeds))
  {
    // Once per configuration: a replay (going back in time, another
    // display's update) would say it again.
    warnOfSeeds(this->Owner, seeds, used, n, p);
  }
  return std::string();
}
