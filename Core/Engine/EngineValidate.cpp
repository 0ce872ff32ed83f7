// SPDX-License-Identifier: BSD-3-Clause
// Engine::validate: the checks a template and parameters pass before the
// engine is sized, one named check per group of parameters, each giving the
// message the user sees (empty when it passes).
#include "Engine.h"
#include "Surfaces.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bp
{
namespace
{
std::string checkShape(const ElementTemplate& shape, const Parameters& /*p*/)
{
  return shape.validate();
}

std::string checkSize(const ElementTemplate& shape, const Parameters& p)
{
  if (p.numberOfElements < 1)
  {
    return "NumberOfElements must be at least 1";
  }
  const std::size_t n = shape.particleCount();
  if (p.numberOfElements > MaxParticles / n)
  {
    std::ostringstream err;
    err << "NumberOfElements " << p.numberOfElements << " x " << n
        << " particles per element exceeds the limit of " << MaxParticles
        << " particles; use fewer elements or a simpler shape";
    return err.str();
  }
  if (!(std::isfinite(p.elementSize) && p.elementSize > 0.0f))
  {
    return "ElementSize must be positive";
  }
  return std::string();
}

/// Release Pattern = Lattice: a lattice the engine can hold, and no super
/// set (whose elements sit at their own lattice's sites).
std::string checkLattice(const ElementTemplate& shape, const Parameters& p)
{
  if (p.releasePattern == ReleasePattern::Random)
  {
    return std::string();
  }
  if (p.releasePattern != ReleasePattern::Lattice)
  {
    return "ReleasePattern must be Random or Lattice";
  }
  if (p.linking != Linking::None)
  {
    return "Release Pattern = Lattice cannot be used with Linking: a super set is released at "
           "its own lattice's sites; set Linking to None or Release Pattern to Random";
  }
  const std::size_t size = p.lattice.size();
  const std::size_t n = shape.particleCount();
  if (size < 1 || size > MaxParticles / n)
  {
    // A count at MaxLatticeCount may stand for more (releaseLattice caps it).
    std::ostringstream err;
    err << "the release lattice (";
    for (int a = 0; a < 3; ++a)
    {
      err << (a > 0 ? " x " : "") << (p.lattice.counts[a] >= MaxLatticeCount ? "over " : "")
          << p.lattice.counts[a];
    }
    err << " points) x " << n << " particles per element exceeds the limit of " << MaxParticles
        << " particles; choose a larger LatticeSpacing (or, with LatticeSpacing 0, a smaller "
        << "NumberOfElements)";
    return err.str();
  }
  if (size != p.numberOfElements)
  {
    return "NumberOfElements must be the release lattice's size (resolveSettings sets it)";
  }
  return std::string();
}

std::string checkTrail(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (p.trailLength < 0 || p.trailLength > MaxTrailLength ||
    (p.trailLength > 0 &&
      !(std::isfinite(p.trailInterval) && p.trailInterval > 0.0 && std::isfinite(p.trailStart))))
  {
    return "TrailLength must be in [0, " + std::to_string(MaxTrailLength) +
      "] poses, with a positive, finite interval between two";
  }
  return std::string();
}

std::string checkReleaseWindow(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (std::isnan(p.releaseStart) || std::isnan(p.releaseStop))
  {
    return "ReleaseStart and ReleaseStop must be numbers (one is NaN)";
  }
  if (!(p.releaseStart <= p.releaseStop))
  {
    std::ostringstream err;
    err << "the release window must not end before it starts: ReleaseStart " << p.releaseStart
        << " is after ReleaseStop " << p.releaseStop;
    return err.str();
  }
  return std::string();
}

/// The plane axis, the seed points and the emitter box.
std::string checkRelease(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (p.planeAxis < -1 || p.planeAxis > 2)
  {
    return "the plane axis must be -1 (none) or an axis 0 to 2";
  }
  if (p.seedPoints.size() % 3 != 0 || p.seedPoints.size() / 3 > MaxSeedPoints)
  {
    return "there must be at most " + std::to_string(MaxSeedPoints) + " seed points, 3 floats each";
  }
  if (!std::all_of(
        p.seedPoints.begin(), p.seedPoints.end(), [](float x) { return std::isfinite(x); }))
  {
    return "the Seed Source has a point that is not finite (NaN or Inf), or one too far from the "
           "field's first point for float coordinates";
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!(std::isfinite(p.emitterMin[k]) && std::isfinite(p.emitterMax[k]) &&
          p.emitterMin[k] <= p.emitterMax[k]))
    {
      return "the emitter box is invalid: EmitterSize must not be negative and both "
             "EmitterCenter and EmitterSize must be finite";
    }
  }
  if (!(std::isfinite(p.lifetimeMin) && std::isfinite(p.lifetimeMax) && p.lifetimeMin > 0.0f &&
        p.lifetimeMin <= p.lifetimeMax))
  {
    return "LifetimeRange must satisfy 0 < min <= max";
  }
  return std::string();
}

std::string checkRestoration(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (p.iterations < 0 || p.iterations > 1000)
  {
    return "RestorationIterations must lie in [0, 1000]";
  }
  if (!(p.relaxation > 0.0f && p.relaxation <= 2.0f))
  {
    return "the Jacobi relaxation factor must lie in (0, 2]";
  }
  if (!(p.shapeStiffness >= 0.0f && p.shapeStiffness <= 1.0f))
  {
    return "the shape-matching stiffness must lie in [0, 1]";
  }
  if (!(p.linearBlend >= 0.0f && p.linearBlend <= 1.0f))
  {
    return "the linear shape-matching blend (beta) must lie in [0, 1]";
  }
  return std::string();
}

std::string checkLinking(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (int(p.linking) < int(Linking::None) || int(p.linking) > int(Linking::Torus))
  {
    return "Linking must be None, Chain, Ring, Sheet, Tube or Torus";
  }
  if (p.latticeWidth < 0)
  {
    return "LatticeWidth must not be negative (0 chooses a near-square lattice)";
  }
  if (!(p.linkStiffness >= 0.0f && p.linkStiffness <= 1.0f))
  {
    return "LinkStiffness must lie in [0, 1]";
  }
  return std::string();
}

std::string checkAnchor(const ElementTemplate& shape, const Parameters& p)
{
  if (p.anchor == Anchor::None)
  {
    return std::string();
  }
  if (p.anchor != Anchor::Centre)
  {
    return "Anchor must be None or Centre";
  }
  if (p.linking != Linking::None)
  {
    // A super set moves as one structure held by its links; anchoring each
    // element at its lattice site would leave the links nothing to hold.
    return "Anchor = Centre holds single elements in place; a super set (Linking) cannot be "
           "anchored: set Linking to None or Anchor to None";
  }
  if (std::find(shape.pinned.begin(), shape.pinned.end(), 1) != shape.pinned.end())
  {
    return "Anchor = Centre moves the whole element back to its release centre, which would "
           "move the template's pinned particles: use a template without pinned particles";
  }
  // The anchor is the release centre, which is the particles' mean at
  // placement only for a template centred on its centroid (as normalize()
  // leaves every built-in and mesh template).
  double mean[3] = { 0, 0, 0 }, radius = 0;
  for (const auto& r : shape.rest)
  {
    for (int k = 0; k < 3; ++k)
    {
      mean[k] += r[k] / double(shape.rest.size());
    }
    radius = std::max(radius, double(std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2])));
  }
  if (std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]) > 1e-4 * radius)
  {
    return "Anchor = Centre needs an element template centred on its centroid "
           "(ElementTemplate::normalize)";
  }
  return std::string();
}
std::string checkInertia(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (p.inertia == Inertia::None)
  {
    return std::string();
  }
  if (p.inertia != Inertia::MaxeyRiley)
  {
    return "Inertia must be None or Maxey-Riley";
  }
  if (!(p.responseTime >= 0.0f) || !std::isfinite(p.responseTime))
  {
    return "ResponseTime (the particles' response time tau) must be a number from 0 (massless "
           "particles) to 3.4e38, the largest float";
  }
  if (!(p.densityRatio > 0.0f) || !std::isfinite(p.densityRatio))
  {
    return "DensityRatio (the particles' density over the fluid's) must be a number above 0 "
           "and at most 3.4e38, the largest float";
  }
  for (const float g : p.gravity)
  {
    if (!std::isfinite(g))
    {
      return "Gravity must be a vector of numbers of at most 3.4e38 in size, the largest float "
             "(0 0 0 for none)";
    }
  }
  if (p.anchor != Anchor::None)
  {
    // An anchored element is held where it was released: it has no path
    // for inertia to change.
    return "Anchor = Centre holds elements in place, where inertia has no meaning: set Anchor "
           "to None or Inertia to None";
  }
  return std::string();
}

std::string checkSurfaces(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (!p.surfaces)
  {
    return std::string();
  }
  if (p.linking != Linking::None)
  {
    // A super set's elements are never flagged, and record nothing.
    return "Surfaces (gates, outlets and walls) act on single elements; a super set (Linking) "
           "lives out "
           "its lifetime whole: set Linking to None or disconnect the Surfaces";
  }
  if (p.anchor != Anchor::None)
  {
    // An anchored element goes back to its release centre every step.
    return "Surfaces (gates, outlets and walls) act on travelling elements; Anchor = Centre holds "
           "them "
           "at their release centre: set Anchor to None or disconnect the Surfaces";
  }
  return std::string();
}

std::string checkBoundary(const ElementTemplate& /*shape*/, const Parameters& p)
{
  if (int(p.boundary) < int(Boundary::ReleaseAgain) || int(p.boundary) > int(Boundary::Bounce))
  {
    return "Boundary must be Release Again, Terminate, Stick, Slip or Bounce";
  }
  if (!(p.restitution >= 0.0f && p.restitution <= 1.0f))
  {
    // Checked whatever the Boundary, so that a saved setting is always sound.
    std::ostringstream said;
    said << "Restitution must be between 0 and 1 (a bounce keeps that share of the normal "
            "velocity), not "
         << p.restitution;
    return said.str();
  }
  if (p.boundary == Boundary::Terminate && p.linking != Linking::None)
  {
    // A super set's elements are never flagged when they leave the field.
    return "Boundary = Terminate ends single elements that leave the field; a super set "
           "(Linking) lives out its lifetime whole: set Linking to None or Boundary to Release "
           "Again";
  }
  if (isWall(p.boundary) && p.linking != Linking::None)
  {
    // The links' pass runs after every restoration iteration and would take
    // particles back through a wall: not defined yet.
    return std::string("Boundary = ") + enumName(p.boundary) +
      " walls single elements in; a super set (Linking) cannot be walled yet: set Linking to "
      "None or Boundary to Release Again";
  }
  if (isWall(p.boundary) && p.anchor != Anchor::None)
  {
    // Anchoring moves the element back to its release centre after the step,
    // past any wall; an anchored element never travels to one.
    return std::string("Boundary = ") + enumName(p.boundary) +
      " walls travelling elements in; Anchor = Centre holds them at their release centre: set "
      "Anchor to None or Boundary to Release Again";
  }
  return std::string();
}
} // namespace

std::string Engine::validate(const ElementTemplate& shape, const Parameters& p)
{
  // In order, each only once the ones before pass (checkSize divides by
  // the particle count that shape.validate() checks): the first failure is
  // the one reported.
  using Check = std::string (*)(const ElementTemplate&, const Parameters&);
  const Check checks[] = { checkShape, checkLattice, checkSize, checkTrail, checkReleaseWindow,
    checkRelease, checkRestoration, checkLinking, checkAnchor, checkInertia, checkBoundary,
    checkSurfaces };
  for (const Check check : checks)
  {
    std::string error = check(shape, p);
    if (!error.empty())
    {
      return error;
    }
  }
  return std::string();
}

} // namespace bp
