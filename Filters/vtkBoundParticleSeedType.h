// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkBoundParticleSeedType
 * @brief A built-in place to release a vtkBoundParticleTracer's elements
 * from: the tracer's Seed Type.
 *
 * The tracer releases elements in its emitter box unless it is given seed
 * points: a Seed Source (its third input, any dataset) or a Seed Type, one of
 * this class's subclasses (vtkBoundParticlePointCloudSeeds,
 * vtkBoundParticleLineSeeds, and vtkBoundParticleSurfaceSeeds, which draws
 * its points over the Seed Source's surface instead of giving way to it). A
 * Seed Type is a set of parameters, not a pipeline source: the tracer
 * computes the points itself, so that they are the same on every process and
 * in every run (ParaView's Point Cloud source draws from a process-wide
 * random sequence, which gave each rank of an MPI job, and each run, other
 * points). In ParaView these are the entries of the tracer's Seed Type list,
 * each with its 3D widget, as in the Stream Tracer.
 */
#ifndef vtkBoundParticleSeedType_h
#define vtkBoundParticleSeedType_h

#include "BoundParticlesFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <cstdint> // for std::uint32_t
#include <string>  // for std::string
#include <vector>  // for std::vector

class BOUNDPARTICLESFILTERS_EXPORT vtkBoundParticleSeedType : public vtkObject
{
public:
  vtkTypeMacro(vtkBoundParticleSeedType, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The name the tracer's messages give these seeds ("Point Cloud", "Line").
  virtual const char* GetSeedTypeName() = 0;

  /// The property that sets how many points there are ("Number Of Points",
  /// "Resolution"), for the tracer's advice when elements share points.
  virtual const char* GetPointCountName() = 0;

  /// How many points these seeds have.
  virtual vtkIdType GetNumberOfSeedPoints() = 0;

  /// Whether these seeds are drawn over the Seed Source (Surface: its surface,
  /// weighted by the flux through it) rather than replaced by it.
  virtual bool UsesSeedSource() { return false; }

#ifndef __VTK_WRAP__
  /**
   * Appends the first min(GetNumberOfSeedPoints(), maxPoints) points, in
   * world coordinates (3 doubles each), to `xyz`. `seed` is the tracer's
   * Seed, for seeds drawn at random: the same seed gives the same points.
   * `flat[a]` says the field has a single point along axis a (a 2D slice):
   * seeds spread over the other axes only, and the caller puts them on the
   * field's plane. The exception: seeds that use the Seed Source
   * (UsesSeedSource(), the Surface) need it and the field, which this does
   * not see; they append nothing here, and the tracer draws their points
   * itself (vtkBoundParticleTracerInternals::surfaceSeedPoints).
   */
  virtual void AppendPoints(
    std::uint32_t seed, const bool flat[3], vtkIdType maxPoints, std::vector<double>& xyz) = 0;

  /**
   * What of the parameters cannot be used as set (a radius below 0, a count
   * below 1: a script's or a state file's typo), and what is used instead,
   * for the tracer's warning; empty where all is well. The setters take any
   * value, so the message names the value given.
   */
  virtual std::string DescribeUnusableParameters()
  {
    return std::string();
  }
#endif

protected:
  vtkBoundParticleSeedType() = default;
  ~vtkBoundParticleSeedType() override = default;

private:
  vtkBoundParticleSeedType(const vtkBoundParticleSeedType&) = delete;
  void operator=(const vtkBoundParticleSeedType&) = delete;
};

#endif
