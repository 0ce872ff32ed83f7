// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, Seed Type Surface (an inlet): points drawn over the
// Seed Source's surface by the flux through it, sampled in the field at the
// trace's start (bp::surfaceWeights and bp::drawSurfacePoints,
// Core/Release/SurfaceRelease.h). See vtkBoundParticleTracerInternals.h.
#include "vtkBoundParticleTracerInternals.h"

#include "SurfaceRelease.h"
#include "VectorField.h"
#include "vtkBoundParticleSurfaceSeeds.h"

#include "vtkDataObject.h"
#include "vtkInformationVector.h"

#include <algorithm>
#include <cmath>

namespace
{
/// The velocity at a surface's point (world coordinates) at time `start`:
/// none outside this process's field (its piece, with its ghost layers,
/// under MPI: the largest weight over the processes is the one of whichever
/// holds the point) or in a cell outside the flow's domain. Along a flat
/// axis the point is taken on the field's plane.
bp::SurfaceVelocity velocityAt(const bp::VectorField& field, const bp::Domain& whole,
  const std::array<double, 3>& offset, double start)
{
  const float weight = field.timeWeight(start);
  return [&field, &whole, offset, weight](const std::array<double, 3>& x, double u[3])
  {
    float local[3];
    for (std::size_t a = 0; a < 3; ++a)
    {
      const double l = whole.degenerate[a] ? double(whole.lower[a]) : x[a] - offset[a];
      if (!std::isfinite(l) || std::abs(l) > 1e30)
      {
        return false;
      }
      local[a] = float(l);
    }
    if (!field.contains(local) || field.outsideCellAt(local, weight))
    {
      return false;
    }
    float v[3];
    field.sampleWeighted(local, weight, v);
    std::copy(v, v + 3, u);
    return true;
  };
}

/// How far a triangle is sampled off the surface where its centroid has no
/// velocity: a cell's diagonal (over the axes that are not flat), `cell` the
/// mean cell length, so the point is past the cells that straddle a mesh's
/// side.
double sampleStep(double cell, const bp::Domain& whole)
{
  int axes = 0;
  for (std::size_t a = 0; a < 3; ++a)
  {
    axes += whole.degenerate[a] ? 0 : 1;
  }
  const double step = cell * std::sqrt(double(std::max(axes, 1)));
  return std::isfinite(step) && step > 0.0 ? step : 0.0;
}

/// The triangles' weights, the other way's, and each one's step off the
/// surface (bp::sideShift) where its velocity is taken.
struct Weighed
{
  std::vector<double> weights, against, shifts;
};

/// The weights of the triangles; under MPI (`layout`) every process takes
/// the first side any process has a velocity at (the lowest), and the
/// largest weight over the processes.
Weighed weigh(const std::vector<double>& triangles, const bp::SurfaceVelocity& velocity, bool flip,
  double step, const bpvtk::PieceLayout* layout)
{
  std::vector<int> sides = bp::surfaceSides(triangles, velocity, flip, step);
  if (layout)
  {
    std::vector<double> lowest(sides.begin(), sides.end());
    std::transform(lowest.begin(), lowest.end(), lowest.begin(), [](double s) { return -s; });
    layout->globalMax(lowest);
    std::transform(lowest.begin(), lowest.end(), sides.begin(), [](double s) { return int(-s); });
  }
  Weighed w;
  w.weights = bp::surfaceWeights(triangles, velocity, flip, step, sides, &w.against);
  if (layout)
  {
    const std::size_t n = w.weights.size();
    w.weights.insert(w.weights.end(), w.against.begin(), w.against.end());
    layout->globalMax(w.weights);
    w.against.assign(w.weights.begin() + std::ptrdiff_t(n), w.weights.end());
    w.weights.resize(n);
  }
  w.shifts.resize(sides.size());
  std::transform(sides.begin(), sides.end(), w.shifts.begin(),
    [step, flip](int side) { return bp::sideShift(side, step, flip); });
  return w;
}

/// The warning about triangles left out (a corner not finite, or no flow).
void warnOfUnusedTriangles(vtkObject* owner, const bp::SurfaceSummary& summary)
{
  std::string parts;
  if (summary.nonFinite > 0)
  {
    parts = std::to_string(summary.nonFinite) + " have a corner that is not finite";
  }
  if (summary.noVelocity > 0)
  {
    parts += (parts.empty() ? "" : " and ") + std::to_string(summary.noVelocity) +
      " lie outside the field or in cells outside the flow's domain at the trace's start";
  }
  vtkWarningWithObjectMacro(owner,
    "Of the Seed Source's " << summary.triangles << " surface triangles, " << parts
                            << "; the Surface releases over the other "
                            << summary.triangles - summary.nonFinite - summary.noVelocity << ".");
}
} // namespace

std::string vtkBoundParticleTracerInternals::surfaceSeedPoints(const Config& config,
  vtkInformationVector** inputVector, const bp::VectorField& field, bpvtk::TracerSeeds& seeds)
{
  vtkBoundParticleSeedType* type = config.seedType;
  auto* surface = vtkBoundParticleSurfaceSeeds::SafeDownCast(type);
  nameSeeds(type, seeds);
  if (!config.seedSource || !surface)
  {
    return "Seed Type Surface releases over the Seed Source's surface, and no Seed Source is "
           "connected: nothing is released. Connect one (a Plane, or a data set whose boundary "
           "is the inlet) as the Seed Source, or choose another Seed Type.";
  }
  this->warnOfUnusableSeeds(surface);
  std::vector<double> triangles;
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(
    vtkDataObject::GetData(inputVector[2], 0), triangles);
  const bool distributed = this->Layout.distributed();
  if (distributed && this->Layout.shareFirst(triangles) > 0)
  {
    vtkWarningWithObjectMacro(this->Owner,
      "The Seed Source gives a different surface on different processes; every process "
      "releases over the first process's "
        << triangles.size() / 9 << " triangles.");
  }
  // The whole field's flat axes: a surface across a 2D field's plane is
  // sampled, and its points put, on the plane.
  const bp::Domain& whole = distributed ? this->Layout.Domain : field.domain();
  const double start = this->Plan.startTime();
  const bp::SurfaceVelocity velocity = velocityAt(field, whole, this->Held.offset, start);
  const bool flip = surface->GetFlipNormals() != 0;
  // A triangle whose centroid has no velocity (a mesh's own boundary: the
  // resampled cells across the mesh's side are outside the flow) is sampled
  // a cell's diagonal into the flow instead, and its points put there.
  const double step = sampleStep(this->Layout.cellLength(field.grid()), whole);
  const Weighed weighed =
    weigh(triangles, velocity, flip, step, distributed ? &this->Layout : nullptr);
  const std::vector<double>& weights = weighed.weights;
  const bp::SurfaceSummary summary = bp::summarizeSurface(triangles, weights, weighed.against);
  std::string problem = bp::surfaceProblem(summary, flip);
  if (!problem.empty())
  {
    return problem;
  }
  seeds.xyz = bp::drawSurfacePoints(triangles, weights, config.trace.engine.seed,
    std::min(seeds.total, bp::MaxSeedPoints), weighed.shifts);
  if (seeds.xyz.empty())
  {
    return "The flux through the Seed Source's surface is too large to weigh (it overflows a "
           "double): Seed Type Surface releases nothing. Scale the velocity down.";
  }
  const std::string warning = bp::surfaceWarning(summary, flip);
  if ((summary.nonFinite + summary.noVelocity > 0 || !warning.empty()) &&
    !this->Said.said(bpvtk::Topic::Seeds))
  {
    if (summary.nonFinite + summary.noVelocity > 0)
    {
      warnOfUnusedTriangles(this->Owner, summary); // once, as the seeds' other warnings
    }
    if (!warning.empty())
    {
      vtkWarningWithObjectMacro(this->Owner, << warning);
    }
  }
  this->putOnFlatAxes(whole, seeds.xyz);
  return std::string();
}
