// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkBoundParticleSurfaceSeeds
 * @brief Seed Type "Surface": an inlet. Number Of Points release points
 * spread over the Seed Source's surface in proportion to the flux through it.
 *
 * The surface is the tracer's Seed Source's (any dataset: its boundary, as
 * vtkDataSetSurfaceFilter gives it, cut into triangles; a composite's
 * blocks merged first, so the faces between blocks are not part of it; a
 * volume's boundary turned to point outward). Each triangle weighs max(0, u · n) × area, u the
 * field's velocity at its centroid at the trace's start and n its unit normal in the surface's own
 * orientation ((b − a) × (c − a); reversed with FlipNormals); a point is drawn in a triangle picked
 * in proportion to its weight, uniform within it, from the tracer's Seed (bp::drawSurfacePoints,
 * Core/Release/SurfaceRelease.h). Releases then take the points in order and
 * cycling, as any seeds'. The points need the surface and the field, so the
 * tracer draws them (its seeds' step); AppendPoints alone gives none.
 */
#ifndef vtkBoundParticleSurfaceSeeds_h
#define vtkBoundParticleSurfaceSeeds_h

#include "BoundParticlesFiltersModule.h" // for export macro
#include "vtkBoundParticleSeedType.h"

#include <algorithm> // for std::max

class vtkDataObject;

class BOUNDPARTICLESFILTERS_EXPORT vtkBoundParticleSurfaceSeeds : public vtkBoundParticleSeedType
{
public:
  static vtkBoundParticleSurfaceSeeds* New();
  vtkTypeMacro(vtkBoundParticleSurfaceSeeds, vtkBoundParticleSeedType);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// How many points are drawn over the surface (default 10000; below 1,
  /// one, said by DescribeUnusableParameters; releases take at most 65,536).
  vtkSetMacro(NumberOfPoints, int);
  vtkGetMacro(NumberOfPoints, int);
  ///@}

  ///@{
  /// Count the flux against the surface's normals instead of along them
  /// (default off): for a surface whose normals point out of the flow it
  /// feeds, such as a volume's boundary, whose normals point outward.
  vtkSetMacro(FlipNormals, vtkTypeBool);
  vtkGetMacro(FlipNormals, vtkTypeBool);
  vtkBooleanMacro(FlipNormals, vtkTypeBool);
  ///@}

  const char* GetSeedTypeName() override { return "Surface"; }
  const char* GetPointCountName() override { return "Number Of Points"; }
  vtkIdType GetNumberOfSeedPoints() override { return std::max(this->NumberOfPoints, 1); }
  bool UsesSeedSource() override { return true; }
#ifndef __VTK_WRAP__
  /// None, the exception to the base class's contract: the points need the
  /// Seed Source's surface and the field (the tracer draws them with
  /// bp::drawSurfacePoints).
  void AppendPoints(std::uint32_t, const bool[3], vtkIdType, std::vector<double>&) override {}
  std::string DescribeUnusableParameters() override;

  /**
   * The surface of `source` (a dataset, or a composite's datasets) as
   * triangles, 9 coordinates each (a, b, c, in the surface's orientation),
   * appended to `triangles`: its boundary surface cut into triangles;
   * vertices and lines give none. A composite's blocks (those with cells)
   * are merged first (vtkAppendFilter, coincident points made one), so a
   * face two blocks share is inside and left out. A block with cells of
   * three dimensions (a volume) whose boundary points inward (a signed
   * volume Σ ((c − o) · n) A / 3 below 0, o its centre: a left-handed grid,
   * a mirrored mesh) has its triangles reversed, so a volume's boundary
   * points outward; a surface keeps its own orientation. A surface cell with
   * a corner that is not finite is left out whole, given as one triangle of
   * NaN corners (so the tracer counts and names it once).
   */
  static void AppendSurfaceTriangles(vtkDataObject* source, std::vector<double>& triangles);
#endif

protected:
  vtkBoundParticleSurfaceSeeds() = default;
  ~vtkBoundParticleSurfaceSeeds() override = default;

  int NumberOfPoints = 10000;
  vtkTypeBool FlipNormals = 0;

private:
  vtkBoundParticleSurfaceSeeds(const vtkBoundParticleSurfaceSeeds&) = delete;
  void operator=(const vtkBoundParticleSurfaceSeeds&) = delete;
};

#endif
