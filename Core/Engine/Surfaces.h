// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Surfaces.h
 * @brief The tracer's Surfaces input as the engine sees it (engine
 * specification 2.10, "Gates and outlets"): triangles in engine
 * coordinates, each with what it does (SurfaceInteraction: Gate, Outlet),
 * the surface it belongs to and the input's cell it was cut from.
 *
 * An element passes a surface where the step of its centre (the particles'
 * mean before the step to their mean after restoration and the walls)
 * crosses one of its triangles (SurfaceCrossings.h: t in (0, 1], one
 * crossing through an edge that triangles share). A Gate records each
 * passage; the first Outlet passed ends the element (Terminated) and
 * records it, and the passages after it in that step are not made.
 */
#ifndef BoundParticles_Surfaces_h
#define BoundParticles_Surfaces_h

#include "BoundParticlesChoices.h"
#include "SurfaceCrossings.h"

#include <cstdint>
#include <vector>

namespace bp
{

/// The triangles of a Surfaces input, before they are kept.
struct SurfaceTriangles
{
  std::vector<float> corners;                  ///< 9 a triangle, engine coordinates
  std::vector<std::int32_t> surfaces;          ///< the surface of each (its block)
  std::vector<std::int32_t> cells;             ///< the input's cell of each
  std::vector<SurfaceInteraction> interaction; ///< what each does
};

class SurfaceSet
{
public:
  explicit SurfaceSet(const SurfaceTriangles& triangles);

  /// What triangle `k` (its index as given) does, and the cell it was cut from.
  SurfaceInteraction interaction(std::uint32_t k) const { return this->Given.interaction[k]; }
  std::int32_t cell(std::uint32_t k) const { return this->Given.cells[k]; }
  /// The triangles as given (each list as long as the triangles: filled in).
  const SurfaceTriangles& triangles() const { return this->Given; }
  /// Whether any triangle kept is an Outlet (an element may end at one).
  bool hasOutlets() const { return !this->OutletCorners.empty(); }
  /// The Outlet triangles kept, 9 floats each (three corners), in the order
  /// given: what the GPU engine tests an element's step against (engine
  /// specification 2.10). Gates are not here: they change nothing in a step.
  const std::vector<float>& outletCorners() const { return this->OutletCorners; }
  /// The triangles kept, and those left out (a corner not finite, or no area).
  std::size_t triangleCount() const { return this->Crossings.triangleCount(); }
  std::size_t droppedTriangles() const { return this->Crossings.droppedTriangles(); }

  /**
   * The passages of the step a -> b, in order along it (allCrossings), up to
   * and with the first Outlet's: what the step does at the surfaces.
   * Returns whether it ends at an Outlet.
   */
  bool passages(const float a[3], const float b[3], std::vector<SurfaceCrossing>& out) const;

private:
  SurfaceTriangles Given;
  SurfaceCrossings Crossings;
  std::vector<float> OutletCorners;
};

} // namespace bp

#endif
