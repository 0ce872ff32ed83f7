// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Surfaces.h
 * @brief The tracer's Surfaces input as the engine sees it (engine
 * specification 2.10, "Gates, outlets and walls"): triangles in engine
 * coordinates, each with what it does (SurfaceInteraction: Gate, Outlet,
 * Wall), the surface it belongs to and the input's cell it was cut from.
 *
 * An element passes a surface where the step of its centre (the particles'
 * mean before the step to their mean after restoration and the walls)
 * crosses one of its triangles (SurfaceCrossings.h: t in (0, 1], one
 * crossing through an edge that triangles share). A Gate records each
 * passage; the first Outlet passed ends the element (Terminated) and
 * records it, and the passages after it in that step are not made. A Wall
 * acts as the Boundary does at the field's sides: with Release Again or
 * Terminate on the element whose centre crosses it (as an Outlet does,
 * released again or ended), with Stick, Slip or Bounce on each particle whose step
 * crosses it (wallCrossing).
 */
#ifndef BoundParticles_Surfaces_h
#define BoundParticles_Surfaces_h

#include "BoundParticlesChoices.h"
#include "SurfaceCrossings.h"
#include "VectorField.h"

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

/// Where a particle is put off a Wall surface, toward the side it came
/// from: 10^-5 of the field's largest extent (its axes that are not flat),
/// some hundred float roundings at that size, so that the next step starts
/// strictly on that side.
float surfaceWallOffset(const Domain& box);

class SurfaceSet
{
public:
  explicit SurfaceSet(const SurfaceTriangles& triangles);

  /// What triangle `k` (its index as given) does, and the cell it was cut from.
  SurfaceInteraction interaction(std::uint32_t k) const { return this->Given.interaction[k]; }
  std::int32_t cell(std::uint32_t k) const { return this->Given.cells[k]; }
  /// The triangles as given (each list as long as the triangles: filled in).
  const SurfaceTriangles& triangles() const { return this->Given; }
  /// Whether any triangle kept is an Outlet (an element may end at one), or a Wall.
  bool hasOutlets() const { return !this->OutletCorners.empty(); }
  bool hasWalls() const { return this->Walls.triangleCount() > 0; }
  /// The Outlet triangles kept, 9 floats each (three corners), in the order
  /// given: what the GPU engine tests an element's step against (engine
  /// specification 2.10). Gates are not here: they change nothing in a step.
  const std::vector<float>& outletCorners() const { return this->OutletCorners; }
  /// The Wall triangles kept, 9 floats each, in the order given (that of
  /// wallCrossing's tie-break): what the GPU engine keeps particles off, or
  /// ends elements at (engine specification 2.10).
  const std::vector<float>& wallCorners() const { return this->WallCorners; }
  /// The triangles kept, and those left out (a corner not finite, or no area).
  std::size_t triangleCount() const { return this->Passing.triangleCount(); }
  std::size_t droppedTriangles() const { return this->Passing.droppedTriangles(); }

  /**
   * The passages of an element's centre over the step a -> b, in order
   * along it, up to and with the first that ends it: an Outlet's, or with
   * `wallsEnd` (Boundary Release Again or Terminate) a Wall's. The
   * crossings' triangles are indices as given. Returns whether one ends it.
   *
   * `seam` (3 floats, or null for none): the whole periods a centre that
   * left through a periodic side of `box` moves by after the step
   * (periodicShift; engine specification 2.8, 2.10). Where it is not 0 the
   * step is also tested translated by it, a + seam -> b + seam (and, where
   * it moves along several axes, by each part of it: a step through a
   * corner), and from each segment only the crossings whose point lies
   * within the box (closed) along the axes the seam moves are kept, so a
   * surface just past the seam is passed too, and one spanning it once.
   * Their t stay the share of the whole step; a triangle met by two
   * segments (on the seam itself) is passed once, the untranslated step's
   * first. A seam of 0 changes nothing.
   */
  bool passages(const float a[3], const float b[3], bool wallsEnd,
    std::vector<SurfaceCrossing>& out, const Domain* box = nullptr,
    const float* seam = nullptr) const;

  /// The first crossing of a particle's step a -> b with a Wall (its
  /// triangle an index as given); false where it crosses none.
  bool wallCrossing(const float a[3], const float b[3], SurfaceCrossing& crossing) const;
  /// Whether p lies on a Wall: within `distance` of a Wall triangle's plane,
  /// its foot within the triangle (SurfaceCrossings::lies). Stick holds such a particle.
  bool onWall(const float p[3], float distance) const { return this->Walls.lies(p, distance); }

private:
  /// Every crossing of the step a -> b, in order along it, with `seam`
  /// (not 0) those of the translated step added as passages() says.
  void crossingsAcrossSeam(const float a[3], const float b[3], const Domain* box, const float* seam,
    std::vector<SurfaceCrossing>& out) const;

  SurfaceTriangles Given;
  /// Every triangle (for the elements' centres), and the Walls alone (for
  /// the particles), with each one's index as given.
  SurfaceCrossings Passing;
  std::vector<std::uint32_t> WallIndex; // before Walls, which fills it as it is made
  SurfaceCrossings Walls;
  std::vector<float> OutletCorners;
  std::vector<float> WallCorners;
};

} // namespace bp

#endif
